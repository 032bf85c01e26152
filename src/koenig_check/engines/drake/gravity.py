"""Drake's gravity terms: the plant's gravity field, ``CalcGravityGeneralizedForces`` and the potential energy.

The loader keeps the gravity Drake's parser read (``<option gravity>``; Drake ignores ``<flag gravity="disable"/>``
with a warning, a catalogued cause).  Drake's ``CalcGravityGeneralizedForces`` is the generalized force gravity
*exerts* on the system; ``g(q)`` here is what must be *applied* to hold it, so its sign is flipped.  The gravity
part of the potential energy is ``-m g·c`` with Drake's own total mass and centre of mass; the springs' part
is the rest of ``CalcPotentialEnergy`` (Drake's MJCF parser drops joint springs: usually zero).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from koenig_check.engines.base import as_batches
from koenig_check.engines.drake.failures import drake_failures_raised
from koenig_check.engines.drake.state_map import DrakeStateMap
from koenig_check.engines.potential import PotentialParts


class DrakeGravity:
    """The gravity methods of :class:`~koenig_check.engines.drake.adapter.DrakeEngine` (contract: ``Engine``'s)."""

    plant: Any
    state_map: DrakeStateMap
    nq: int
    nv: int
    _context: Any

    def gravity_vector(self) -> np.ndarray:
        """Return the plant's gravity field vector (as its parser read it)."""
        return np.array(self.plant.gravity_field().gravity_vector(), dtype=float)

    @drake_failures_raised
    def generalized_gravity(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``-CalcGravityGeneralizedForces`` (Drake's is the force on the system) in canonical coordinates."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.positions(qpos)
        tau = np.empty((q.shape[0], self.nv))
        for p in range(q.shape[0]):
            self.plant.SetPositions(self._context, q[p])
            tau[p] = -self.plant.CalcGravityGeneralizedForces(self._context)
        return self.state_map.force_to_canonical(qpos, tau)

    @drake_failures_raised
    def potential_energy(self, qpos: np.ndarray) -> PotentialParts:
        """Return ``-m g·c`` (Drake's mass and COM) and the rest of ``CalcPotentialEnergy`` as the springs' part."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.positions(qpos)
        g = self.gravity_vector()
        mass = self.plant.CalcTotalMass(self._context)
        grav, total = np.empty(q.shape[0]), np.empty(q.shape[0])
        for p in range(q.shape[0]):
            self.plant.SetPositions(self._context, q[p])
            grav[p] = -mass * float(g @ self.plant.CalcCenterOfMassPositionInWorld(self._context))
            total[p] = self.plant.CalcPotentialEnergy(self._context)
        return PotentialParts(gravity=grav, springs=total - grav)
