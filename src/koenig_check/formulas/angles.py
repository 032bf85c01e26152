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

from koenig_check.formulas.cache import States, memo, memo_of
from koenig_check.formulas.terms import delta_rotation_components
from koenig_check.kernels import components, times_transpose

Convention = Literal["rotvec", "euler_xyz", "integrated"]
CONVENTIONS: tuple[Convention, ...] = ("rotvec", "euler_xyz", "integrated")


def delta_rotation(states: States) -> np.ndarray:
    """Return the rotation from the reference to the current pose, ``ΔR = R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3, 3)
    """
    return memo(states, "delta_rotation", lambda: times_transpose(states.rotation, states.rotation_ref[None]))


def quaternion_of(R: np.ndarray) -> np.ndarray:
    """Unit quaternions ``(x, y, z, w)`` with ``w >= 0`` of rotation matrices (Shepperd's method).

    For each matrix the largest of ``1 + tr R`` and ``1 + 2 R_kk − tr R`` selects a numerically
    stable formula, as in ``scipy.spatial.transform.Rotation.from_matrix`` (same numbers to rounding).

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 4)
    """
    R = np.asarray(R, dtype=float)
    r = R.reshape(-1, 9)
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = r.T
    tr = r00 + r11 + r22
    # The four candidates (x, y, z, w) of Shepperd's method, computed for every matrix, then one is picked.
    cand = np.stack(
        [
            np.stack([1.0 - tr + 2.0 * r00, r10 + r01, r20 + r02, r21 - r12], axis=-1),
            np.stack([r01 + r10, 1.0 - tr + 2.0 * r11, r21 + r12, r02 - r20], axis=-1),
            np.stack([r02 + r20, r12 + r21, 1.0 - tr + 2.0 * r22, r10 - r01], axis=-1),
            np.stack([r21 - r12, r02 - r20, r10 - r01, 1.0 + tr], axis=-1),
        ],
        axis=1,
    )
    choice = np.argmax(np.stack([r00, r11, r22, tr], axis=-1), axis=-1)
    q = cand[np.arange(r.shape[0]), choice]
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    q *= np.where(q[:, 3:] < 0, -1.0, 1.0)
    return q.reshape(*R.shape[:-2], 4)


def rotvec_of(R: np.ndarray) -> np.ndarray:
    """Rotation vectors of rotation matrices (angle in [0, π] times the unit axis).

    From the skew part ``(R − Rᵀ)/2 = sin θ [u]×`` and the trace, ``θ = atan2(sin θ, cos θ)``;
    where ``sin θ`` is small and ``θ`` near π (the skew part loses the axis), from the unit
    quaternion (:func:`quaternion_of`), as ``scipy``'s ``as_rotvec``.

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3)
    """
    R = np.asarray(R, dtype=float)
    out = rotvec_components(components(R.reshape(*R.shape[:-2], 9)))
    return np.moveaxis(out, 0, -1)


def rotvec_components(r: np.ndarray) -> np.ndarray:
    """:func:`rotvec_of` on component planes: row-major entries (9, ...) → rotation vectors (3, ...).

    Parameters
    ----------
    r : ndarray, shape (9, ...)

    Returns
    -------
    ndarray, shape (3, ...)
    """
    if r.ndim == 1:  # one matrix: as a batch of one (the in-place arithmetic below needs arrays, not scalars)
        return rotvec_components(r[:, None])[:, 0]
    out = np.empty((3, *r.shape[1:]))  # 2 sin θ u, scaled in place below
    np.subtract(r[7], r[5], out=out[0])
    np.subtract(r[2], r[6], out=out[1])
    np.subtract(r[3], r[1], out=out[2])
    two_sin = out[0] * out[0]
    tmp = out[1] * out[1]
    two_sin += tmp
    np.multiply(out[2], out[2], out=tmp)
    two_sin += tmp
    np.sqrt(two_sin, out=two_sin)
    cos = r[0] + r[4]
    cos += r[8]
    cos -= 1.0
    cos *= 0.5
    np.multiply(0.5, two_sin, out=tmp)
    angle = np.arctan2(tmp, cos)
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = np.divide(angle, two_sin, out=tmp)  # θ / (2 sin θ)
    small = angle <= 1e-3
    if small.any():  # its series where sin θ is small (the quotient loses digits or divides by zero)
        a2 = angle[small] ** 2
        scale[small] = 0.5 + a2 / 12.0 + 7.0 * a2**2 / 720.0
    out *= scale
    hard = (two_sin < 0.2) & (cos < 0)  # θ within ~6° of π
    if hard.any():
        q = quaternion_of(np.moveaxis(r[:, hard], 0, -1).reshape(-1, 3, 3))
        v, w = q[:, :3], q[:, 3]
        half = np.arctan2(np.linalg.norm(v, axis=-1), w)
        out[:, hard] = ((2.0 * half / np.sin(half))[:, None] * v).T
    return out


