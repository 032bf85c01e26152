"""The compiler options a file sets, read once: import parity's notes and the root causes share the records.

Expected options are read by hand from the files (their ``<compiler>`` lines are quoted beside each case).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest
from common import dm_control_root

from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.pair_causes import compiler_causes
from koenig_check.engines import load_model
from koenig_check.findings import Kind
from koenig_check.modelfile import compiler
from koenig_check.modelfile.compiler import compiler_findings, compiler_options

TESTS = Path(__file__).resolve().parents[1]
MODELS = TESTS.parent / "models"


def _dm(rel: str) -> Path:
    root = dm_control_root()
    if root is None:
        pytest.skip("dm_control is not installed")
    return root / rel


CASES = {
    # <compiler settotalmass="5"/>
    "tiebreak settotalmass": (lambda: TESTS / "models/tiebreak/settotalmass.xml", [("settotalmass", 5.0, "5")]),
    # <compiler inertiafromgeom="true" settotalmass="5"/>: file order of the options MuJoCo applies
    "tiebreak settotalmass_inertiafromgeom": (
        lambda: TESTS / "models/tiebreak/settotalmass_inertiafromgeom.xml",
        [("settotalmass", 5.0, "5"), ("inertiafromgeom", True, "true")],
    ),
    # <compiler settotalmass="14"/>
    "dm_control cheetah": (lambda: _dm("suite/cheetah.xml"), [("settotalmass", 14.0, "14")]),
    # <compiler boundmass="1e-3" boundinertia="1e-9" meshdir="assets"/>
    "dm_control drosophila": (
        lambda: _dm("locomotion/walkers/assets/build_fruitfly/assets/drosophila.xml"),
        [("boundmass", 1e-3, "1e-3"), ("boundinertia", 1e-9, "1e-9")],
    ),
    # <compiler angle="radian" inertiafromgeom="false"/>: nothing MuJoCo changes
    "gimbal": (lambda: MODELS / "gimbal.xml", []),
    "a URDF": (lambda: MODELS / "gimbal.urdf", []),
}


@pytest.mark.parametrize("case", list(CASES))
def test_each_option_in_effect_is_one_record(case: str) -> None:
    path, expected = CASES[case]
    options = compiler_options(path())
    assert [(f.kind, f.engine, f.element) for f in options] == [
        (Kind.COMPILER, "mujoco", f"compiler {name}") for name, _, _ in expected
    ]
    assert [dict(f.values) for f in options] == [{name: v, "as written": w} for name, v, w in expected]
    assert all(f.affects_energy and not f.root_cause for f in options)


def test_settotalmass_reads_the_same_in_the_parity_notes_and_the_cause() -> None:
    """dm_control's cheetah: MuJoCo rescales to 14 kg, Pinocchio keeps the file's masses."""
    report = import_parity(load_model(_dm("suite/cheetah.xml")))
    assert (
        "compiler settotalmass=14: MuJoCo rescales every mass and inertia to this total; check whether Pinocchio's "
        "MJCF parser does the same (total masses below)"
    ) in report.findings
    (cause,) = [c for c in report.causes if c.kind is Kind.COMPILER]
    assert (cause.engine, cause.element, cause.root_cause, cause.hint, cause.cause) == (
        "pinocchio",  # the engine that departs from the file (it ignores the option): the cause's, built so
        "compiler settotalmass",
        True,
        "",
        "pinocchio.mjcf.settotalmass",
    )
    assert cause.summary == "settotalmass=14: MuJoCo rescales every mass and inertia to this total, Pinocchio does not"
    assert cause.values["mujoco"] == pytest.approx(14.0, rel=1e-12)
    spec = mujoco.MjSpec.from_file(str(_dm("suite/cheetah.xml")))
    spec.compiler.settotalmass = -1  # the file's masses: MuJoCo's compile without the option
    assert cause.values["pinocchio"] == pytest.approx(spec.compile().body_mass.sum(), rel=1e-9)


def test_the_notes_and_the_cause_come_from_one_reading(monkeypatch: pytest.MonkeyPatch) -> None:
    """Change what the one table says settotalmass does: the note and the cause both say the new words."""
    effect = "MuJoCo sets the total mass (patched reading)"
    monkeypatch.setitem(compiler.MASS_OPTIONS, "settotalmass", (effect, "a patched hint"))
    path = TESTS / "models/tiebreak/settotalmass.xml"
    assert f"compiler settotalmass=5: {effect}; a patched hint" in compiler_findings(path)
    (cause,) = compiler_causes(load_model(path))
    assert cause.summary == f"settotalmass=5: {effect}, Pinocchio does not"
    monkeypatch.delitem(compiler.MASS_OPTIONS, "settotalmass")
    assert compiler_causes(load_model(path)) == []
    assert not any("settotalmass" in line for line in compiler_findings(path))
