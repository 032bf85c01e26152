"""Where the paper says two formulas coincide they must; where its recipe fails the tests show it."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.analytic import (
    box_inertia,
    constant_rotation_states,
    random_physical_inertia,
    random_rotations,
    random_states,
    rigid_states,
)
from koenig_check.formulas import FORMULAS, integrate_angular_velocity
from koenig_check.formulas.alyushin import alyushin_current, alyushin_paper, alyushin_pole
from koenig_check.formulas.angles import CONVENTIONS
from koenig_check.paper_section3 import angular_velocity_39, rotation_39

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


def test_koenig_world_error_takes_both_signs(rng: np.random.Generator) -> None:
    """The paper claims eq. (1) always overestimates; over random cases it does not."""
    states = random_states(rng, 500, 3)
    diff = FORMULAS["koenig_world"](states) - FORMULAS["exact"](states)
    scale = FORMULAS["exact"](states)
    assert (diff > 1e-9 * scale).any()
    assert (diff < -1e-9 * scale).any()


def test_fixed_axis_rotation_keeps_paper_recipe_exact_only_with_rotvec(rng: np.random.Generator) -> None:
    """A fixed-axis turn with two non-zero world components of ω, principal axes on the world axes.

    The rotation-vector reading of Δθ keeps eq. (38) exact here; the Euler reading does not.
    """
    times = np.linspace(0.0, 1.5, 7)
    states = constant_rotation_states(2.0, ASYMMETRIC_BOX, np.array([1.0, 0.0, 1.0]), times)
    exact = FORMULAS["exact"](states)
    np.testing.assert_allclose(FORMULAS["alyushin_paper:rotvec"](states), exact, rtol=1e-12)
    rel = np.abs(FORMULAS["alyushin_paper:euler_xyz"](states) / exact - 1)
    assert rel[1:].min() > 1e-3
