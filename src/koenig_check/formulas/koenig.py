"""Koenig's formula, eq. (1) of the paper, in its two readings."""

from __future__ import annotations

import numpy as np

from koenig_check.formulas import terms
from koenig_check.formulas.exact import translational
from koenig_check.segments import SegmentStates


def koenig_world(states: SegmentStates) -> np.ndarray:
    """Eq. (1) read literally: world axes through C, current pose, no products of inertia.

    ``E = ½ m v_C² + ½ (ω_x² J_C^x + ω_y² J_C^y + ω_z² J_C^z)`` where ``ω_i`` are the
    world components of the angular velocity and ``J_C^i`` the axial moments of
    inertia about world-parallel axes through the centre of mass at the current
    pose (the diagonal of ``R I_body R^T``).  The products of inertia are dropped,
    which is what the paper reads eq. (1) to say.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B)
    """
    return translational(states) + 0.5 * terms.axial_part_world(states)


def principal_axes(inertia_body: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return principal moments and axes of body-frame inertia tensors.

    Parameters
    ----------
    inertia_body : ndarray, shape (B, 3, 3)

    Returns
    -------
    moments : ndarray, shape (B, 3)
        Principal central moments, ascending.
    axes : ndarray, shape (B, 3, 3)
        Columns are the principal directions in segment axes.
    """
    return np.linalg.eigh(inertia_body)


def koenig_principal(states: SegmentStates) -> np.ndarray:
    """Eq. (1) in principal central axes with the body-frame angular velocity (textbook form).

    ``E = ½ m v_C² + ½ (ω_1² J_1 + ω_2² J_2 + ω_3² J_3)`` with ``J_k`` the principal
    central moments and ``ω_k`` the components of the angular velocity along the
    principal axes of the body at the current pose.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B)
    """
    moments, axes = principal_axes(states.inertia_body)
    R, w = terms.rotation_components(states), terms.omega_components(states)
    w_body = [R[i] * w[0] + R[3 + i] * w[1] + R[6 + i] * w[2] for i in range(3)]  # Rᵀ ω
    rot = 0.0
    for k in range(3):
        w_k = axes[:, 0, k] * w_body[0] + axes[:, 1, k] * w_body[1] + axes[:, 2, k] * w_body[2]
        rot = rot + w_k * w_k * moments[:, k]
    return translational(states) + 0.5 * rot
