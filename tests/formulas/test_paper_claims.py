"""Where the paper says two formulas coincide they must; where its recipe fails the tests show it."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from koenig_check.formulas import FORMULAS, integrate_angular_velocity
from koenig_check.formulas.alyushin import alyushin_current, alyushin_paper, alyushin_pole
from koenig_check.formulas.analytic import (
    box_inertia,
    constant_rotation_states,
    random_physical_inertia,
    random_rotations,
    random_states,
    rigid_states,
)
from koenig_check.formulas.angles import CONVENTIONS
from koenig_check.formulas.paper_section3 import angular_velocity_39, rotation_39

ASYMMETRIC_BOX = box_inertia(2.0, 0.5, 0.3, 0.1)


@pytest.mark.parametrize("formula", ["koenig_world", *[f"alyushin_paper:{c}" for c in CONVENTIONS], "planar"])
@pytest.mark.parametrize("axis", [[0, 0, 1], [1, 0, 0], [0, 1, 0]])
def test_rotation_about_one_world_axis_from_initial_state_matches_exact(
    rng: np.random.Generator, formula: str, axis: list[int]
) -> None:
    """Eq. (17) and the conclusion: one-axis rotation from the initial configuration."""
    R_ref = random_rotations(rng, ())  # products of inertia in world axes are non-zero
    times = np.linspace(0.0, 3.0, 13)
    states = constant_rotation_states(
        2.0,
        ASYMMETRIC_BOX,
        2.5 * np.array(axis, dtype=float),
        times,
        rotation_ref=R_ref,
        v_com=[0.2, 0.1, 0.0],
    )
    if formula == "planar":
        states = states.with_motion(v_com=np.where(np.array(axis) == 1, 0.0, states.v_com))
    angles = integrate_angular_velocity(states.omega, times)
    np.testing.assert_allclose(FORMULAS[formula](states, angles=angles), FORMULAS["exact"](states), rtol=1e-12)


@pytest.mark.parametrize("convention", CONVENTIONS)
def test_eq37_with_pole_at_com_equals_eq38(rng: np.random.Generator, convention: str) -> None:
    states = random_states(rng, 40, 4)
    at_com = states.with_motion(pole=states.com, v_pole=states.v_com, pole_ref=states.com_ref)
    angles = rng.normal(size=(40, 4, 3))
    kw = {"angles": angles} if convention == "integrated" else {}
    np.testing.assert_allclose(alyushin_pole(at_com, "current"), alyushin_current(at_com), rtol=1e-12)
    np.testing.assert_allclose(
        alyushin_pole(at_com, "paper", convention, **kw), alyushin_paper(at_com, convention, **kw), rtol=1e-12
    )


def test_eq37_current_is_exact_about_a_fixed_pole_only(rng: np.random.Generator) -> None:
    """Eq. (37) has no coupling of v_P with rotation: exact when P is fixed, not when it moves."""
    P, B = 30, 3
    R = random_rotations(rng, (P, B))
    omega = rng.normal(size=(P, B, 3))
    pole_body = rng.normal(scale=0.4, size=(B, 3))
    arm = np.einsum("pbij,bj->pbi", R, pole_body)
    fixed = rigid_states(
        mass=np.ones(B),
        inertia_body=random_physical_inertia(rng, B),
        rotation=R,
        omega=omega,
        v_com=-np.cross(omega, arm),
        pole_body=pole_body,
    )
    np.testing.assert_allclose(np.abs(fixed.v_pole).max(), 0.0, atol=1e-14)
    np.testing.assert_allclose(alyushin_pole(fixed, "current"), FORMULAS["exact"](fixed), rtol=1e-12)
    moving = fixed.with_motion(v_com=fixed.v_com + 1.0, v_pole=fixed.v_pole + 1.0)
    rel = np.abs(alyushin_pole(moving, "current") / FORMULAS["exact"](moving) - 1)
    assert rel.max() > 1e-3


def _gimbal_path(n: int = 4001) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Motion (39) at constant joint rates: Δθ_z = 1.3 t, Δθ_x = 0.8 t, t in [0, 1]."""
    t = np.linspace(0.0, 1.0, n)
    R = rotation_39(1.3 * t, 0.8 * t)
    omega = angular_velocity_39(1.3 * t, np.full_like(t, 1.3), np.full_like(t, 0.8))
    return t, R, omega


