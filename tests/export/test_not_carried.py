"""What a URDF cannot hold: refused naming the joints, or listed as not carried (never dropped silently)."""

from __future__ import annotations

from pathlib import Path

import pytest
from export_helpers import MODELS

import koenig_check
from koenig_check.export import ExportRefusedError


def test_ball_joint_is_refused_for_urdf_naming_the_joint(tmp_path: Path) -> None:
    out = tmp_path / "ball.urdf"
    with pytest.raises(ExportRefusedError, match="ball joint") as caught:
        koenig_check.export(MODELS / "ball.xml", to="urdf", out=out)
    assert "socket" in str(caught.value)
    assert [c.construct for c in caught.value.constructs] == ["ball joint"]
    assert not out.exists()


def test_several_joints_in_one_body_are_refused_naming_them(tmp_path: Path) -> None:
    model = tmp_path / "two_joints.xml"
    model.write_text(
        '<mujoco><worldbody><body name="b"><joint name="tilt" axis="0 1 0"/><joint name="pan" axis="0 0 1"/>'
        '<geom size="0.1" mass="1"/></body></worldbody></mujoco>'
    )
    with pytest.raises(ExportRefusedError, match="body b") as caught:
        koenig_check.export(model, to="urdf", out=tmp_path / "two_joints.urdf")
    assert "tilt" in str(caught.value) and "pan" in str(caught.value)


@pytest.mark.parametrize(
    ("name", "construct", "element"),
    [
        ("armature.xml", "armature", "joint j1"),
        ("armature.xml", "armature", "joint j2"),
        ("equality.xml", "equality", "joint mimic"),
        ("free_root.xml", "floating base", "joint floating"),
        ("defaults.xml", "geom shape", "geoms"),  # capsules: URDF has no capsule
    ],
)
def test_urdf_lists_what_it_does_not_carry(tmp_path: Path, name: str, construct: str, element: str) -> None:
    result = koenig_check.export(MODELS / name, to="urdf", out=tmp_path / "out.urdf", poses=2)
    found = [n for n in result.not_carried if n.construct == construct]
    assert any(element in n.element for n in found), [n.message() for n in result.not_carried]
    assert result.equivalent, result.proof.summary()


def test_free_root_says_floating_base(tmp_path: Path) -> None:
    result = koenig_check.export(MODELS / "free_root.xml", to="urdf", out=tmp_path / "free.urdf", poses=2)
    assert result.floating_base
    assert "floating" not in result.path.read_text()  # the free joint itself is left out


def test_portable_mjcf_keeps_ball_armature_and_equality(tmp_path: Path) -> None:
    for name in ("ball.xml", "armature.xml", "equality.xml"):
        result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
        assert result.equivalent, result.proof.summary()
        assert not [n for n in result.not_carried if n.affects_mass_matrix]
    text = (tmp_path / "equality.xml").read_text()
    assert 'joint1="finger2"' in text and 'joint2="finger1"' in text


def test_drake_extensions_write_rotor_inertia(tmp_path: Path) -> None:
    result = koenig_check.export(
        MODELS / "armature.xml", to="urdf", out=tmp_path / "arm.urdf", drake_extensions=True, poses=2
    )
    text = result.path.read_text()
    assert 'drake:rotor_inertia value="0.05"' in text and 'drake:rotor_inertia value="0.2"' in text
    assert all("drake:rotor_inertia" in n.reason for n in result.not_carried if n.construct == "armature")
