"""A pose set drawn by its kind: random, keyframes, a grid over two joints, or a trajectory."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from koenig_check.arguments import POSE_KINDS
from koenig_check.run import poses


def make_poses(
    mj_model: Any,
    kind: str = "random",
    n_poses: int = 20,
    seed: int = 0,
    velocity_scale: float = 1.0,
    grid_joints: Sequence[str] | None = None,
    duration: float = 1.0,
) -> poses.PoseSet:
    """Draw a pose set of a given kind for a MuJoCo model.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    kind : {"random", "keyframes", "grid", "trajectory"}
    n_poses : int
        Poses (random), samples per joint (grid) or samples along the path (trajectory).
    seed : int
    velocity_scale : float
    grid_joints : sequence of two str, optional
        Required for ``grid``.
    duration : float
        Trajectory duration in seconds.

    Returns
    -------
    PoseSet
    """
    if kind == "random":
        return poses.random_poses(mj_model, n_poses, seed=seed, velocity_scale=velocity_scale)
    if kind == "keyframes":
        keys = poses.keyframe_poses(mj_model, seed=seed, velocity_scale=velocity_scale)
        if keys.n_poses == 0:
            raise ValueError("the model has no keyframe")
        return keys
    if kind == "grid":
        if not grid_joints or len(grid_joints) != 2:
            raise ValueError("a grid sweep needs exactly two joint names")
        return poses.grid_poses(mj_model, grid_joints[0], grid_joints[1], n=n_poses)
    if kind == "trajectory":
        return poses.trajectory_poses(
            mj_model, duration=duration, samples=max(n_poses, 2), seed=seed, velocity_scale=velocity_scale
        )
    raise ValueError(f"unknown pose kind {kind!r}; choose one of {POSE_KINDS}")
