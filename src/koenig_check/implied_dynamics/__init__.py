"""Dynamics implied by kinetic-energy formulas: mass matrix and generalized inertia forces, against both engines.

For each energy formula ``T(q, q̇)``: ``M = ∂²T/∂q̇²`` by polarization
(:mod:`~koenig_check.implied_dynamics.energy`), ``Q* = −(d/dt ∂T/∂q̇ − ∂T/∂q)`` by Lagrange's equations
(:mod:`~koenig_check.implied_dynamics.lagrange`), compared with each engine's mass matrix and inverse
dynamics with the armature taken out (:mod:`~koenig_check.implied_dynamics.reference`).

(The package is not called ``dynamics``: the function :func:`koenig_check.dynamics` would be shadowed
by a submodule of that name.)
"""

from __future__ import annotations

from koenig_check.implied_dynamics.energy import (
    FormulaEnergy,
    PathDependentError,
    implied_mass_matrix,
    implied_momentum,
)
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix

__all__ = [
    "FormulaEnergy",
    "PathDependentError",
    "implied_mass_matrix",
    "implied_momentum",
    "rigid_inertia_forces",
    "rigid_mass_matrix",
]