def euler_xyz_of(R: np.ndarray) -> np.ndarray:
    """Extrinsic x-y-z angles ``(a, b, c)`` with ``R = R_z(c) R_y(b) R_x(a)``, ``b`` in [−π/2, π/2].

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3)
        At gimbal lock (``|b| = π/2``) the split between ``a`` and ``c`` is not unique; ``c`` is
        set to 0 there.
    """
    R = np.asarray(R, dtype=float)
    return np.moveaxis(euler_xyz_components(components(R.reshape(*R.shape[:-2], 9))), 0, -1)


def euler_xyz_components(r: np.ndarray) -> np.ndarray:
    """:func:`euler_xyz_of` on component planes: row-major entries (9, ...) → ``(a, b, c)`` (3, ...).

    Parameters
    ----------
    r : ndarray, shape (9, ...)

    Returns
    -------
    ndarray, shape (3, ...)
    """
    if r.ndim == 1:  # one matrix: as a batch of one (the in-place arithmetic below needs arrays, not scalars)
        return euler_xyz_components(r[:, None])[:, 0]
    out = np.empty((3, *r.shape[1:]))
    a, b, c = out
    h = np.hypot(r[0], r[3])
    np.arctan2(np.negative(r[6], out=b), h, out=b)
    np.arctan2(r[7], r[8], out=a)
    np.arctan2(r[3], r[0], out=c)
    lock = h < 1e-12
    if np.any(lock):  # only a - c (b > 0) or a + c (b < 0) is defined: keep c = 0
        a[lock] = np.arctan2(-r[5][lock], r[4][lock])
        c[lock] = 0.0
    return out