def _eq38_rotational_by_hand(inertia_ref: np.ndarray, omega: np.ndarray, dtheta: np.ndarray) -> np.ndarray:
    """Rotational part of eq. (38), written out from the paper for one body.

    Initial planar and centrifugal moments (32) from ``S = ∫ r rᵀ dm = ½ tr(I) 1 − I``; axial
    moments (35) as sums of two planar moments (28); centrifugal moments updated by (36).
    ``omega`` and ``dtheta`` have shape (T, 3); returns (T,).
    """
    S = 0.5 * np.trace(inertia_ref) * np.eye(3) - inertia_ref
    i_a, i_b, i_g = S[0, 0], S[1, 1], S[2, 2]
    i_ab, i_bg, i_ag = S[0, 1], S[1, 2], S[0, 2]
    j_x, j_y, j_z = i_b + i_g, i_a + i_g, i_a + i_b
    tx, ty, tz = dtheta[:, 0], dtheta[:, 1], dtheta[:, 2]
    i_xy = 0.5 * np.sin(2 * tz) * (i_a - i_b) + np.cos(2 * tz) * i_ab
    i_yz = 0.5 * np.sin(2 * tx) * (i_b - i_g) + np.cos(2 * tx) * i_bg
    i_zx = 0.5 * np.sin(2 * ty) * (i_g - i_a) + np.cos(2 * ty) * i_ag
    wx, wy, wz = omega[:, 0], omega[:, 1], omega[:, 2]
    return 0.5 * (wz**2 * j_z + wy**2 * j_y + wx**2 * j_x) - wy * wz * i_yz - wx * wz * i_zx - wy * wx * i_xy


def test_two_axis_rotation_breaks_the_paper_recipe_and_koenig_world() -> None:
    """Stated case: the asymmetric box turned by motion (39) (z external, x internal) to t = 1."""
    t, R, omega = _gimbal_path()
    states = rigid_states(
        mass=np.array([2.0]),
        inertia_body=ASYMMETRIC_BOX[None],
        rotation=R[:, None],
        omega=omega[:, None],
        v_com=np.zeros((t.size, 1, 3)),
    )
    angles = integrate_angular_velocity(states.omega, t)
    exact = FORMULAS["exact"](states)[-1, 0]
    for name in ["koenig_world", *[f"alyushin_paper:{c}" for c in CONVENTIONS]]:
        value = FORMULAS[name](states, angles=angles)[-1, 0]
        assert abs(value / exact - 1) > 1e-3, name
    # The formulas the paper calls exact for any rotation (with current moments) stay exact.
    for name in ["koenig_principal", "alyushin_current", "point_masses"]:
        np.testing.assert_allclose(FORMULAS[name](states, angles=angles)[-1, 0], exact, rtol=1e-12)


def test_paper_recipe_on_the_gimbal_path_is_eq38_with_eq36_by_hand() -> None:
    """The recipe's value along motion (39) is eq. (38) with (35) initial and (36), under each reading of Δθ.

    ω of motion (39) is ``θ_z,t e_z + θ_x,t R_z(Δθ_z) e_x = (0.8 cos 1.3t, 0.8 sin 1.3t, 1.3)``; the readings:
    the paper's own joint angles (extrinsic x-y-z Euler angles ``(0.8 t, 0, 1.3 t)``), the integral of ω
    in closed form, and the rotation vector of the current orientation.
    """
    t, R, omega = _gimbal_path(401)
    np.testing.assert_allclose(
        omega, np.stack([0.8 * np.cos(1.3 * t), 0.8 * np.sin(1.3 * t), np.full_like(t, 1.3)], -1), atol=1e-14
    )
    states = rigid_states(
        mass=np.array([2.0]),
        inertia_body=ASYMMETRIC_BOX[None],
        rotation=R[:, None],
        omega=omega[:, None],
        v_com=np.zeros((t.size, 1, 3)),
    )
    readings = {
        "euler_xyz": np.stack([0.8 * t, np.zeros_like(t), 1.3 * t], axis=-1),
        "integrated": np.stack([0.8 / 1.3 * np.sin(1.3 * t), 0.8 / 1.3 * (1 - np.cos(1.3 * t)), 1.3 * t], axis=-1),
        "rotvec": Rotation.from_matrix(R).as_rotvec(),
    }
    for convention, dtheta in readings.items():
        by_hand = _eq38_rotational_by_hand(ASYMMETRIC_BOX, omega, dtheta)
        kw = {"angles": dtheta[:, None]} if convention == "integrated" else {}
        value = alyushin_paper(states, convention, **kw)[:, 0]
        np.testing.assert_allclose(value, by_hand, rtol=1e-12, err_msg=convention)


