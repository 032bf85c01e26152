"""Geoms go out where the original has them: MuJoCo places the exported mesh as it places the original's."""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import numpy as np
import pytest
from export_helpers import MODELS, mujoco_model

import koenig_check


def _mesh_geom_pose(model: mujoco.MjModel, angle: float) -> tuple[np.ndarray, np.ndarray]:
    data = mujoco.MjData(model)
    data.qpos[:] = angle
    mujoco.mj_kinematics(model, data)
    g = int(np.flatnonzero(model.geom_type == mujoco.mjtGeom.mjGEOM_MESH)[0])
    return data.geom_xpos[g].copy(), data.geom_xmat[g].reshape(3, 3).copy()


@pytest.mark.parametrize(("to", "suffix"), [("urdf", ".urdf"), ("mjcf", ".xml")])
def test_mesh_geom_is_placed_as_in_the_original(tmp_path: Path, to: str, suffix: str) -> None:
    result = koenig_check.export(MODELS / "mesh_inertia.xml", to=to, out=tmp_path / f"mesh{suffix}", poses=2)
    match = re.search(r'(?:filename|file)="([^"]*wedge.obj)"', result.path.read_text())
    assert match is not None
    written = Path(match.group(1))
    assert not written.is_absolute()  # relative to the written file
    assert (result.path.parent / written).resolve() == (MODELS / "meshes" / "wedge.obj").resolve()
    original, export = mujoco_model(MODELS / "mesh_inertia.xml"), mujoco_model(result.path)
    for angle in (0.0, 0.7):
        (p0, r0), (p1, r1) = _mesh_geom_pose(original, angle), _mesh_geom_pose(export, angle)
        assert np.abs(p0 - p1).max() < 1e-9 and np.abs(r0 - r1).max() < 1e-9
