"""Seeded random canonical states (MuJoCo layout), a minimal sampler for engine tests."""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.coupling import apply_joint_relations

#: Half-width of the box free-joint positions and unlimited slides are drawn from.
POSITION_RANGE = 1.0


def _unit_quaternions(rng: np.random.Generator, n: int) -> np.ndarray:
    """Uniform random unit quaternions (normalized 4-D Gaussians), ``(w, x, y, z)``, shape (n, 4)."""
    quat = rng.normal(size=(n, 4))
    return quat / np.linalg.norm(quat, axis=1, keepdims=True)


def random_states(
    model: mujoco.MjModel, n: int, seed: int = 0, velocity_scale: float = 1.0
) -> tuple[np.ndarray, np.ndarray]:
    """Draw random canonical states.

    Limited hinges and slides are uniform within their range, unlimited hinges uniform in
    ``[-π, π]``, unlimited slides and free-joint positions uniform in ``[-1, 1]``, ball and free
    orientations uniform on SO(3); every velocity is normal with standard deviation
    ``velocity_scale``.  Joints coupled to others (URDF mimic, MJCF joint equalities) then follow
    their leaders in position and velocity.

    Parameters
    ----------
    model : mujoco.MjModel
        Defines the canonical layout (or anything with a ``.model`` MjModel attribute).
    n : int
        Number of poses ``P``.
    seed : int
        Seed of ``numpy.random.default_rng``.
    velocity_scale : float

    Returns
    -------
    qpos : ndarray, shape (n, nq)
    qvel : ndarray, shape (n, nv)
    """
    model = getattr(model, "model", model)
    rng = np.random.default_rng(seed)
    qpos = np.tile(np.asarray(model.qpos0, dtype=float), (n, 1))
    for j in range(model.njnt):
        adr = int(model.jnt_qposadr[j])
        kind = int(model.jnt_type[j])
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            qpos[:, adr : adr + 3] = rng.uniform(-POSITION_RANGE, POSITION_RANGE, size=(n, 3))
            qpos[:, adr + 3 : adr + 7] = _unit_quaternions(rng, n)
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            qpos[:, adr : adr + 4] = _unit_quaternions(rng, n)
        else:
            lo, hi = model.jnt_range[j]
            if not model.jnt_limited[j] or hi <= lo:
                half = np.pi if kind == mujoco.mjtJoint.mjJNT_HINGE else POSITION_RANGE
                lo, hi = -half, half
            qpos[:, adr] = rng.uniform(lo, hi, size=n)
    qvel = rng.normal(scale=velocity_scale, size=(n, model.nv))
    qpos, qvel, _ = apply_joint_relations(model, qpos, qvel)
    return qpos, qvel
