"""The paper's corrected formulas: eq. (30)/(34) with the translational terms of (37)/(38).

Notation (the paper's): axial moments ``J^x, J^y, J^z`` (eq. 28/35) are the diagonal of
the inertia tensor in world-parallel axes; centrifugal moments ``I_xy, I_yz, I_zx``
(eq. 27) are the *second-moment* products ``∫(x-x_P)(y-y_P) dm`` etc., i.e. the negated
off-diagonal entries of the inertia tensor.  ``θ_{i,t}`` are read as the world
components of the angular velocity (rotations about axes "parallel to the axes of the
observer's coordinate system", section 1).
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from koenig_check.formulas import terms
from koenig_check.formulas.angles import Convention, angle_components, euler_xyz_double_angles
from koenig_check.formulas.cache import memo, memo_of
from koenig_check.formulas.exact import translational
from koenig_check.formulas.terms import delta_rotation_components
from koenig_check.kernels import scale
from koenig_check.segments import SegmentStates, second_moments

Recipe = Literal["current", "paper"]
RECIPES: tuple[str, ...] = ("current", "paper")


def rotational_energy_30_planes(
    squares: np.ndarray, products: np.ndarray, axial: np.ndarray, centrifugal: np.ndarray
) -> np.ndarray:
    """The rotational part of eq. (30)/(34) on component planes, with ``θ_i²`` and ``θ_i θ_j`` given (shared).

    ``½(θ_z² J^z + θ_y² J^y + θ_x² J^x) − θ_y θ_z I_yz − θ_x θ_z I_xz − θ_y θ_x I_xy``.

    Parameters
    ----------
    squares : ndarray, shape (3, ...)
        ``(θ_x², θ_y², θ_z²)``.
    products : ndarray, shape (3, ...)
        ``(θ_y θ_z, θ_x θ_z, θ_y θ_x)``.
    axial : ndarray, shape (3, ...)
        ``(J^x, J^y, J^z)``, broadcast against the planes.
    centrifugal : ndarray, shape (3, ...)
        ``(I_yz, I_zx, I_xy)``, broadcast against the planes.

    Returns
    -------
    ndarray, shape (...)
    """
    shape = np.broadcast_shapes(squares.shape[1:], axial.shape[1:], products.shape[1:], centrifugal.shape[1:])
    out, tmp = np.empty(shape), np.empty(shape)
    for i in range(3):  # ½ Σ θ_i² J^i, the sum left to right
        _times(squares[i], axial[i], out=out if i == 0 else tmp)
        if i:
            out += tmp
    out *= 0.5
    for i in range(3):
        out -= _times(products[i], centrifugal[i], out=tmp)
    return out


def _times(planes: np.ndarray, factor: np.ndarray, out: np.ndarray) -> np.ndarray:
    """``planes * factor`` into ``out``: a per-segment factor (B,) through :func:`~koenig_check.kernels.scale`."""
    if factor.ndim == 1 and planes.ndim > 1:
        return scale(planes, factor, out=out)
    return np.multiply(planes, factor, out=out)


def centrifugal_update_33(
    S_ref: np.ndarray, dtheta: np.ndarray, trig: tuple[np.ndarray, np.ndarray] | None = None
) -> np.ndarray:
    """Centrifugal moments updated from the initial state by eq. (33)/(36).

    ``I_xy = ½ sin(2Δθ_z)(I_α − I_β) + cos(2Δθ_z) I_αβ``,
    ``I_yz = ½ sin(2Δθ_x)(I_β − I_γ) + cos(2Δθ_x) I_βγ``,
    ``I_zx = ½ sin(2Δθ_y)(I_γ − I_α) + cos(2Δθ_y) I_αγ``.

    Parameters
    ----------
    S_ref : ndarray, shape (B, 3, 3)
        Second moments at the initial configuration, eq. (32).
    dtheta : ndarray, shape (P, B, 3)
        ``(Δθ_x, Δθ_y, Δθ_z)``.
    trig : (ndarray, ndarray), optional
        ``(sin 2Δθ, cos 2Δθ)`` when already computed (shared by the formulas of one state set).

    Returns
    -------
    ndarray, shape (P, B, 3)
        ``(I_yz, I_zx, I_xy)``.
    """
    sin2, cos2 = trig if trig is not None else double_angle_trig(dtheta)
    out = centrifugal_update_33_planes(S_ref, np.moveaxis(sin2, -1, 0), np.moveaxis(cos2, -1, 0))
    return np.moveaxis(out, 0, -1)


def centrifugal_update_33_planes(S_ref: np.ndarray, sin2: np.ndarray, cos2: np.ndarray) -> np.ndarray:
    """:func:`centrifugal_update_33` on component planes: ``sin 2Δθ``, ``cos 2Δθ`` (3, P, B) → (3, P, B).

    Parameters
    ----------
    S_ref : ndarray, shape (B, 3, 3)
    sin2, cos2 : ndarray, shape (3, P, B)

    Returns
    -------
    ndarray, shape (3, P, B)
        ``(I_yz, I_zx, I_xy)``.
    """
    ia, ib, ig = S_ref[:, 0, 0], S_ref[:, 1, 1], S_ref[:, 2, 2]
    iab, ibg, iag = S_ref[:, 0, 1], S_ref[:, 1, 2], S_ref[:, 0, 2]
    out = np.empty(np.broadcast_shapes(sin2.shape, cos2.shape))
    tmp = np.empty(out.shape[1:])
    # (I_yz, I_zx, I_xy) = ½ sin 2Δθ_i (difference of planar moments) + cos 2Δθ_i (product moment), i = x, y, z
    for n, (diff, product) in enumerate(((ib - ig, ibg), (ig - ia, iag), (ia - ib, iab))):
        o = out[n, ...]
        np.multiply(0.5, sin2[n], out=o)
        _times(o, diff, out=o)
        o += _times(cos2[n], product, out=tmp)
    return out


def double_angle_trig(dtheta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(sin 2Δθ, cos 2Δθ)``, the trigonometric factors of eq. (33)/(36).

    From ``t = tan Δθ``: ``sin 2Δθ = 2t / (1 + t²)``, ``cos 2Δθ = (1 − t²) / (1 + t²)`` (the same
    numbers to rounding; numpy's float64 ``tan`` is about 20 times faster than its ``sin`` and
    ``cos`` here, and one call replaces two).  Both are π-periodic, like ``tan``; at
    ``Δθ = ±π/2`` the float ``tan`` is finite (about 1.6e16), giving ``(≈0, −1)``.

    Parameters
    ----------
    dtheta : ndarray, shape (..., 3)

    Returns
    -------
    (ndarray, ndarray)
    """
    t = np.tan(dtheta)
    t2 = t * t
    d = t2 + 1.0
    t *= 2.0
    t /= d  # sin 2Δθ
    np.subtract(1.0, t2, out=t2)
    t2 /= d  # cos 2Δθ
    return t, t2


