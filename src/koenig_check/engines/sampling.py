"""The one seeded sampler of random canonical states (MuJoCo ``qpos``/``qvel``).

Every random pose of the package comes from :func:`random_state_range`: the CLI and the API
(``compare``, ``parity``, ``dynamics``), ``assert_energy_parity``, export's proof, the engines' load-time
checks and the comparison scripts.  A seed therefore gives the same poses everywhere.

The distribution, joint by joint (MuJoCo's joint order; one draw per joint and pose):

- hinge or slide, limited (``limited`` and ``range[0] < range[1]``): uniform in its range;
- hinge, unlimited: uniform in ``[-π, π]``;
- slide, unlimited: uniform in ``qpos0 ± POSITION_RANGE``;
- free: position uniform in the box ``qpos0 ± POSITION_RANGE`` (each axis), orientation a uniform
  random unit quaternion (uniform on SO(3)), written ``(w, x, y, z)`` with ``w >= 0``;
- ball: a uniform random unit quaternion, as for free joints;
- every velocity component ``qvel`` independently normal, mean 0, standard deviation ``velocity_scale``.

Joints coupled to others (URDF mimic, MJCF joint equalities) then follow their leaders, in position and
velocity.  Pose ``i`` depends only on ``(seed, i)``: poses are drawn in blocks of :data:`RANDOM_BLOCK`,
block ``b`` from ``numpy.random.default_rng([seed, b])`` (its positions first, then its velocities), so any
range of poses (a chunk, a worker's share) is the same as in the whole sequence.
"""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.coupling import apply_joint_relations

#: Half-width of the interval unlimited slides and free-joint positions are drawn from, about ``qpos0``.
POSITION_RANGE = 1.0

#: Random poses are drawn in blocks of this many, each block from its own seed, so that any range of
#: poses can be drawn without the others (chunks, processes, cluster workers) and gives the same poses.
RANDOM_BLOCK = 1024


def unit_quaternions(rng: np.random.Generator, n: int) -> np.ndarray:
    """Uniform random unit quaternions ``(w, x, y, z)`` with ``w >= 0``.

    Normalized 4-D standard normals are uniform on the unit 3-sphere, hence uniform rotations; the sign
    is chosen so that ``w >= 0`` (``q`` and ``-q`` are the same rotation).

    Parameters
    ----------
    rng : numpy.random.Generator
    n : int

    Returns
    -------
    ndarray, shape (n, 4)
    """
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    return q * np.where(q[:, :1] < 0, -1.0, 1.0)


def check_pose_count(n: int) -> None:
    """Refuse a number of poses below one.

    Parameters
    ----------
    n : int
    """
    if int(n) < 1:
        raise ValueError(f"number of poses must be >= 1, got {n}")


def check_velocity_scale(scale: float) -> None:
    """Refuse a velocity scale that is not a finite number > 0.

    Parameters
    ----------
    scale : float
    """
    if not np.isfinite(scale) or scale <= 0:
        raise ValueError(
            f"velocity scale must be a finite number > 0, got {scale}"
            + (": with zero velocity every energy is zero and no relative error is defined" if scale == 0 else "")
        )


def _block_qpos(model: mujoco.MjModel, n: int, rng: np.random.Generator) -> np.ndarray:
    """``n`` configurations drawn joint by joint from the module's distribution (no coupling applied)."""
    qpos = np.tile(np.asarray(model.qpos0, dtype=float), (n, 1))
    for j in range(model.njnt):
        adr, kind = int(model.jnt_qposadr[j]), int(model.jnt_type[j])
        lo, hi = (float(x) for x in model.jnt_range[j])
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            qpos[:, adr : adr + 3] += rng.uniform(-POSITION_RANGE, POSITION_RANGE, size=(n, 3))
            qpos[:, adr + 3 : adr + 7] = unit_quaternions(rng, n)
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            qpos[:, adr : adr + 4] = unit_quaternions(rng, n)
        elif model.jnt_limited[j] and hi > lo:
            qpos[:, adr] = rng.uniform(lo, hi, size=n)
        elif kind == mujoco.mjtJoint.mjJNT_HINGE:
            qpos[:, adr] = rng.uniform(-np.pi, np.pi, size=n)
        else:  # an unlimited slide
            qpos[:, adr] += rng.uniform(-POSITION_RANGE, POSITION_RANGE, size=n)
    return qpos


def random_state_range(
    model: mujoco.MjModel, start: int, stop: int, seed: int = 0, velocity_scale: float = 1.0
) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """States ``start`` to ``stop − 1`` of the seeded random sequence (the module's distribution).

    Parameters
    ----------
    model : mujoco.MjModel
        Defines the canonical layout (or anything with a ``.model`` MjModel attribute).
    start, stop : int
        ``0 <= start < stop``.
    seed : int
        Non-negative.
    velocity_scale : float
        Standard deviation of every ``qvel`` component (rad/s or m/s), finite and > 0.

    Returns
    -------
    qpos : ndarray, shape (stop − start, nq)
    qvel : ndarray, shape (stop − start, nv)
    notes : list of str
        The couplings imposed (one line per relation), empty for a model without any.
    """
    model = getattr(model, "model", model)
    if not 0 <= start < stop:
        raise ValueError(f"random poses: need 0 <= start < stop, got {start}, {stop}")
    if seed < 0:
        raise ValueError(f"seed must be >= 0, got {seed}")
    check_velocity_scale(velocity_scale)
    first, last = start // RANDOM_BLOCK, (stop - 1) // RANDOM_BLOCK
    qpos, qvel = [], []
    for block in range(first, last + 1):
        rng = np.random.default_rng([seed, block])
        qpos.append(_block_qpos(model, RANDOM_BLOCK, rng))
        qvel.append(rng.normal(scale=velocity_scale, size=(RANDOM_BLOCK, model.nv)))
    cut = slice(start - first * RANDOM_BLOCK, stop - first * RANDOM_BLOCK)
    return apply_joint_relations(model, np.concatenate(qpos)[cut], np.concatenate(qvel)[cut])


def random_states(
    model: mujoco.MjModel, n: int, seed: int = 0, velocity_scale: float = 1.0
) -> tuple[np.ndarray, np.ndarray]:
    """The first ``n`` states of the seeded random sequence (see :func:`random_state_range`).

    Parameters
    ----------
    model : mujoco.MjModel
        Defines the canonical layout (or anything with a ``.model`` MjModel attribute).
    n : int
        Number of poses ``P``, >= 1.
    seed : int
        Non-negative.
    velocity_scale : float
        Standard deviation of every ``qvel`` component.

    Returns
    -------
    qpos : ndarray, shape (n, nq)
    qvel : ndarray, shape (n, nv)
    """
    check_pose_count(n)
    qpos, qvel, _ = random_state_range(model, 0, int(n), seed, velocity_scale)
    return qpos, qvel
