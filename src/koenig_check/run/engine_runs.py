"""One engine's view of a pose set: its segment states, its own energy and point velocities, from one sweep."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from koenig_check.engines.base import Engine
from koenig_check.formulas.point_masses import equimomental_points
from koenig_check.run.poses import PoseSet
from koenig_check.segments import SegmentStates


@dataclass
class EngineRun:
    """One engine's view of a pose set."""

    engine: str
    states: SegmentStates
    rigid: np.ndarray  # (P,) engine's rigid-body kinetic energy
    armature: np.ndarray  # (P,) engine's armature energy
    point_velocities: np.ndarray | None  # (P, B, 6, 3) from the engine's kinematics


def run_engine(engine: Engine, poses: PoseSet) -> EngineRun:
    """Evaluate one engine on a pose set: segment states, its energy, point velocities (one sweep).

    Parameters
    ----------
    engine : Engine
    poses : PoseSet

    Returns
    -------
    EngineRun
    """
    states, pv, rigid, armature = engine.sweep(poses.qpos, poses.qvel, _points_for(engine))
    return EngineRun(engine.engine, states, rigid, armature, pv)


#: Equimomental points of the last models' segments, keyed by their mass properties (see :func:`_points_for`).
_POINTS: dict[tuple, np.ndarray | None] = {}


def _points_for(engine: Engine) -> np.ndarray | None:
    """The equimomental points of an engine's segments, or None; computed once per set of mass properties.

    The mass properties are constant over the poses, so every chunk of a model asks for the same
    points: they are kept, keyed by the masses, inertias and names they come from.
    """
    mass, inertia = (np.asarray(a, dtype=float) for a in engine.mass_properties())
    key = (mass.tobytes(), inertia.tobytes(), tuple(engine.segment_names))
    if key in _POINTS:
        return _POINTS[key]
    try:
        points, _ = equimomental_points(mass, inertia, engine.segment_names)
    except ValueError:  # a non-physical inertia: point_masses will refuse, with the reason
        offsets = None
    else:
        points.setflags(write=False)
        offsets = points
    if len(_POINTS) >= 8:  # a few engines of a few models; a long run over many models starts afresh
        _POINTS.clear()
    _POINTS[key] = offsets
    return offsets


#: Poses on which the engines' verdicts are computed: the first of the run's poses.
VERDICT_POSES = 256


@dataclass(frozen=True)
class RunEnergies:
    """One engine's energies on some of the run's poses (what :meth:`Engine.kinetic_energy` gives the verdicts)."""

    rigid: np.ndarray
    armature: np.ndarray


@dataclass(frozen=True)
class VerdictPoses:
    """The first :data:`VERDICT_POSES` poses of a run and each engine's energies there, as the run computed them.

    The verdicts of three engines or more compare these energies: the run's own, not computed again.

    Attributes
    ----------
    qpos, qvel : ndarray, shape (P, nq) and (P, nv)
    energies : dict of str to RunEnergies
        Per engine run on every pose.
    """

    qpos: np.ndarray
    qvel: np.ndarray
    energies: dict[str, RunEnergies]

    @classmethod
    def of_runs(cls, poses: PoseSet, runs: dict[str, EngineRun], n: int) -> VerdictPoses:
        """The first ``n`` poses of a chunk and its engines' energies on them."""
        return cls(
            poses.qpos[:n],
            poses.qvel[:n],
            {name: RunEnergies(run.rigid[:n], run.armature[:n]) for name, run in runs.items()},
        )

    @classmethod
    def concat(cls, parts: list[VerdictPoses]) -> VerdictPoses | None:
        """The parts of several chunks, in pose order (None without any)."""
        if not parts:
            return None
        if len(parts) == 1:
            return parts[0]
        energies = {
            name: RunEnergies(
                np.concatenate([p.energies[name].rigid for p in parts]),
                np.concatenate([p.energies[name].armature for p in parts]),
            )
            for name in parts[0].energies
        }
        return cls(np.concatenate([p.qpos for p in parts]), np.concatenate([p.qvel for p in parts]), energies)
