"""Pinocchio's gravity terms: ``model.gravity``, ``computeGeneralizedGravity`` and ``computePotentialEnergy``.

Pinocchio's models carry no springs, so its potential energy is gravity's alone.  Its MJCF parser ignores
``<option>`` (gravity stays (0, 0, -9.81)); that is a catalogued cause, not something corrected here.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from koenig_check.engines.base import as_batches
from koenig_check.engines.pinocchio.state_map import StateMap
from koenig_check.engines.potential import PotentialParts


class PinocchioGravity:
    """The gravity methods of :class:`~koenig_check.engines.pinocchio.adapter.PinocchioEngine` (contract: Engine's)."""

    model: pin.Model
    state_map: StateMap
    nq: int
    nv: int
    _data: pin.Data

    def gravity_vector(self) -> np.ndarray:
        """Return ``model.gravity.linear``."""
        return np.array(self.model.gravity.linear, dtype=float)

    def generalized_gravity(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``computeGeneralizedGravity`` in canonical coordinates (the state map's force map)."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.to_pinocchio(qpos)
        tau = np.empty((q.shape[0], self.model.nv))
        for p in range(q.shape[0]):
            tau[p] = pin.computeGeneralizedGravity(self.model, self._data, q[p])
        return self.state_map.force_to_canonical(qpos, tau)

    def potential_energy(self, qpos: np.ndarray) -> PotentialParts:
        """Return ``computePotentialEnergy`` (gravity only: no springs in Pinocchio's models)."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.to_pinocchio(qpos)
        out = np.array([pin.computePotentialEnergy(self.model, self._data, q[p]) for p in range(q.shape[0])])
        return PotentialParts(gravity=out, springs=np.zeros_like(out))
