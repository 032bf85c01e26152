"""The exact rigid-body kinetic energy, the reference every other formula is measured against."""

from __future__ import annotations

import numpy as np

from koenig_check.formulas.cache import memo
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
    return memo(
        states,
        "translational",
        lambda: 0.5 * states.mass[None, :] * np.einsum("pbi,pbi->pb", states.v_com, states.v_com),
    )


def body_angular_velocity(states: SegmentStates) -> np.ndarray:
    """Return the angular velocity in segment axes, ``R^T ω``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3)
    """
    return memo(states, "body_omega", lambda: np.einsum("pbji,pbj->pbi", states.rotation, states.omega))


def exact(states: SegmentStates) -> np.ndarray:
    """Kinetic energy ``½ m v_C² + ½ ω·I_C ω`` with the full current inertia tensor.

    This is the textbook (König) decomposition about the centre of mass with the
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
    w_body = body_angular_velocity(states)
    I_w = (states.inertia_body[None] @ w_body[..., None])[..., 0]
    rot = 0.5 * np.einsum("pbi,pbi->pb", w_body, I_w)
    return translational(states) + rot
