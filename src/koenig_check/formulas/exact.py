"""The exact rigid-body kinetic energy, the reference every other formula is measured against."""

from __future__ import annotations

import numpy as np

from koenig_check.formulas import terms
from koenig_check.segments import SegmentStates


def translational(states: SegmentStates) -> np.ndarray:
    """Return the energy of the centre of mass, ``½ m v_C²``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B)
    """
    return terms.translational(states)


def exact(states: SegmentStates) -> np.ndarray:
    """Kinetic energy ``½ m v_C² + ½ ω·I_C ω`` with the full current inertia tensor.

    Evaluated in world axes, ``½ Σ_i I_ii ω_i² + Σ_{i<j} I_ij ω_i ω_j``, from the six world
    inertia components shared with the other formulas.  This is the textbook (König) decomposition
    about the centre of mass with the
    complete central inertia tensor ``I_C = R I_body R^T``, i.e. the encyclopedia's
    ``T = ½ M V·V + ½ ω·[I_R]ω`` (second seed).  It is what the paper's eq. (10)
    integrates to for a rigid body.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B)
        Per-segment energy; the total is the sum over the last axis.
    """
    inertia, prod = terms.inertia_world6(states), terms.omega_products(states)
    products = terms.dot3(prod[0], prod[1], prod[2], inertia[3], inertia[4], inertia[5])
    rot = np.multiply(0.5, terms.axial_part_world(states))
    rot += products
    return np.add(translational(states), rot, out=rot)
