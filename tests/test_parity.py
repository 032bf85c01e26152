"""Import parity: the same file in both engines, and files made to differ in one link."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.parity import compiler_findings, format_parity, import_parity

MODELS = Path(__file__).resolve().parents[1] / "models"
PROJECT_FILES = sorted(p.name for p in MODELS.glob("*.xml")) + sorted(p.name for p in MODELS.glob("*.urdf"))


def _pair(name: str):
    return load_model(MODELS / name, floating=name == "free_body.urdf")


@pytest.mark.parametrize("name", PROJECT_FILES)
def test_project_models_have_no_import_difference(name: str) -> None:
    report = import_parity(_pair(name))
    assert report.clean, format_parity(report)
    assert report.total_mass[0] == pytest.approx(report.total_mass[1], rel=1e-12)
    assert report.mass_matrix_max_rel < 1e-12


def test_armature_is_measured_per_dof() -> None:
    report = import_parity(_pair("armature_chain.xml"))
    arm = {d.joint: d.armature for d in report.dofs}
    assert len(arm) == 4
    for joint, (a_mj, a_pin) in arm.items():
        assert a_mj > 0, joint  # every revolute joint of this model carries armature
        assert a_mj == pytest.approx(a_pin, rel=1e-9)


def _altered_copy(tmp_path: Path, source: str, pattern: str, replacement: str) -> Path:
    text = (MODELS / source).read_text()
    new, n = re.subn(pattern, replacement, text, count=1, flags=re.S)
    assert n == 1, pattern
    path = tmp_path / f"altered_{source}"
    path.write_text(new)
    return path


@pytest.mark.parametrize(
    ("source", "pattern", "replacement", "segment", "cause"),
    [
        (
            "serial7.urdf",
            r'(<link name="link3">.*?<mass value=")2(")',
            r"\g<1>2.2\g<2>",
            "j3",
            "mass",
        ),
        (
            "serial7.urdf",
            r'(<link name="link4_mount">.*?<mass value=")0.5(")',
            r"\g<1>0.45\g<2>",
            "j4",
            "mass",
        ),
        ("gimbal.xml", r'(<body name="inner".*?fullinertia=")0.019401', r"\g<1>0.025", "inner_x", "inertia"),
    ],
    ids=["urdf-link-mass", "urdf-welded-link-mass", "mjcf-inertia"],
)
def test_a_link_changed_in_a_copy_is_named(
    tmp_path: Path, source: str, pattern: str, replacement: str, segment: str, cause: str
) -> None:
    altered = _altered_copy(tmp_path, source, pattern, replacement)
    pair = load_model(MODELS / source, pinocchio_source=altered)
    report = import_parity(pair)
    assert not report.clean
    assert [s.name for s in report.differing_segments] == [segment]
    assert cause in report.causes_for(segment)
    assert segment in report.headline() and cause in report.headline()


def test_settotalmass_is_reported(tmp_path: Path) -> None:
    text = (MODELS / "gimbal.xml").read_text().replace("<compiler ", '<compiler settotalmass="5" ', 1)
    path = tmp_path / "heavier.xml"
    path.write_text(text)
    findings = compiler_findings(path)
    assert any("settotalmass=5" in f for f in findings)
    report = import_parity(load_model(path))
    # MuJoCo rescales to 5 kg; whatever Pinocchio does, the report must say which segments differ and why.
    if not report.clean:
        assert all("mass" in s.causes for s in report.differing_segments)
        assert any("same factor" in f for f in report.findings)
    else:
        assert report.total_mass[1] == pytest.approx(5.0)
    assert report.total_mass[0] == pytest.approx(5.0)
    assert np.isfinite(report.mass_matrix_max_rel)
