"""What one engine says about gravity on a batch of poses: its vector, ``g(q)`` and ``V(q) - V(q_ref)``."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from koenig_check.engines.base import Engine


@dataclass(frozen=True)
class GravityReading:
    """One engine's gravity terms at the run's poses, in canonical coordinates.

    Attributes
    ----------
    engine : str
    vector : ndarray, shape (3,)
        The gravity the engine applies (zero when it honours a disable flag).
    g : ndarray, shape (P, nv)
        The generalized force to apply to hold each pose still.
    dv_gravity : ndarray, shape (P,)
        ``V(q) - V(q_ref)`` of gravity alone: each engine's constant cancels.
    dv_springs : ndarray, shape (P,)
        The same for the springs the engine counts (zero where it counts none).
    v_gravity : ndarray, shape (P,)
        ``V(q)`` of gravity as the engine computes it, constant included (shown, never compared).
    """

    engine: str
    vector: np.ndarray
    g: np.ndarray
    dv_gravity: np.ndarray
    dv_springs: np.ndarray
    v_gravity: np.ndarray


def read_gravity(engine: Engine, qpos: np.ndarray, qref: np.ndarray) -> GravityReading:
    """Ask one engine for its gravity terms at ``qpos``, potential energies against ``qref``.

    Parameters
    ----------
    engine : Engine
    qpos : ndarray, shape (P, nq)
        Canonical positions.
    qref : ndarray, shape (nq,)
        The canonical reference configuration (MuJoCo's ``qpos0``).

    Returns
    -------
    GravityReading

    Raises
    ------
    NotImplementedError
        The engine does not report its gravity terms.
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    both = np.vstack([qpos, np.asarray(qref, dtype=float)[None]])
    vector = np.asarray(engine.gravity_vector(), dtype=float)
    g = np.asarray(engine.generalized_gravity(qpos), dtype=float)
    v = engine.potential_energy(both)
    gravity, springs = np.asarray(v.gravity, dtype=float), np.asarray(v.springs, dtype=float)
    return GravityReading(
        engine.engine, vector, g, gravity[:-1] - gravity[-1], springs[:-1] - springs[-1], gravity[:-1]
    )
