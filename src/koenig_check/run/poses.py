"""Pose and trajectory samplers, in the canonical state convention (MuJoCo ``qpos``/``qvel``).

Every sampler is seeded and returns a :class:`PoseSet`.  Random states (random poses, the velocities
of keyframes at rest, a trajectory's start) all come from the package's one sampler,
:mod:`koenig_check.engines.sampling`, whose docstring gives the distribution.  Trajectories are
simulated by MuJoCo itself, with gravity and contacts off unless asked for, so that the
``integrated`` angle convention of eq. (36) has a real path to integrate along.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field

import mujoco
import numpy as np

from koenig_check.engines.coupling import apply_joint_relations, joint_relations
from koenig_check.engines.sampling import (
    check_pose_count,
    check_velocity_scale,
    random_state_range,
    random_states,
)

_FREE, _BALL, _SLIDE, _HINGE = (
    int(mujoco.mjtJoint.mjJNT_FREE),
    int(mujoco.mjtJoint.mjJNT_BALL),
    int(mujoco.mjtJoint.mjJNT_SLIDE),
    int(mujoco.mjtJoint.mjJNT_HINGE),
)


@dataclass(frozen=True)
class PoseSet:
    """A batch of canonical states.

    Attributes
    ----------
    qpos : ndarray, shape (P, nq)
    qvel : ndarray, shape (P, nv)
    ids : tuple of str
        One label per pose, e.g. ``"random-3"``, ``"key:home"``, ``"grid-12"``, ``"traj-40"``.
    kind : str
        ``random``, ``keyframes``, ``grid``, ``trajectory`` or ``file``.
    times : ndarray, shape (P,), optional
        Sample times when the poses form a path (trajectories), else ``None``.
    grid : dict, optional
        For grid sweeps: the two joint names and the swept values.
    notes : tuple of str
        Anything the sampler had to decide (e.g. keyframes without velocities).
    """

    qpos: np.ndarray
    qvel: np.ndarray
    ids: tuple[str, ...]
    kind: str
    times: np.ndarray | None = None
    grid: dict | None = None
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        if self.qpos.shape[0] != self.qvel.shape[0] or self.qpos.shape[0] != len(self.ids):
            raise ValueError(
                f"PoseSet: {self.qpos.shape[0]} qpos rows, {self.qvel.shape[0]} qvel rows, {len(self.ids)} ids"
            )

    @property
    def n_poses(self) -> int:
        """Number of poses ``P``."""
        return self.qpos.shape[0]

    def slice(self, start: int, stop: int) -> PoseSet:
        """Poses ``start`` to ``stop − 1`` as states alone (no path times, grid or notes).

        Parameters
        ----------
        start, stop : int

        Returns
        -------
        PoseSet
        """
        return PoseSet(self.qpos[start:stop], self.qvel[start:stop], self.ids[start:stop], self.kind)


def random_poses(model: mujoco.MjModel, n: int, seed: int = 0, velocity_scale: float = 1.0) -> PoseSet:
    """Random poses within joint limits and normal random velocities.

    Parameters
    ----------
    model : mujoco.MjModel
    n : int
        Number of poses, >= 1.
    seed : int
    velocity_scale : float
        Standard deviation of every ``qvel`` component (rad/s or m/s); must be > 0.

    Returns
    -------
    PoseSet
        Joints coupled to others (URDF mimic, MJCF joint equalities) follow their leaders, in
        position and velocity; the notes say so.
    """
    check_pose_count(n)
    return random_pose_range(model, 0, n, seed=seed, velocity_scale=velocity_scale)


def check_random(n: int, seed: int, velocity_scale: float) -> None:
    """Refuse a random pose request before any work starts.

    Parameters
    ----------
    n : int
        Number of poses, >= 1.
    seed : int
        >= 0.
    velocity_scale : float
        > 0.
    """
    check_pose_count(n)
    check_velocity_scale(velocity_scale)
    if seed < 0:
        raise ValueError(f"seed must be >= 0, got {seed}")


def random_pose_range(
    model: mujoco.MjModel, start: int, stop: int, seed: int = 0, velocity_scale: float = 1.0
) -> PoseSet:
    """Poses ``start`` to ``stop − 1`` of the seeded random sequence of :func:`random_poses`.

    The states are those of :func:`koenig_check.engines.sampling.random_state_range`, the package's one
    sampler (its docstring gives the distribution); pose ``i`` depends only on ``(seed, i)``.

    Parameters
    ----------
    model : mujoco.MjModel
    start, stop : int
        ``0 <= start < stop``.
    seed : int
        Non-negative.
    velocity_scale : float

    Returns
    -------
    PoseSet
        Ids ``random-i``.
    """
    qpos, qvel, notes = random_state_range(model, start, stop, seed, velocity_scale)
    return PoseSet(qpos, qvel, tuple(f"random-{i}" for i in range(start, stop)), "random", notes=tuple(notes))


def keyframe_poses(model: mujoco.MjModel, seed: int = 0, velocity_scale: float = 1.0) -> PoseSet:
    """The model's keyframes; keyframe ``k`` at rest gets the velocities of random pose ``k`` (noted).

    The velocities are those of :func:`random_states` with the same seed and scale, so keyframe ``k`` at
    rest moves as random pose ``k`` of ``--pose-kind random`` does.

    Parameters
    ----------
    model : mujoco.MjModel
    seed : int
    velocity_scale : float

    Returns
    -------
    PoseSet
        Empty (zero poses) when the model has no keyframe.
    """
    check_velocity_scale(velocity_scale)
    qpos = np.array(model.key_qpos, dtype=float).reshape(model.nkey, model.nq)
    qvel = np.array(model.key_qvel, dtype=float).reshape(model.nkey, model.nv)
    at_rest = ~np.any(qvel, axis=1)
    if at_rest.any():
        qvel[at_rest] = random_states(model, model.nkey, seed, velocity_scale)[1][at_rest]
    notes = []
    ids = []
    for k in range(model.nkey):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_KEY, k) or str(k)
        ids.append(f"key:{name}")
        if at_rest[k]:
            notes.append(f"keyframe {name!r} is at rest: random velocities (seed {seed}) were drawn for it")
    qpos, qvel, coupled = apply_joint_relations(model, qpos, qvel)
    notes += coupled
    return PoseSet(qpos, qvel, tuple(ids), "keyframes", notes=tuple(notes))


def _joint(model: mujoco.MjModel, name: str) -> int:
    j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
    if j < 0:
        names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, i) for i in range(model.njnt)]
        raise ValueError(f"no joint named {name!r}; joints: {names}")
    if int(model.jnt_type[j]) not in (_HINGE, _SLIDE):
        raise ValueError(f"joint {name!r} is not a hinge or slide joint: a grid sweeps scalar joints only")
    return j


def grid_poses(
    model: mujoco.MjModel,
    joint_a: str,
    joint_b: str,
    n: int = 25,
    rate_a: float = 1.0,
    rate_b: float = 1.0,
) -> PoseSet:
    """A grid sweep over two joints (the paper's section-3 map), all other joints at ``qpos0``.

    Each joint is swept over its range if limited, else over [-π, π] (hinges) or
    ``qpos0 ± 1`` (slides); the two joints move at ``rate_a``, ``rate_b``, the others rest.

    Parameters
    ----------
    model : mujoco.MjModel
    joint_a, joint_b : str
        Joint names.
    n : int
        Samples per joint; the grid has ``n²`` poses, joint_a varying slowest.
    rate_a, rate_b : float
        Joint velocities.

    Returns
    -------
    PoseSet
        With ``grid = {"joints": (a, b), "values": (values_a, values_b), "shape": (n, n)}``.
    """
    check_pose_count(n)
    values = []
    joints = [_joint(model, joint_a), _joint(model, joint_b)]
    for j in joints:
        lo, hi = model.jnt_range[j]
        if model.jnt_limited[j] and hi > lo:
            values.append(np.linspace(lo, hi, n))
        elif int(model.jnt_type[j]) == _HINGE:
            values.append(np.linspace(-np.pi, np.pi, n))
        else:
            q0 = model.qpos0[model.jnt_qposadr[j]]
            values.append(np.linspace(q0 - 1, q0 + 1, n))
    A, B = np.meshgrid(values[0], values[1], indexing="ij")
    qpos = np.tile(model.qpos0, (n * n, 1))
    qvel = np.zeros((n * n, model.nv))
    for j, vals, rate in zip(joints, (A, B), (rate_a, rate_b), strict=True):
        qpos[:, model.jnt_qposadr[j]] = vals.ravel()
        qvel[:, model.jnt_dofadr[j]] = rate
    qpos, qvel, notes = apply_joint_relations(model, qpos, qvel)
    return PoseSet(
        qpos,
        qvel,
        tuple(f"grid-{i}" for i in range(n * n)),
        "grid",
        grid={"joints": (joint_a, joint_b), "values": tuple(values), "shape": (n, n)},
        notes=tuple(notes),
    )


def trajectory_poses(
    model: mujoco.MjModel,
    duration: float = 1.0,
    samples: int = 200,
    seed: int = 0,
    velocity_scale: float = 1.0,
    gravity: bool = False,
    contacts: bool = False,
    free_motion: bool = True,
    from_reference: bool = True,
) -> PoseSet:
    """A trajectory simulated by MuJoCo from a seeded random state.

    The model is copied; gravity and contacts are switched off unless requested, and
    with ``free_motion`` joint limits, equality constraints, friction loss, springs,
    dampers and actuators are switched off too, so by default the motion is the
    torque-free motion of the mechanism (its kinetic energy is conserved).  By default the
    path starts at the reference configuration ``qpos0`` (the paper's initial state, where
    every Δθ is zero) with seeded random velocities, so that the path integrals of ω
    measure the rotation from the reference.  Every
    simulation step is kept internally and ``samples`` evenly spaced states are
    returned with their times.

    Parameters
    ----------
    model : mujoco.MjModel
    duration : float
        Simulated time in seconds, > 0.
    samples : int
        Number of returned states (>= 2), including the initial one.
    seed : int
    velocity_scale : float
    gravity, contacts : bool
    free_motion : bool
    from_reference : bool
        Start at ``qpos0``; otherwise at a seeded random configuration.

    Returns
    -------
    PoseSet
        With ``times``.
    """
    if samples < 2:
        raise ValueError(f"a trajectory needs at least 2 samples, got {samples}")
    if not duration > 0:
        raise ValueError(f"trajectory duration must be > 0, got {duration}")
    check_velocity_scale(velocity_scale)
    sim = copy.deepcopy(model)
    if not gravity:
        sim.opt.gravity[:] = 0.0
    if not contacts:
        sim.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
    if free_motion:
        for flag in ("LIMIT", "EQUALITY", "FRICTIONLOSS", "SPRING", "DAMPER", "ACTUATION"):
            sim.opt.disableflags |= int(getattr(mujoco.mjtDisableBit, f"mjDSBL_{flag}"))
    data = mujoco.MjData(sim)
    start = random_poses(model, 1, seed=seed, velocity_scale=velocity_scale)
    data.qpos[:] = model.qpos0 if from_reference else start.qpos[0]
    data.qvel[:] = start.qvel[0]
    steps = max(int(np.ceil(duration / sim.opt.timestep)), samples - 1)
    keep = np.unique(np.round(np.linspace(0, steps, samples)).astype(int))
    qpos = np.empty((keep.size, model.nq))
    qvel = np.empty((keep.size, model.nv))
    times = np.empty(keep.size)
    k = 0
    for step in range(steps + 1):
        if step == keep[k]:
            qpos[k], qvel[k], times[k] = data.qpos, data.qvel, data.time
            k += 1
            if k == keep.size:
                break
        mujoco.mj_step(sim, data)
    if not np.all(np.isfinite(qpos)) or not np.all(np.isfinite(qvel)):
        raise ValueError("the simulated trajectory diverged (non-finite state): shorten it or lower the velocity")
    notes = []
    if joint_relations(model) and (free_motion or sim.opt.disableflags & int(mujoco.mjtDisableBit.mjDSBL_EQUALITY)):
        notes.append(
            "couplings between joints (mimic, joint equalities) are not enforced along the simulated path "
            "(equality constraints off for torque-free motion)"
        )
    return PoseSet(
        qpos, qvel, tuple(f"traj-{i}" for i in range(keep.size)), "trajectory", times=times, notes=tuple(notes)
    )
