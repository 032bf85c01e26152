"""Component arrays shared by the formulas: each quantity as contiguous (P, B) planes, computed once.

The formulas' arithmetic is a handful of products and sums per segment and pose.  On (P, B, 3) and
(P, B, 3, 3) arrays every component access is strided and every small ``einsum`` or ``matmul`` pays
a per-matrix overhead; here each component is one contiguous (P, B) plane (component axis first),
so that every formula is a few elementwise passes, and the planes shared by several formulas
(``ω_i²``, ``ω_i ω_j``, the six world inertia components, ``½ m v_C²``, ``ΔR``) are computed once
per state set through :func:`~koenig_check.formulas.cache.memo`.
"""

from __future__ import annotations

import numpy as np

from koenig_check.formulas.cache import States, memo
from koenig_check.kernels import (
    components,
    dot3,
    inertia_world_components,
    matrix_components,
    scale,
    times_transpose_components,
)
from koenig_check.segments import SegmentStates

#: Order of the six unique entries of a symmetric 3 × 3 matrix: the diagonal, then (yz, xz, xy).
SYM6 = ((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))


def omega_components(states: SegmentStates) -> np.ndarray:
    """World angular velocity, (3, P, B)."""
    return memo(states, "omega_c", lambda: components(states.omega))


def omega_squares(states: SegmentStates) -> np.ndarray:
    """``(ω_x², ω_y², ω_z²)``, (3, P, B)."""

    def compute() -> np.ndarray:
        w = omega_components(states)
        return w * w

    return memo(states, "omega_sq", compute)


def omega_products(states: SegmentStates) -> np.ndarray:
    """``(ω_y ω_z, ω_x ω_z, ω_y ω_x)``, (3, P, B): the factors of ``I_yz, I_zx, I_xy`` in eq. (30)."""

    def compute() -> np.ndarray:
        wx, wy, wz = omega_components(states)
        out = np.empty((3, *wx.shape))
        np.multiply(wy, wz, out=out[0])
        np.multiply(wx, wz, out=out[1])
        np.multiply(wy, wx, out=out[2])
        return out

    return memo(states, "omega_prod", compute)


def rotation_components(states: States) -> np.ndarray:
    """Rotation matrices ``R`` (world ← segment) as (9, P, B), row-major entries."""
    return memo(states, "rotation_c", lambda: matrix_components(states.rotation))


def inertia_world6(states: SegmentStates) -> np.ndarray:
    """The six unique entries of ``R I_body Rᵀ`` in the order of :data:`SYM6`, (6, P, B)."""
    return memo(
        states, "inertia_world6", lambda: inertia_world_components(rotation_components(states), states.inertia_body)
    )


def squared_norm(v: np.ndarray) -> np.ndarray:
    """``|v|²`` of component planes (3, ...)."""
    return dot3(v[0], v[1], v[2], v[0], v[1], v[2])


def half_mass_times_squared_speed(mass: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``½ m |v|²`` (P, B) from velocities (P, B, 3), read in place (no component copy)."""
    v0, v1, v2 = v[..., 0], v[..., 1], v[..., 2]
    sq = dot3(v0, v1, v2, v0, v1, v2, out=np.empty(v.shape[:-1]))
    return scale(sq, 0.5 * mass, out=sq)


def translational(states: SegmentStates) -> np.ndarray:
    """``½ m v_C²``, (P, B)."""
    return memo(states, "translational", lambda: half_mass_times_squared_speed(states.mass, states.v_com))


def axial_part_world(states: SegmentStates) -> np.ndarray:
    """``ω_x² J^x + ω_y² J^y + ω_z² J^z`` with the world axial moments of the current pose, (P, B)."""

    def compute() -> np.ndarray:
        sq, inertia = omega_squares(states), inertia_world6(states)
        return dot3(sq[0], sq[1], sq[2], inertia[0], inertia[1], inertia[2])

    return memo(states, "axial_part_world", compute)


def delta_rotation_components(states: States) -> np.ndarray:
    """``ΔR = R R_refᵀ`` as (9, P, B), row-major entries."""
    return memo(
        states, "delta_rotation_c", lambda: times_transpose_components(rotation_components(states), states.rotation_ref)
    )
