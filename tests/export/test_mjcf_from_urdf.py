"""URDF → MJCF: MuJoCo's import at full precision; Pinocchio reads the MJCF as it reads the URDF."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
from export_constructs import POSES, check_against_original, export_to
from export_helpers import (
    MODELS,
    RTOL,
    in_order,
    mujoco_model,
    pinocchio_matrix,
    pinocchio_model,
    random_joint_values,
    relative_difference,
)

import koenig_check


def test_urdf_to_mjcf_has_the_urdf_mass_matrix_in_both_engines(tmp_path: Path) -> None:
    result = export_to(tmp_path, "arm.urdf", "mjcf")
    assert result.equivalent, result.proof.summary()
    assert [n.construct for n in result.not_carried] == ["fixed links"]  # base and sensor, fused by MuJoCo
    check_against_original(result, "arm.urdf", "mjcf")


def test_round_trip_urdf_mjcf_pinocchio(tmp_path: Path) -> None:
    """URDF → MJCF → Pinocchio gives Pinocchio's M(q) of the URDF (off-diagonal, rotated inertias included)."""
    result = export_to(tmp_path, "arm.urdf", "mjcf")
    urdf = pinocchio_model(MODELS / "arm.urdf")
    mjcf = pinocchio_model(result.path)
    names = [urdf.names[j] for j in range(1, urdf.njoints)]
    rng = np.random.default_rng(5)
    for _ in range(POSES):
        values = random_joint_values(names, rng)
        reference, order = pinocchio_matrix(urdf, values)
        matrix, labels = pinocchio_matrix(mjcf, values)
        assert relative_difference(reference, in_order(matrix, labels, order)) < RTOL


def test_urdf_to_mjcf_compiles_to_the_same_numbers(tmp_path: Path) -> None:
    result = koenig_check.export(MODELS / "arm.urdf", to="mjcf", out=tmp_path / "arm.xml", poses=2)
    spec = mujoco.MjSpec.from_file(str(MODELS / "arm.urdf"))
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    original, export = spec.compile(), mujoco_model(result.path)
    for field in ("body_mass", "body_ipos", "body_inertia", "body_pos", "jnt_axis", "jnt_range"):
        assert np.array_equal(getattr(original, field), getattr(export, field)), field
