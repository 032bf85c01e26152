"""A compiled MuJoCo model's geoms, as the file gave them: shape, pose in the body, mesh file and scale."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.export.transforms import Pose, compose, inverse, quat_to_matrix

#: MuJoCo geom type -> the shape name used in this module.
SHAPES = {
    int(mujoco.mjtGeom.mjGEOM_PLANE): "plane",
    int(mujoco.mjtGeom.mjGEOM_HFIELD): "hfield",
    int(mujoco.mjtGeom.mjGEOM_SPHERE): "sphere",
    int(mujoco.mjtGeom.mjGEOM_CAPSULE): "capsule",
    int(mujoco.mjtGeom.mjGEOM_ELLIPSOID): "ellipsoid",
    int(mujoco.mjtGeom.mjGEOM_CYLINDER): "cylinder",
    int(mujoco.mjtGeom.mjGEOM_BOX): "box",
    int(mujoco.mjtGeom.mjGEOM_MESH): "mesh",
    int(mujoco.mjtGeom.mjGEOM_SDF): "sdf",
}


@dataclass(frozen=True)
class Geom:
    """One geom of a compiled model.

    Parameters
    ----------
    name : str
        The geom's name, or ``geom<id>``.
    body : int
        The body holding it.
    shape : str
        One of :data:`SHAPES`' values.
    size : ndarray, shape (3,)
        MuJoCo's ``geom_size`` (half-sizes, radius, half-length).
    pose : Pose
        In the body frame, as written in the file (for a mesh, MuJoCo's recentring undone).
    mesh_file : str
        The mesh's absolute path, or ``""``.
    mesh_scale : ndarray, shape (3,)
    collides : bool
        ``contype`` or ``conaffinity`` non-zero.
    rgba : ndarray, shape (4,)
    """

    name: str
    body: int
    shape: str
    size: np.ndarray
    pose: Pose
    mesh_file: str
    mesh_scale: np.ndarray
    collides: bool
    rgba: np.ndarray


def _path(model: mujoco.MjModel, adr: int) -> str:
    if adr < 0:
        return ""
    raw = bytes(model.paths[adr:])
    return raw.split(b"\0", 1)[0].decode()


def model_geoms(model: mujoco.MjModel, model_dir: str | os.PathLike[str] | None = None) -> list[Geom]:
    """Every geom of a compiled model, in the frame of its body.

    Parameters
    ----------
    model : mujoco.MjModel
    model_dir : path, optional
        Directory relative mesh paths are read from (the original file's directory and meshdir).

    Returns
    -------
    list of Geom
    """
    out = []
    for g in range(model.ngeom):
        shape = SHAPES.get(int(model.geom_type[g]), "other")
        pose: Pose = (np.array(model.geom_pos[g], dtype=float), quat_to_matrix(model.geom_quat[g]))
        mesh_file, scale = "", np.ones(3)
        if shape == "mesh":
            mesh = int(model.geom_dataid[g])
            offset = (np.array(model.mesh_pos[mesh], dtype=float), quat_to_matrix(model.mesh_quat[mesh]))
            pose = compose(pose, inverse(offset))
            mesh_file = _path(model, int(model.mesh_pathadr[mesh]))
            if mesh_file and model_dir is not None and not Path(mesh_file).is_absolute():
                mesh_file = str(Path(model_dir) / mesh_file)
            scale = np.array(model.mesh_scale[mesh], dtype=float)
        out.append(
            Geom(
                model.geom(g).name or f"geom{g}",
                int(model.geom_bodyid[g]),
                shape,
                np.array(model.geom_size[g], dtype=float),
                pose,
                mesh_file,
                scale,
                bool(model.geom_contype[g] or model.geom_conaffinity[g]),
                np.array(model.geom_rgba[g], dtype=float),
            )
        )
    return out


def relative_mesh_path(mesh_file: str, out_file: str | os.PathLike[str]) -> str:
    """A mesh path relative to the directory of the file being written (absolute across drives).

    Parameters
    ----------
    mesh_file : str
    out_file : path

    Returns
    -------
    str
    """
    try:
        return os.path.relpath(mesh_file, Path(out_file).resolve().parent)
    except ValueError:
        return mesh_file