def test_koenig_world_error_takes_both_signs(rng: np.random.Generator) -> None:
    """The paper claims eq. (1) always overestimates; over random cases it does not."""
    states = random_states(rng, 500, 3)
    diff = FORMULAS["koenig_world"](states) - FORMULAS["exact"](states)
    scale = FORMULAS["exact"](states)
    assert (diff > 1e-9 * scale).any()
    assert (diff < -1e-9 * scale).any()


#: A reference orientation whose world-axis products of inertia are all non-zero (6 % to 11 % of the trace).
TILTED = Rotation.from_euler("xyz", [0.5, -0.4, 0.7]).as_matrix()


@pytest.mark.parametrize("axis", [[1.0, 0.0, 1.0], [1.0, 0.5, 0.0], [0.0, 0.7, 1.2]])
def test_fixed_axis_rotation_keeps_paper_recipe_exact_only_with_rotvec(axis: list[float]) -> None:
    """A fixed-axis turn with two non-zero world components of ω, from a tilted reference orientation.

    The rotation-vector reading of Δθ (and the path integral, equal to it for a fixed axis) keeps
    eq. (38) exact; the Euler reading does not.  Why rotvec is exact even with non-zero products of
    inertia: the only product term of eq. (30) with a non-zero weight θ_j θ_k is the one of the plane
    of the axis, and eq. (36) updates it with the angle about the third world axis, which is zero, while
    ½ ωᵀ I ω is invariant under a turn about ω itself.
    """
    I_ref = TILTED @ ASYMMETRIC_BOX @ TILTED.T
    assert np.abs(I_ref[[0, 0, 1], [1, 2, 2]]).min() > 0.05 * np.trace(I_ref)
    times = np.linspace(0.0, 1.5, 7)
    states = constant_rotation_states(2.0, ASYMMETRIC_BOX, np.array(axis), times, rotation_ref=TILTED)
    exact = FORMULAS["exact"](states)
    angles = integrate_angular_velocity(states.omega, times)
    np.testing.assert_allclose(FORMULAS["alyushin_paper:rotvec"](states), exact, rtol=1e-12)
    np.testing.assert_allclose(FORMULAS["alyushin_paper:integrated"](states, angles=angles), exact, rtol=1e-12)
    rel = np.abs(FORMULAS["alyushin_paper:euler_xyz"](states) / exact - 1)
    assert rel[1:].min() > 1e-3


def test_fixed_axis_with_three_world_components_breaks_the_paper_recipe_even_with_rotvec() -> None:
    """Off every coordinate plane, eq. (36) turns each product by a different angle: not a rotation any more.

    The recipe still is eq. (38) with (36) at Δθ = ω t (checked by hand), but it is no longer exact.
    """
    omega = np.array([1.0, 0.5, 1.0])
    times = np.linspace(0.0, 1.5, 7)
    states = constant_rotation_states(2.0, ASYMMETRIC_BOX, omega, times, rotation_ref=TILTED)
    exact = FORMULAS["exact"](states)[:, 0]
    value = FORMULAS["alyushin_paper:rotvec"](states)[:, 0]
    by_hand = _eq38_rotational_by_hand(
        TILTED @ ASYMMETRIC_BOX @ TILTED.T, np.broadcast_to(omega, (times.size, 3)), times[:, None] * omega
    )
    np.testing.assert_allclose(value, by_hand, rtol=1e-12)
    np.testing.assert_allclose(value[0], exact[0], rtol=1e-12)  # at the initial state nothing has turned yet
    assert np.abs(value[1:] / exact[1:] - 1).min() > 1e-3
