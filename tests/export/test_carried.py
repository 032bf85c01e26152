"""What a target cannot hold is listed as not carried, never dropped silently."""

from __future__ import annotations

from pathlib import Path

import pytest
from export_helpers import MODELS

import koenig_check


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


def test_portable_mjcf_keeps_ball_armature_and_equality(tmp_path: Path) -> None:
    for name in ("ball.xml", "armature.xml", "equality.xml"):
        result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
        assert result.equivalent, result.proof.summary()
        assert not [n for n in result.not_carried if n.affects_mass_matrix]
    text = (tmp_path / "equality.xml").read_text()
    assert 'joint1="finger2"' in text and 'joint2="finger1"' in text
