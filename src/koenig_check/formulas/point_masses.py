"""Eq. (10) integrated numerically over an equimomental set of point masses per segment."""

from __future__ import annotations

import numpy as np

from koenig_check.formulas.cache import per_model
from koenig_check.formulas.terms import dot3
from koenig_check.kernels import scale
from koenig_check.segments import SegmentStates, second_moments

#: Points per segment in the equimomental set built by :func:`equimomental_points`.
POINTS_PER_SEGMENT = 6


def equimomental_points(
    mass: np.ndarray, inertia_body: np.ndarray, names: tuple[str, ...] | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Six point masses per segment with the segment's mass, centre of mass and inertia.

    With the second-moment matrix ``S = ½ tr(I) 1 − I = V diag(s) Vᵀ`` (``s >= 0`` exactly
    when the inertia is physical), the points sit at ``±sqrt(3 s_k / m) v_k`` from the
    centre of mass, each of mass ``m/6``: their mass is ``m``, their centre is the centre
    of mass and their second moments are ``S``, hence their inertia is ``I``.

    Parameters
    ----------
    mass : ndarray, shape (B,)
    inertia_body : ndarray, shape (B, 3, 3)
        Central inertia in segment axes.
    names : tuple of str, optional
        Segment names, used in error messages.

    Returns
    -------
    offsets : ndarray, shape (B, 6, 3)
        Point positions relative to the centre of mass, in segment axes.
    masses : ndarray, shape (B, 6)

    Raises
    ------
    ValueError
        If a segment's inertia is not physical (some ``s_k < 0``).
    """
    mass = np.asarray(mass, dtype=float)
    s, V = np.linalg.eigh(second_moments(np.asarray(inertia_body, dtype=float)))
    scale = np.maximum(np.abs(s).max(axis=-1), 1e-300)
    bad = s.min(axis=-1) < -1e-12 * scale
    if bad.any():
        b = int(np.flatnonzero(bad)[0])
        name = names[b] if names else str(b)
        raise ValueError(
            f"equimomental_points: segment {name!r} has a non-physical inertia "
            f"(second moments {np.round(s[b], 12).tolist()} must be >= 0: triangle inequality)"
        )
    d = np.sqrt(np.clip(3.0 * s / mass[:, None], 0.0, None))  # (B, 3)
    axes = np.swapaxes(V, -1, -2) * d[..., None]  # (B, 3, 3): row k = d_k v_k
    offsets = np.concatenate([axes, -axes], axis=1)
    masses = np.repeat((mass / POINTS_PER_SEGMENT)[:, None], POINTS_PER_SEGMENT, axis=1)
    return offsets, masses


def point_world_positions(states: SegmentStates, offsets: np.ndarray) -> np.ndarray:
    """World positions of points fixed in each segment, ``C + R r``.

    Parameters
    ----------
    states : SegmentStates
    offsets : ndarray, shape (B, K, 3)
        Relative to the centre of mass, in segment axes.

    Returns
    -------
    ndarray, shape (P, B, K, 3)
    """
    return states.com[:, :, None, :] + np.einsum("pbij,bkj->pbki", states.rotation, offsets)


def rigid_point_velocities(states: SegmentStates, offsets: np.ndarray) -> np.ndarray:
    """Velocities of points fixed in each segment, ``v_C + ω × (R r)``.

    Parameters
    ----------
    states : SegmentStates
    offsets : ndarray, shape (B, K, 3)
        Relative to the centre of mass, in segment axes.

    Returns
    -------
    ndarray, shape (P, B, K, 3)
    """
    arm = np.einsum("pbij,bkj->pbki", states.rotation, offsets)
    return states.v_com[:, :, None, :] + np.cross(states.omega[:, :, None, :], arm)


def point_masses(states: SegmentStates, point_velocities: np.ndarray | None = None) -> np.ndarray:
    """Eq. (10), ``E = ½ ∫ v² dm``, as a sum over an equimomental point set per segment.

    Parameters
    ----------
    states : SegmentStates
    point_velocities : ndarray, shape (P, B, 6, 3), optional
        World velocities of the points of :func:`equimomental_points`, e.g. computed by
        an engine from its own kinematics.  By default they are computed from the
        segment's motion, ``v_C + ω × (R r)``.

    Returns
    -------
    ndarray, shape (P, B)
    """
    offsets, masses = per_model(
        "equimomental_points",
        (states.mass, states.inertia_body),
        lambda: equimomental_points(states.mass, states.inertia_body, states.names),
    )
    if point_velocities is None:
        v = rigid_point_velocities(states, offsets)
    else:
        v = np.asarray(point_velocities, dtype=float)
        expected = (states.n_poses, states.n_segments, POINTS_PER_SEGMENT, 3)
        if v.shape != expected:
            raise ValueError(f"point_velocities: shape {v.shape}, expected {expected}")
    planes = np.moveaxis(v, (2, 3), (0, 1))  # (K, 3, P, B): contiguous for the engines' point velocities
    total = np.zeros(planes.shape[2:])
    sq = np.empty(total.shape)
    for k in range(planes.shape[0]):  # Σ_k m_k |v_k|², in point order
        vk = planes[k]
        dot3(vk[0], vk[1], vk[2], vk[0], vk[1], vk[2], out=sq)
        total += scale(sq, masses[:, k], out=sq)
    total *= 0.5
    return total
