"""Import parity: the same file in both engines, and files made to differ in one link."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.engines import load_model
from koenig_check.modelfile.compiler import compiler_findings
from koenig_check.report.parity_table import format_parity

MODELS = Path(__file__).resolve().parents[2] / "models"
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


# serial7: j1 -> link1 -> j2 -> link2 -> j3 -> link3 -> j4 -> link4 (+ welded link4_mount) -> j5 -> link5 -> j6 -> ...
# The dof check compares, per dof, the angular velocity and pole velocity of the dof's own segment under a unit
# rate of that dof: the joint axis alone.  A moved COM or a moved joint origin is a segment cause, not an axis one.
@pytest.mark.parametrize(
    ("pattern", "replacement", "segments", "dofs"),
    [
        (
            # link3's COM moves 2 cm along link3's z: only segment j3's COM differs; no joint axis changed.
            r'(<link name="link3">.*?<origin xyz=")-0.02 0.03 0.1(")',
            r"\g<1>-0.02 0.03 0.12\g<2>",
            {"j3": ("com",)},
            {},
        ),
        (
            # j5's origin moves 2 cm: link5 and everything after it (segments j5, j6, j7) moves rigidly with it,
            # so their anchors and COMs move; the rates of j5..j7 still turn them about the same relative geometry.
            r'(<joint name="j5".*?<origin xyz=")0 0 0.15(")',
            r"\g<1>0 0 0.17\g<2>",
            {"j5": ("com", "anchor"), "j6": ("com", "anchor"), "j7": ("com", "anchor")},
            {},
        ),
        (
            # j6's axis tilts: at the reference pose (angle 0) nothing has moved, only j6's rate turns differently.
            r'(<joint name="j6".*?<axis xyz=")0 1 0(")',
            r"\g<1>0.1 1 0\g<2>",
            {},
            {"j6": ("axis",)},
        ),
    ],
    ids=["com", "anchor", "axis"],
)
def test_geometry_changed_in_a_copy_is_named_on_exactly_the_affected_segments_and_dofs(
    tmp_path: Path, pattern: str, replacement: str, segments: dict, dofs: dict
) -> None:
    altered = _altered_copy(tmp_path, "serial7.urdf", pattern, replacement)
    report = import_parity(load_model(MODELS / "serial7.urdf", pinocchio_source=altered))
    assert not report.clean
    assert {s.name: s.causes for s in report.differing_segments} == segments, format_parity(report)
    assert {d.joint: d.causes for d in report.differing_dofs} == dofs, format_parity(report)
    assert report.total_mass[0] == pytest.approx(report.total_mass[1], rel=1e-12)


def test_armature_missing_in_one_file_is_named_per_dof() -> None:
    """armature_chain.urdf has no armature (URDF cannot carry it); the MJCF twin has 0.02/0.015/0.01/0.005."""
    report = import_parity(load_model(MODELS / "armature_chain.xml", pinocchio_source=MODELS / "armature_chain.urdf"))
    assert not report.clean
    assert report.differing_segments == []
    assert {d.joint: d.causes for d in report.differing_dofs} == {j: ("armature",) for j in ("j1", "j2", "j3", "j4")}
    arm = {d.joint: d.armature for d in report.dofs}
    for joint, expected in {"j1": 0.02, "j2": 0.015, "j3": 0.01, "j4": 0.005}.items():
        assert arm[joint][0] == pytest.approx(expected, rel=1e-9), joint
        assert arm[joint][1] == pytest.approx(0.0, abs=1e-9 * expected), joint


def test_settotalmass_is_reported(tmp_path: Path) -> None:
    """MuJoCo applies settotalmass; Pinocchio's MJCF parser keeps the file's masses (0.6 kg + 2 kg)."""
    text = (MODELS / "gimbal.xml").read_text().replace("<compiler ", '<compiler settotalmass="5" ', 1)
    path = tmp_path / "heavier.xml"
    path.write_text(text)
    findings = compiler_findings(path)
    assert any("settotalmass=5" in f for f in findings)
    report = import_parity(load_model(path))
    assert not report.clean
    assert report.total_mass[0] == pytest.approx(5.0)
    assert report.total_mass[1] == pytest.approx(0.6 + 2.0)
    assert {s.name for s in report.differing_segments} == {"outer_z", "inner_x"}
    for s in report.differing_segments:
        assert "mass" in s.causes and s.mass[0] / s.mass[1] == pytest.approx(5.0 / 2.6, rel=1e-9)
    assert any("same factor 1.92307692" in f for f in report.findings)
    assert np.isfinite(report.mass_matrix_max_rel)


def test_segment_poses_that_differ_only_by_a_dropped_root_pose_say_so() -> None:
    """Next to "no import difference", a pose difference reads as what it is: the root pose Pinocchio drops."""
    report = import_parity(load_model(Path(__file__).resolve().parents[1] / "models" / "causes" / "posed_root.xml"))
    assert report.clean
    (line,) = [f for f in report.findings if "segment poses differ" in f]
    assert line.endswith("the dropped root-body pose explains it (a constant transform, no effect on the energy)")
