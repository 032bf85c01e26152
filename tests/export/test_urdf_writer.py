"""MJCF → URDF: each construct's export has the original's M(q) in MuJoCo and Pinocchio; what URDF cannot hold."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from export_constructs import CONSTRUCTS, POSES, URDF_REFUSED, check_against_original, export_to
from export_helpers import (
    MODELS,
    RTOL,
    in_order,
    mujoco_matrix,
    mujoco_model,
    one_dof_joint_names,
    random_joint_values,
    relative_difference,
)

import koenig_check
from koenig_check.export import ExportRefusedError

WRITABLE = [name for name in CONSTRUCTS if name not in URDF_REFUSED]


@pytest.mark.parametrize("name", WRITABLE)
def test_urdf_has_the_original_mass_matrix_in_both_engines(tmp_path: Path, name: str) -> None:
    result = export_to(tmp_path, name, "urdf")
    assert result.equivalent, result.proof.summary()
    check_against_original(result, name, "urdf")


@pytest.mark.parametrize("name", ["hinge_ref.xml", "free_root.xml", "mesh_inertia.xml", "defaults.xml"])
def test_round_trip_mjcf_urdf_mujoco_import(tmp_path: Path, name: str) -> None:
    """MJCF → URDF → MuJoCo's own URDF import gives the original's M(q)."""
    result = export_to(tmp_path, name, "urdf")
    original = mujoco_model(MODELS / name)
    imported = mujoco_model(result.path, floating=result.floating_base)
    rng = np.random.default_rng(3)
    for _ in range(POSES):
        values = random_joint_values(one_dof_joint_names(original), rng)
        reference, order = mujoco_matrix(original, values)
        matrix, labels = mujoco_matrix(imported, values)
        assert relative_difference(reference, in_order(matrix, labels, order)) < RTOL


def test_ball_joint_is_refused_naming_the_joint(tmp_path: Path) -> None:
    out = tmp_path / "ball.urdf"
    with pytest.raises(ExportRefusedError, match="ball joint") as caught:
        koenig_check.export(MODELS / "ball.xml", to="urdf", out=out)
    assert "socket" in str(caught.value)
    assert [c.construct for c in caught.value.constructs] == ["ball joint"]
    assert not out.exists()


def test_several_joints_in_one_body_are_refused_naming_them(tmp_path: Path) -> None:
    with pytest.raises(ExportRefusedError, match="body thigh") as caught:
        koenig_check.export(MODELS / "multi_joint.xml", to="urdf", out=tmp_path / "multi.urdf")
    assert "hip_x" in str(caught.value) and "hip_y" in str(caught.value)


def test_free_root_says_floating_base(tmp_path: Path) -> None:
    result = koenig_check.export(MODELS / "free_root.xml", to="urdf", out=tmp_path / "free.urdf", poses=2)
    assert result.floating_base
    assert "floating" not in result.path.read_text()  # the free joint itself is left out


def test_drake_extensions_write_rotor_inertia(tmp_path: Path) -> None:
    result = koenig_check.export(
        MODELS / "armature.xml", to="urdf", out=tmp_path / "arm.urdf", drake_extensions=True, poses=2
    )
    text = result.path.read_text()
    assert 'drake:rotor_inertia value="0.05"' in text and 'drake:rotor_inertia value="0.2"' in text
    assert all("drake:rotor_inertia" in n.reason for n in result.not_carried if n.construct == "armature")