def euler_xyz_double_angles(r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(sin 2Δθ, cos 2Δθ)`` of the :func:`euler_xyz_components` angles, from the entries alone.

    Each angle is ``φ = atan2(y, x)`` of two entries (as :func:`euler_xyz_components` reads them:
    ``a`` of ``(r₈, r₇)``, ``b`` of ``(h, −r₆)`` with ``h = √(r₀² + r₃²)``, ``c`` of ``(r₀, r₃)``; at
    gimbal lock, ``h < 10⁻¹²``, ``a`` of ``(r₄, −r₅)`` and ``c = 0``), so that
    ``sin 2φ = 2xy / (x² + y²)`` and ``cos 2φ = (x² − y²) / (x² + y²)``: no ``arctan2``, ``hypot``
    or ``tan`` (the same numbers as :func:`~koenig_check.formulas.alyushin.double_angle_trig` of the
    angles, to rounding).  Where ``x = y = 0`` (``atan2`` gives 0): ``(0, 1)``.

    Parameters
    ----------
    r : ndarray, shape (9, ...)
        Row-major entries of rotation matrices.

    Returns
    -------
    (ndarray, ndarray), each shape (3, ...)
        For ``(a, b, c)``.
    """
    if r.ndim == 1:  # one matrix: as a batch of one
        sin2, cos2 = euler_xyz_double_angles(r[:, None])
        return sin2[:, 0], cos2[:, 0]
    shape = r.shape[1:]
    sin2, cos2 = np.empty((3, *shape)), np.empty((3, *shape))
    xx, yy, h2 = np.empty(shape), np.empty(shape), np.empty(shape)
    np.multiply(r[0], r[0], out=xx)
    np.multiply(r[3], r[3], out=yy)
    np.add(xx, yy, out=h2)  # h², the denominator of c
    _double_angle(r[0], r[3], xx, yy, h2, sin2[2], cos2[2])
    h = np.sqrt(h2)
    np.multiply(r[6], r[6], out=yy)
    n = np.add(h2, yy, out=xx)
    _double_angle(h, r[6], h2, yy, n, sin2[1], cos2[1])
    np.negative(sin2[1], out=sin2[1])  # y = −r₆
    np.multiply(r[8], r[8], out=xx)
    np.multiply(r[7], r[7], out=yy)
    _double_angle(r[8], r[7], xx, yy, np.add(xx, yy, out=h2), sin2[0], cos2[0])
    lock = h < 1e-12
    if lock.any():  # a of (r₄, −r₅), c = 0
        x, y = r[4][lock], -r[5][lock]
        xx_l, yy_l = x * x, y * y
        sin_l, cos_l = np.empty(x.shape), np.empty(x.shape)
        _double_angle(x, y, xx_l, yy_l, xx_l + yy_l, sin_l, cos_l)
        sin2[0][lock], cos2[0][lock] = sin_l, cos_l
        sin2[2][lock], cos2[2][lock] = 0.0, 1.0
    return sin2, cos2


def _double_angle(
    x: np.ndarray, y: np.ndarray, xx: np.ndarray, yy: np.ndarray, n: np.ndarray, sin2: np.ndarray, cos2: np.ndarray
) -> None:
    """``sin 2φ = 2xy / n``, ``cos 2φ = (x² − y²) / n`` into ``sin2``, ``cos2``, given ``x²``, ``y²``, ``n = x² + y²``.

    Where ``n = 0`` (``x = y = 0``, ``atan2`` gives 0): ``(0, 1)``; a NaN stays a NaN.
    """
    zero = n == 0
    with np.errstate(divide="ignore", invalid="ignore"):
        np.multiply(x, y, out=sin2)
        sin2 *= 2.0
        sin2 /= n
        np.subtract(xx, yy, out=cos2)
        cos2 /= n
    if zero.any():
        sin2[zero], cos2[zero] = 0.0, 1.0


def rotvec_angles(states: States) -> np.ndarray:
    """Δθ as the world-axis components of the rotation vector of ``R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3)
    """
    return np.moveaxis(angle_components(states, "rotvec"), 0, -1)


def euler_xyz_angles(states: States) -> np.ndarray:
    """Δθ as extrinsic x-y-z Euler angles of ``R R_ref^T``.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B, 3)
        ``(a, b, c)`` with ``ΔR = R_z(c) R_y(b) R_x(a)``.
    """
    return np.moveaxis(angle_components(states, "euler_xyz"), 0, -1)


def angle_components(states: States, convention: Convention, angles: np.ndarray | None = None) -> np.ndarray:
    """:func:`paper_angles` as component planes (3, P, B), computed once per shared state set.

    Parameters
    ----------
    states : SegmentStates
    convention : {"rotvec", "euler_xyz", "integrated"}
    angles : ndarray, shape (P, B, 3), optional
        Required for, and only for, ``integrated``.

    Returns
    -------
    ndarray, shape (3, P, B)
    """
    if convention == "rotvec" and angles is None:
        return memo(states, "rotvec_c", lambda: rotvec_components(delta_rotation_components(states)))
    if convention == "euler_xyz" and angles is None:
        return memo(states, "euler_xyz_c", lambda: euler_xyz_components(delta_rotation_components(states)))
    dtheta = paper_angles(states, convention, angles)
    return memo_of(states, f"angles_c:{convention}:given", angles, lambda: components(dtheta))


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


def paper_angles(states: States, convention: Convention, angles: np.ndarray | None = None) -> np.ndarray:
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
