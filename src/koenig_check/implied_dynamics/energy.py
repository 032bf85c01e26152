"""A formula's kinetic energy as a function of canonical state, and what polarization gets out of it.

Every formula under test maps segment states to per-segment energies; evaluated on the states an
engine produces for ``(q, q̇)`` it becomes a function ``T(q, q̇)`` of the canonical state.  Every
formula here is a quadratic form in ``q̇`` (segment velocities are linear in ``q̇``), so

* the mass matrix it implies, ``M_ij = ∂²T/∂q̇_i∂q̇_j``, follows exactly (up to rounding) by
  polarization: ``M_ii = 2 T(e_i)``, ``M_ij = T(e_i + e_j) − T(e_i) − T(e_j)``;
* its generalized momentum ``p = ∂T/∂q̇`` follows exactly by a symmetric difference,
  ``p_j = (T(q̇ + s e_j) − T(q̇ − s e_j)) / 2s`` for any ``s`` (the quadratic has no third
  derivative).

A formula whose energy depends on the path (the paper's recipe with angles integrated along a
trajectory) is not a function of the state: :class:`PathDependentError` says so.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from koenig_check.exceptions import PathDependentError
from koenig_check.formulas import FORMULAS


@dataclass(frozen=True)
class FormulaEnergy:
    """The total kinetic energy a formula gives on one engine's segment states.

    Parameters
    ----------
    formula : str
        A name of :data:`koenig_check.formulas.FORMULAS`.
    engine : object
        An engine adapter (``pair.mujoco`` or ``pair.pinocchio``) with ``segment_states``.

    Raises
    ------
    KeyError
        For an unknown formula.
    PathDependentError
        For a formula that needs the path (``needs_path``): its energy, hence its mass matrix and
        Lagrange's equations, are not defined by the state alone.
    """

    formula: str
    engine: Any

    def __post_init__(self) -> None:
        if self.formula not in FORMULAS:
            raise KeyError(f"unknown formula {self.formula!r}; known: {list(FORMULAS)}")
        if FORMULAS[self.formula].needs_path:
            raise PathDependentError(
                f"{self.formula}: its energy depends on the path (angles integrated along a trajectory), not on "
                "the state (q, q̇), so M(q) = ∂²T/∂q̇² and Lagrange's equations are not defined for it"
            )

    @property
    def nv(self) -> int:
        """Number of canonical velocity coordinates."""
        return int(self.engine.nv)

    def __call__(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """Return ``T(q, q̇)``, shape (N,), for canonical states ``qpos`` (N, nq), ``qvel`` (N, nv)."""
        states = self.engine.segment_states(qpos, qvel)
        return np.asarray(FORMULAS[self.formula](states), dtype=float).sum(axis=1)


def polarization_pairs(nv: int) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs ``(i, j)``, ``i <= j``, and the unit-velocity combinations polarization evaluates.

    Parameters
    ----------
    nv : int

    Returns
    -------
    pairs : ndarray, shape (K, 2)
        ``K = nv (nv + 1) / 2`` pairs, the diagonal first.
    velocities : ndarray, shape (K, nv)
        ``e_i`` for the diagonal pairs, ``e_i + e_j`` for the others.
    """
    diag = np.stack([np.arange(nv), np.arange(nv)], axis=1)
    iu, ju = np.triu_indices(nv, k=1)
    pairs = np.concatenate([diag, np.stack([iu, ju], axis=1)]).astype(int)
    velocities = np.zeros((len(pairs), nv))
    velocities[np.arange(len(pairs)), pairs[:, 0]] = 1.0
    velocities[np.arange(len(pairs)), pairs[:, 1]] = 1.0
    return pairs, velocities


def implied_mass_matrix(energy: FormulaEnergy, qpos: np.ndarray) -> np.ndarray:
    """The mass matrix a formula implies, ``∂²T/∂q̇²``, by polarization of energy evaluations.

    Parameters
    ----------
    energy : FormulaEnergy
    qpos : ndarray, shape (P, nq)
        Canonical configurations.

    Returns
    -------
    ndarray, shape (P, nv, nv)
        Symmetric; armature is not part of any formula, so none is in it.
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    P, nv = qpos.shape[0], energy.nv
    pairs, unit = polarization_pairs(nv)
    K = len(pairs)
    T = energy(np.repeat(qpos, K, axis=0), np.tile(unit, (P, 1))).reshape(P, K)
    diag = T[:, :nv]  # T(e_i)
    M = np.zeros((P, nv, nv))
    M[:, np.arange(nv), np.arange(nv)] = 2.0 * diag
    i, j = pairs[nv:, 0], pairs[nv:, 1]
    off = T[:, nv:] - diag[:, i] - diag[:, j]
    M[:, i, j] = off
    M[:, j, i] = off
    return M


def implied_momentum(energy: FormulaEnergy, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """The generalized momentum ``p = ∂T/∂q̇`` a formula implies, by symmetric differences in ``q̇``.

    Exact up to rounding for an energy quadratic in ``q̇``; the step ``s`` is the largest velocity
    component of the pose (at least 1), so the differenced energies are of the size of ``T``.

    Parameters
    ----------
    energy : FormulaEnergy
    qpos : ndarray, shape (N, nq)
    qvel : ndarray, shape (N, nv)

    Returns
    -------
    ndarray, shape (N, nv)
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    qvel = np.atleast_2d(np.asarray(qvel, dtype=float))
    N, nv = qvel.shape
    s = np.maximum(np.abs(qvel).max(axis=1), 1.0)  # (N,)
    steps = s[:, None, None] * np.eye(nv)[None]  # (N, nv, nv)
    plus = (qvel[:, None, :] + steps).reshape(-1, nv)
    minus = (qvel[:, None, :] - steps).reshape(-1, nv)
    q = np.repeat(qpos, nv, axis=0)
    T = energy(np.concatenate([q, q]), np.concatenate([plus, minus])).reshape(2, N, nv)
    return (T[0] - T[1]) / (2.0 * s[:, None])