def _shared_trig(states, convention: Convention, angles: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """``(sin 2Δθ, cos 2Δθ)`` as planes (3, P, B), once per convention and shared state set.

    For ``euler_xyz`` they come from ``ΔR``'s entries without the angles (:func:`euler_xyz_double_angles`).
    """
    if convention == "euler_xyz" and angles is None:
        return memo(
            states, "double_angle_trig:euler_xyz", lambda: euler_xyz_double_angles(delta_rotation_components(states))
        )
    dtheta = angle_components(states, convention, angles)
    if angles is None:
        return memo(states, f"double_angle_trig:{convention}", lambda: double_angle_trig(dtheta))
    return memo_of(states, f"double_angle_trig:{convention}:given", angles, lambda: double_angle_trig(dtheta))


def shift_inertia(mass: np.ndarray, inertia_c: np.ndarray, offset: np.ndarray) -> np.ndarray:
    """Parallel-axis theorem: inertia about a point at ``-offset`` from the centre of mass.

    Parameters
    ----------
    mass : ndarray, shape (B,)
    inertia_c : ndarray, shape (..., B, 3, 3)
        Central inertia, world axes.
    offset : ndarray, shape (..., B, 3)
        ``C − P``.

    Returns
    -------
    ndarray, shape (..., B, 3, 3)
        ``I_C + m(|d|² 1 − d dᵀ)``.
    """
    d2 = np.einsum("...i,...i->...", offset, offset)
    outer = offset[..., :, None] * offset[..., None, :]
    return inertia_c + mass[..., None, None] * (d2[..., None, None] * np.eye(3) - outer)


def alyushin_current(states: SegmentStates) -> np.ndarray:
    """Eq. (38) with the axial (35) and centrifugal (27) moments of the current configuration.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P, B)
    """
    inertia = terms.inertia_world6(states)
    centrifugal = memo(states, "centrifugal_world", lambda: -inertia[3:])  # (I_yz, I_zx, I_xy), eq. (27)
    rot = rotational_energy_30_planes(
        terms.omega_squares(states), terms.omega_products(states), inertia[:3], centrifugal
    )
    return np.add(translational(states), rot, out=rot)


def alyushin_paper(
    states: SegmentStates, convention: Convention = "rotvec", angles: np.ndarray | None = None
) -> np.ndarray:
    """Eq. (38) as the paper prescribes it.

    Axial moments (35) are taken from the initial configuration, which eq. (29) claims
    invariant; centrifugal moments are the initial ones (32) updated by eq. (36) with
    the angles Δθ_x, Δθ_y, Δθ_z read under ``convention``.

    Parameters
    ----------
    states : SegmentStates
    convention : {"rotvec", "euler_xyz", "integrated"}
        How Δθ is read for a general rotation (see :mod:`koenig_check.formulas.angles`).
    angles : ndarray, shape (P, B, 3), optional
        Path integrals of ω, required for ``integrated``.

    Returns
    -------
    ndarray, shape (P, B)
    """
    I_ref = states.inertia_world_ref()
    sin2, cos2 = _shared_trig(states, convention, angles)
    centrifugal = centrifugal_update_33_planes(
        memo(states, "second_moments_ref", lambda: second_moments(I_ref)), sin2, cos2
    )
    axial = np.diagonal(I_ref, axis1=-2, axis2=-1).T  # (3, B)
    rot = rotational_energy_30_planes(terms.omega_squares(states), terms.omega_products(states), axial, centrifugal)
    return np.add(translational(states), rot, out=rot)


def alyushin_pole(
    states: SegmentStates,
    recipe: Recipe = "current",
    convention: Convention = "rotvec",
    angles: np.ndarray | None = None,
) -> np.ndarray:
    """Eq. (37): energy about the pole P (the joint anchor), moments (28) and (27)/(33).

    ``E = ½ m v_P² + ½ Σ θ_i² J_P^i − θ_y θ_z I_yz − θ_x θ_z I_xz − θ_y θ_x I_xy`` with the
    moments taken about P.  As written, eq. (37) has no term coupling ``v_P`` with the
    rotation about P (the paper assumes the pole's coordinates vanish, section 2), so it
    is exact only when P is the centre of mass or does not move.

    Parameters
    ----------
    states : SegmentStates
    recipe : {"current", "paper"}
        ``current``: moments of the current configuration; ``paper``: axial moments
        from the initial configuration (29) and centrifugal moments by eq. (33).
    convention : {"rotvec", "euler_xyz", "integrated"}
        Angle convention of eq. (33), used by the ``paper`` recipe only.
    angles : ndarray, shape (P, B, 3), optional
        Path integrals of ω for ``integrated``.

    Returns
    -------
    ndarray, shape (P, B)
    """
    trans = memo(states, "translational_pole", lambda: terms.half_mass_times_squared_speed(states.mass, states.v_pole))
    if recipe == "current":
        axial, centrifugal = memo(states, "pole_moments", lambda: _pole_moments(states))
    elif recipe == "paper":
        I_P_ref = memo(
            states,
            "pole_inertia_ref",
            lambda: shift_inertia(states.mass, states.inertia_world_ref(), states.com_ref - states.pole_ref),
        )
        sin2, cos2 = _shared_trig(states, convention, angles)
        centrifugal = centrifugal_update_33_planes(
            memo(states, "pole_second_moments_ref", lambda: second_moments(I_P_ref)), sin2, cos2
        )
        axial = np.diagonal(I_P_ref, axis1=-2, axis2=-1).T  # (3, B)
    else:
        raise ValueError(f"unknown recipe {recipe!r}; choose one of {RECIPES}")
    rot = rotational_energy_30_planes(terms.omega_squares(states), terms.omega_products(states), axial, centrifugal)
    return np.add(trans, rot, out=rot)


def _pole_moments(states: SegmentStates) -> tuple[np.ndarray, np.ndarray]:
    """Axial and centrifugal moments about the pole at the current pose (eqs. 28, 27), as planes (3, P, B).

    The parallel-axis theorem of :func:`shift_inertia` entry by entry on the six world components:
    ``J_P^i = I_ii + m(|d|² − d_i²)``, ``I_ij(P) = −(I_ij + m(−d_i d_j))`` with ``d = C − P``.
    """
    inertia = terms.inertia_world6(states)
    com, pole, m = states.com, states.pole, states.mass
    d = np.empty((3, *com.shape[:-1]))
    for i in range(3):
        np.subtract(com[..., i], pole[..., i], out=d[i])
    d2 = terms.squared_norm(d)
    axial, centrifugal = np.empty(d.shape), np.empty(d.shape)
    for i in range(3):  # I_ii + m (|d|² − d_i²)
        a = np.multiply(d[i], d[i], out=axial[i])
        np.subtract(d2, a, out=a)
        scale(a, m, out=a)
        a += inertia[i]
    for n, (i, j) in enumerate(((1, 2), (0, 2), (0, 1))):  # −(I_ij + m (−d_i d_j))
        c = np.multiply(d[i], d[j], out=centrifugal[n])
        np.negative(c, out=c)
        scale(c, m, out=c)
        c += inertia[3 + n]
        np.negative(c, out=c)
    return axial, centrifugal
