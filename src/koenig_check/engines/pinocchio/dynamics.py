"""Pinocchio's dynamics in canonical coordinates: kinetic energy, mass matrix, inverse dynamics, armature parts.

What Pinocchio 4.1 includes (verified, see ``self_consistency``): ``computeKineticEnergy`` and ``crba`` both
include ``model.armature`` (diagonal), ``rnea`` adds ``armature * a``; ``rotorInertia``/``rotorGearRatio`` are
used by none of them.  ``crba`` fills the upper triangle only; it is symmetrized here.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from koenig_check.engines.base import as_batches
from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.pinocchio.state_map import StateMap


class PinocchioDynamics:
    """The dynamics methods of :class:`~koenig_check.engines.pinocchio.adapter.PinocchioEngine`.

    Each method's contract (parameters, shapes, returns) is :class:`~koenig_check.engines.base.Engine`'s.

    Attributes
    ----------
    model : pinocchio.Model
    state_map : StateMap
        Canonical <-> Pinocchio conversion for this model.
    nq, nv : int
    """

    model: pin.Model
    state_map: StateMap
    nq: int
    nv: int
    _data: pin.Data
    _m_rigid: pin.Model  # the model with armature zero
    _d_rigid: pin.Data
    _m_dyn: pin.Model  # the model with gravity zero
    _d_dyn: pin.Data

    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return ``computeKineticEnergy`` with and without armature, and the armature term."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        P = q.shape[0]
        reported, rigid = np.empty(P), np.empty(P)
        for p in range(P):
            reported[p] = pin.computeKineticEnergy(self.model, self._data, q[p], v[p])
            rigid[p] = pin.computeKineticEnergy(self._m_rigid, self._d_rigid, q[p], v[p])
        return EnergyParts(rigid=rigid, armature=0.5 * (v**2) @ np.asarray(self.model.armature), reported=reported)

    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``crba`` (armature included), symmetrized, in canonical velocity coordinates."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.to_pinocchio(qpos)
        M = np.empty((q.shape[0], self.nv, self.nv))
        for p in range(q.shape[0]):
            upper = np.triu(pin.crba(self.model, self._data, q[p]))
            M[p] = upper + np.triu(upper, 1).T
        return self.state_map.matrix_to_canonical(qpos, M)

    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return ``rnea`` with gravity zero, in canonical coordinates."""
        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        a = self.state_map.acceleration_to_pinocchio(qpos, qvel, qacc)
        tau = np.empty_like(v)
        for p in range(q.shape[0]):
            tau[p] = pin.rnea(self._m_dyn, self._d_dyn, q[p], v[p], a[p])
        return self.state_map.force_to_canonical(qpos, tau)

    def armature_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return the armature part of :meth:`mass_matrix` (P, nv, nv), canonical coordinates.

        ``Tᵀ diag(armature) T`` with ``v = T q̇`` the state map's velocity matrix.
        """
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        arm = np.diag(np.asarray(self.model.armature, dtype=float))
        return self.state_map.matrix_to_canonical(qpos, np.broadcast_to(arm, (qpos.shape[0], *arm.shape)))

    def armature_forces(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return the armature part of :meth:`inverse_dynamics` (P, nv), canonical coordinates.

        ``Tᵀ (armature ⊙ a)`` with ``a`` Pinocchio's acceleration.
        """
        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        a = self.state_map.acceleration_to_pinocchio(qpos, qvel, qacc)
        return self.state_map.force_to_canonical(qpos, a * np.asarray(self.model.armature, dtype=float))
