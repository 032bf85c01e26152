"""The rotation angles Δθx, Δθy, Δθz of the paper's eq. (33)/(36), under explicit conventions.

The paper defines Δθ_i only for a rotation about a single axis (eqs. 3-6).  For a
general rotation it gives no definition, so every reading is a named convention:

``rotvec``
    the components of the rotation vector of ``ΔR = R R_ref^T`` (world axes);
``euler_xyz``
    extrinsic angles about world x, then y, then z: ``ΔR = R_z(c) R_y(b) R_x(a)``,
    returned as ``(a, b, c)``;
``integrated``
    the time integrals of the world angular-velocity components along a path,
    supplied by the caller (see :func:`integrate_angular_velocity`).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.segments import SegmentStates

Convention = Literal["rotvec", "euler_xyz", "integrated"]
CONVENTIONS: tuple[str, ...] = ("rotvec", "euler_xyz", "integrated")


def delta_rotation(states: SegmentStates) -> np.ndarray:
    """Return the rotation from the reference to the current pose, ``ΔR = R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3, 3)
    """
    return states.rotation @ np.swapaxes(states.rotation_ref, -1, -2)[None]


def _as_rotation(matrices: np.ndarray) -> Rotation:
    return Rotation.from_matrix(matrices.reshape(-1, 3, 3))


def rotvec_angles(states: SegmentStates) -> np.ndarray:
    """Δθ as the world-axis components of the rotation vector of ``R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3)
    """
    dR = delta_rotation(states)
    return _as_rotation(dR).as_rotvec().reshape(dR.shape[:-1])


def euler_xyz_angles(states: SegmentStates) -> np.ndarray:
    """Δθ as extrinsic x-y-z Euler angles of ``R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3)
        ``(a, b, c)`` with ``ΔR = R_z(c) R_y(b) R_x(a)``.
    """
    dR = delta_rotation(states)
    return _as_rotation(dR).as_euler("xyz").reshape(dR.shape[:-1])


def integrate_angular_velocity(omega: np.ndarray, times: np.ndarray) -> np.ndarray:
    """Time integral of the world angular-velocity components along a path (trapezoid rule).

    Parameters
    ----------
    omega : ndarray, shape (T, B, 3)
        World angular velocity at each sample of the path.
    times : ndarray, shape (T,)
        Strictly increasing sample times; the integral starts at ``times[0]``.

    Returns
    -------
    ndarray, shape (T, B, 3)
        ``∫ ω_i dt`` from the first sample, zero at the first sample.
    """
    omega = np.asarray(omega, dtype=float)
    times = np.asarray(times, dtype=float)
    if times.ndim != 1 or omega.shape[0] != times.shape[0]:
        raise ValueError(f"times shape {times.shape} does not match omega shape {omega.shape}")
    dt = np.diff(times)
    if np.any(dt <= 0):
        raise ValueError("times must be strictly increasing")
    steps = 0.5 * (omega[1:] + omega[:-1]) * dt[:, None, None]
    return np.concatenate([np.zeros_like(omega[:1]), np.cumsum(steps, axis=0)], axis=0)


def paper_angles(states: SegmentStates, convention: Convention, angles: np.ndarray | None = None) -> np.ndarray:
    """Return Δθ (P, B, 3) for a convention, validating a caller-supplied path integral.

    Parameters
    ----------
    states : SegmentStates
    convention : {"rotvec", "euler_xyz", "integrated"}
    angles : ndarray, shape (P, B, 3), optional
        Required for, and only for, ``integrated``.

    Returns
    -------
    ndarray, shape (P, B, 3)
    """
    if convention == "integrated":
        if angles is None:
            raise ValueError(
                "convention 'integrated' needs the path integrals of ω: pass angles=(P, B, 3) "
                "(see integrate_angular_velocity)"
            )
        angles = np.asarray(angles, dtype=float)
        expected = (states.n_poses, states.n_segments, 3)
        if angles.shape != expected:
            raise ValueError(f"angles: shape {angles.shape}, expected {expected}")
        if not np.all(np.isfinite(angles)):
            raise ValueError("angles: non-finite values")
        return angles
    if angles is not None:
        raise ValueError(f"angles are only used by convention 'integrated', not {convention!r}")
    if convention == "rotvec":
        return rotvec_angles(states)
    if convention == "euler_xyz":
        return euler_xyz_angles(states)
    raise ValueError(f"unknown angle convention {convention!r}; choose one of {CONVENTIONS}")
