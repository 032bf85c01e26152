"""Every number that reaches an export parses back to the same double, so the compiled models are equal."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from export_helpers import MODELS, mujoco_model

import koenig_check
from koenig_check.export.transforms import matrix_to_rpy, number, rpy_to_matrix

#: Compiled arrays that must survive the export bit for bit (no ref folded in these models).
EXACT = ("body_mass", "body_ipos", "body_inertia", "body_pos", "jnt_axis", "jnt_pos", "jnt_range", "dof_armature")


@pytest.mark.parametrize("name", ["mesh_inertia.xml", "settotalmass.xml", "defaults.xml", "armature.xml"])
def test_portable_mjcf_compiles_to_the_same_numbers(tmp_path: Path, name: str) -> None:
    result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
    original, export = mujoco_model(MODELS / name), mujoco_model(result.path)
    for field in EXACT:
        assert np.array_equal(getattr(original, field), getattr(export, field)), field
    assert np.abs(original.body_iquat - export.body_iquat).max() <= 4 * np.finfo(float).eps


def test_urdf_to_mjcf_compiles_to_the_same_numbers(tmp_path: Path) -> None:
    result = koenig_check.export(MODELS / "arm.urdf", to="mjcf", out=tmp_path / "arm.xml", poses=2)
    spec = mujoco.MjSpec.from_file(str(MODELS / "arm.urdf"))
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    original, export = spec.compile(), mujoco_model(result.path)
    for field in ("body_mass", "body_ipos", "body_inertia", "body_pos", "jnt_axis", "jnt_range"):
        assert np.array_equal(getattr(original, field), getattr(export, field)), field


def test_numbers_round_trip_exactly() -> None:
    rng = np.random.default_rng(11)
    values = np.concatenate([rng.normal(size=500) * 10.0 ** rng.integers(-12, 12, size=500), [0.1, 1 / 3, -0.0]])
    assert all(float(number(v)) == v for v in values)


@pytest.mark.parametrize("pitch", [0.3, np.pi / 2, -np.pi / 2, np.pi / 2 - 1e-9])
def test_rpy_round_trip(pitch: float) -> None:
    rng = np.random.default_rng(2)
    for _ in range(20):
        roll, yaw = rng.uniform(-np.pi, np.pi, size=2)
        rot = rpy_to_matrix(np.array([roll, pitch, yaw]))
        assert np.abs(rpy_to_matrix(matrix_to_rpy(rot)) - rot).max() < 1e-12
