"""``compiler inertiagrouprange``: the geoms MuJoCo leaves out of a body's mass are named as the root cause.

Expected masses are computed by hand (density 1000 × volume) and confirmed from each engine's own model
(``MjModel.body_mass``, Pinocchio's inertias); the disagreement itself from the engines' mass matrices
(:mod:`independent_energy`).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest

import koenig_check
from independent_energy import engines_agree
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.reason import short_cause
from koenig_check.engines import load_model
from koenig_check.findings import Kind

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"
BOX = 1000.0 * 0.2 * 0.4 * 0.6  # body a's box, group 0: counted by every engine
BALL = 1000.0 * 4.0 / 3.0 * np.pi * 0.2**3  # body a's sphere, group 3
HAS_DRAKE = importlib.util.find_spec("pydrake") is not None


def _group_causes(path: Path) -> list:
    return [c for c in import_parity(load_model(path)).causes if c.element == "compiler inertiagrouprange"]


def test_the_engines_own_masses_differ_by_the_ball_left_out() -> None:
    path = CAUSES / "inertia_group.xml"
    m = mujoco.MjModel.from_xml_path(str(path))
    p = pin.buildModelFromMJCF(str(path))
    assert m.body("a").mass[0] == pytest.approx(BOX, rel=1e-12)
    assert p.inertias[p.getJointId("j")].mass == pytest.approx(BOX + BALL, rel=1e-12)


@pytest.mark.parametrize(("groups", "left_out"), [("0 2", ("ball",)), ("0 3", ())])
def test_geoms_outside_the_range_are_the_named_cause(tmp_path: Path, groups: str, left_out: tuple[str, ...]) -> None:
    text = (CAUSES / "inertia_group.xml").read_text()
    path = tmp_path / "inertia_group.xml"  # "0 3": every group the geoms use is counted, nothing is left out
    path.write_text(text.replace('inertiagrouprange="0 2"', f'inertiagrouprange="{groups}"'))
    pair = load_model(path)
    causes = _group_causes(path)
    assert engines_agree(pair) is (not left_out)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert check.ok is (not left_out)
    if not left_out:
        assert causes == []
        return
    (cause,) = causes
    # Pinocchio's: the engine that departs from the file, counting every geom (Drake too), built so, never moved
    assert (cause.kind, cause.engine) == (Kind.COMPILER, "pinocchio") and cause.root_cause and cause.affects_energy
    assert cause.values["geoms"] == left_out and cause.segments == ("j",)  # the rod (group 1) is counted
    assert cause.values["mujoco"] == pytest.approx(BOX, rel=1e-12)
    assert cause.values["pinocchio"] == pytest.approx(BOX + BALL, rel=1e-12)
    assert cause.values["mujoco, every group"] == pytest.approx(BOX + BALL, rel=1e-12)
    assert short_cause(cause) in check.reason()
    assert f"{cause.element}: {cause.summary}" in check.agreements[0].reason  # the engine shown is the one departing


@pytest.mark.skipif(not HAS_DRAKE, reason="Drake (the optional extra [drake]) is not installed")
def test_drake_which_ignores_the_option_too_is_named_and_abstains() -> None:
    """Drake counts every geom as Pinocchio does (the catalogue's reading): its finding carries the id, it casts no
    vote (formerly "MuJoCo departs"), and asked for it could not check the model on the cause's quantities."""
    check = koenig_check.compare(
        CAUSES / "inertia_group.xml", n_poses=3, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"]
    )
    findings = check.comparisons[0].findings
    assert not [f for f in findings if f.kind is Kind.VERDICT]
    (drake,) = [f for f in findings if f.engine == "drake" and f.cause == "pinocchio.mjcf.inertiagrouprange"]
    assert drake.root_cause and drake.values["geoms"] == ("ball",)
    (unable,) = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.values["causes"] == ("pinocchio.mjcf.inertiagrouprange",)
    assert unable.values["quantities"] == ("mass", "com", "inertia")
