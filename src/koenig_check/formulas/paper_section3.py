"""The paper's section-3 example: rotation about z (external) and x (internal), eqs. (39)-(41).

A body is a cloud of particles with Lagrange (initial) coordinates ``(α, β, γ)`` and
masses; the pole ``P = (α_P, β_P, γ_P)`` is fixed.  The functions broadcast over any
grid of angles and rates: an angle array of shape ``G`` gives results of shape
``G + (N, 3)`` for ``N`` particles.
"""

from __future__ import annotations

import numpy as np


def _split(lagrange: np.ndarray, pole: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rel = np.asarray(lagrange, dtype=float) - np.asarray(pole, dtype=float)
    return rel[..., 0], rel[..., 1], rel[..., 2]


def _grid(*values: np.ndarray) -> list[np.ndarray]:
    """Broadcast per-grid values against the particle axis."""
    return [np.asarray(v, dtype=float)[..., None] for v in values]


def coordinates_39(lagrange: np.ndarray, pole: np.ndarray, dtheta_z: np.ndarray, dtheta_x: np.ndarray) -> np.ndarray:
    """Current coordinates of every particle, eq. (39), as written.

    Parameters
    ----------
    lagrange : ndarray, shape (N, 3)
        Initial coordinates ``(α, β, γ)``.
    pole : ndarray, shape (3,)
        ``(α_P, β_P, γ_P)``.
    dtheta_z, dtheta_x : array_like, shape G
        Rotation angles about z (external) and x (internal).

    Returns
    -------
    ndarray, shape G + (N, 3)
    """
    a, b, g = _split(lagrange, pole)
    tz, tx = _grid(dtheta_z, dtheta_x)
    aP, bP, gP = np.asarray(pole, dtype=float)
    inner = b * np.cos(tx) - g * np.sin(tx)
    x = aP + a * np.cos(tz) - inner * np.sin(tz)
    y = bP + a * np.sin(tz) + inner * np.cos(tz)
    z = gP + b * np.sin(tx) + g * np.cos(tx)
    return np.stack(np.broadcast_arrays(x, y, z), axis=-1)


def velocities_40(
    lagrange: np.ndarray,
    pole: np.ndarray,
    dtheta_z: np.ndarray,
    dtheta_x: np.ndarray,
    rate_z: np.ndarray,
    rate_x: np.ndarray,
) -> np.ndarray:
    """Particle velocities of the joint motion in Lagrange variables, eq. (40), as written.

    Parameters
    ----------
    lagrange : ndarray, shape (N, 3)
    pole : ndarray, shape (3,)
    dtheta_z, dtheta_x : array_like, shape G
    rate_z, rate_x : array_like, shape G
        ``θ_z,t`` and ``θ_x,t``.

    Returns
    -------
    ndarray, shape G + (N, 3)
    """
    a, b, g = _split(lagrange, pole)
    tz, tx, wz, wx = _grid(dtheta_z, dtheta_x, rate_z, rate_x)
    inner = b * np.cos(tx) - g * np.sin(tx)
    lift = b * np.sin(tx) + g * np.cos(tx)
    xt = wz * (-a * np.sin(tz) - inner * np.cos(tz)) + wx * (lift * np.sin(tz))
    yt = wz * (a * np.cos(tz) - inner * np.sin(tz)) - wx * lift * np.cos(tz)
    zt = wx * inner
    return np.stack(np.broadcast_arrays(xt, yt, zt), axis=-1)


def integrand_41(
    lagrange: np.ndarray,
    pole: np.ndarray,
    dtheta_x: np.ndarray,
    rate_z: np.ndarray,
    rate_x: np.ndarray,
) -> np.ndarray:
    """The integrand ``x_t² + y_t² + z_t²`` of eq. (10) for this motion, eq. (41) as written.

    Parameters
    ----------
    lagrange : ndarray, shape (N, 3)
    pole : ndarray, shape (3,)
    dtheta_x : array_like, shape G
        Eq. (41) does not depend on ``Δθ_z``.
    rate_z, rate_x : array_like, shape G

    Returns
    -------
    ndarray, shape G + (N,)
    """
    a, b, g = _split(lagrange, pole)
    tx, wz, wx = _grid(dtheta_x, rate_z, rate_x)
    inner = b * np.cos(tx) - g * np.sin(tx)
    lift = b * np.sin(tx) + g * np.cos(tx)
    return wz**2 * a**2 + wz**2 * inner**2 + wx**2 * (b**2 + g**2) - 2 * wx * wz * a * lift


def concluding_energy(
    masses: np.ndarray, lagrange: np.ndarray, pole: np.ndarray, rate_z: np.ndarray, rate_x: np.ndarray
) -> np.ndarray:
    """The paper's concluding energy for this motion (section 4) about a fixed pole.

    ``E = ½ θ_z,t² J_P^z + ½ θ_x,t² J_P^x − θ_x,t θ_z,t I_xz`` (``v_P = 0``), with the axial
    moments (28) from the initial configuration (claimed invariant, eq. 29) and the
    centrifugal moment by eq. (33) with ``Δθ_y = 0``, i.e. the initial ``I_αγ``.  As
    prescribed, the result does not depend on the angles.

    Parameters
    ----------
    masses : ndarray, shape (N,)
    lagrange : ndarray, shape (N, 3)
    pole : ndarray, shape (3,)
    rate_z, rate_x : array_like, shape G

    Returns
    -------
    ndarray, shape G
    """
    a, b, g = _split(lagrange, pole)
    m = np.asarray(masses, dtype=float)
    J_z = np.sum(m * (a**2 + b**2))
    J_x = np.sum(m * (b**2 + g**2))
    I_xz = np.sum(m * a * g)
    wz = np.asarray(rate_z, dtype=float)
    wx = np.asarray(rate_x, dtype=float)
    return 0.5 * wz**2 * J_z + 0.5 * wx**2 * J_x - wx * wz * I_xz


def rotation_39(dtheta_z: np.ndarray, dtheta_x: np.ndarray) -> np.ndarray:
    """The rotation matrix of motion (39): ``R = R_z(Δθ_z) R_x(Δθ_x)``.

    Parameters
    ----------
    dtheta_z, dtheta_x : array_like, shape G

    Returns
    -------
    ndarray, shape G + (3, 3)
    """
    tz, tx = np.broadcast_arrays(np.asarray(dtheta_z, dtype=float), np.asarray(dtheta_x, dtype=float))
    cz, sz, cx, sx = np.cos(tz), np.sin(tz), np.cos(tx), np.sin(tx)
    one, zero = np.ones_like(tz), np.zeros_like(tz)
    Rz = np.stack([cz, -sz, zero, sz, cz, zero, zero, zero, one], axis=-1).reshape(*tz.shape, 3, 3)
    Rx = np.stack([one, zero, zero, zero, cx, -sx, zero, sx, cx], axis=-1).reshape(*tz.shape, 3, 3)
    return Rz @ Rx


def angular_velocity_39(dtheta_z: np.ndarray, rate_z: np.ndarray, rate_x: np.ndarray) -> np.ndarray:
    """World angular velocity of motion (39): ``θ_z,t e_z + θ_x,t R_z(Δθ_z) e_x``.

    Parameters
    ----------
    dtheta_z, rate_z, rate_x : array_like, shape G

    Returns
    -------
    ndarray, shape G + (3,)
    """
    tz, wz, wx = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (dtheta_z, rate_z, rate_x)))
    return np.stack([wx * np.cos(tz), wx * np.sin(tz), wz], axis=-1)
