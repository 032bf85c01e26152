"""Koenig's formula, eq. (1) of the paper, in its two readings."""

from __future__ import annotations

import numpy as np

from koenig_check.formulas import terms
from koenig_check.formulas.cache import per_model
from koenig_check.formulas.exact import translational
from koenig_check.kernels import scale
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
    moments, axes = per_model("principal_axes", (states.inertia_body,), lambda: principal_axes(states.inertia_body))
    R, w = terms.rotation_components(states), terms.omega_components(states)
    w_body = np.empty((3, *w.shape[1:]))
    for i in range(3):  # Rᵀ ω
        terms.dot3(R[i], R[3 + i], R[6 + i], w[0], w[1], w[2], out=w_body[i])
    rot = np.zeros(w.shape[1:])
    w_k, tmp = np.empty(rot.shape), np.empty(rot.shape)
    for k in range(3):  # ω along the principal axis k, then ω_k² J_k
        scale(w_body[0], axes[:, 0, k], out=w_k)
        w_k += scale(w_body[1], axes[:, 1, k], out=tmp)
        w_k += scale(w_body[2], axes[:, 2, k], out=tmp)
        np.multiply(w_k, w_k, out=w_k)
        rot += scale(w_k, moments[:, k], out=w_k)
    rot *= 0.5
    return np.add(translational(states), rot, out=rot)
