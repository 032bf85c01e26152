"""The gravity part of the :class:`~koenig_check.engines.base.Engine` interface: what an engine read and computes.

Three questions, asked of every engine in canonical (MuJoCo-layout) coordinates:

- :meth:`GravityTerms.gravity_vector`: the gravity the engine read from the file (zero when it honours a flag that
  disables gravity);
- :meth:`GravityTerms.generalized_gravity`: ``g(q)``, the generalized force that must be *applied* to hold the
  system still (MuJoCo's ``qfrc_bias`` at zero velocity, Pinocchio's ``computeGeneralizedGravity``, minus Drake's
  ``CalcGravityGeneralizedForces``, which is the force gravity exerts);
- :meth:`GravityTerms.potential_energy`: ``V(q)`` split into its gravity part and its springs' part, each with the
  constant the engine chooses (only differences ``V(q) - V(q_ref)`` compare across engines).

An engine that cannot answer keeps the defaults, which raise :class:`NotImplementedError`; the gravity
comparison then leaves it out and says so.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PotentialParts:
    """Potential energy of ``P`` poses as an engine computes it, gravity and springs apart.

    Parameters
    ----------
    gravity : ndarray, shape (P,)
        ``-Σ m_b g·c_b`` up to the engine's constant.
    springs : ndarray, shape (P,)
        Joint and tendon spring energy the engine counts (zero for an engine without springs).
    """

    gravity: np.ndarray
    springs: np.ndarray


class GravityTerms:
    """The gravity methods of :class:`~koenig_check.engines.base.Engine` (defaults: not available)."""

    def gravity_vector(self) -> np.ndarray:
        """Return the gravity vector the engine applies, in its world frame (zero when disabled).

        Returns
        -------
        ndarray, shape (3,)
        """
        raise NotImplementedError(f"{type(self).__name__} does not report its gravity")

    def generalized_gravity(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``g(q)``: the generalized force to apply to hold each pose still, canonical coordinates.

        Springs, dampers and constraints are not part of it.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv)
        """
        raise NotImplementedError(f"{type(self).__name__} does not report its gravity forces")

    def potential_energy(self, qpos: np.ndarray) -> PotentialParts:
        """Return the potential energy of each pose, gravity and springs apart, up to the engine's constants.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        PotentialParts
        """
        raise NotImplementedError(f"{type(self).__name__} does not report its potential energy")
