"""Eq. (33)/(36) and eq. (37) against what the paper itself claims for them."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS, integrate_angular_velocity
from koenig_check.formulas.alyushin import alyushin_pole, centrifugal_update_33, double_angle_trig
from koenig_check.formulas.analytic import random_physical_inertia, random_rotations, rigid_states, rotation_about
from koenig_check.formulas.angles import CONVENTIONS

#: Index of the centrifugal moment of the plane normal to world axis k in ``(I_yz, I_zx, I_xy)``.
PLANE_OF_AXIS = {0: (1, 2), 1: (0, 2), 2: (0, 1)}


def _random_second_moments(rng: np.random.Generator, n: int) -> np.ndarray:
    """Random positive second-moment matrices ``∫ r rᵀ dm`` with non-zero products in world axes."""
    V = random_rotations(rng, (n,))
    s = rng.uniform(0.01, 0.2, size=(n, 3))
    return V @ (s[..., None] * np.eye(3)) @ np.swapaxes(V, -1, -2)


@pytest.mark.parametrize("k", [0, 1, 2], ids=["x", "y", "z"])
def test_eq33_rotates_the_centrifugal_moment_of_the_plane_normal_to_the_axis(rng: np.random.Generator, k: int) -> None:
    """Eq. (31)/(33): a turn by Δθ_k about world axis k maps ∫(.)(.)dm of the plane normal to k exactly.

    The reference is the rotated second-moment matrix ``R_k S0 R_kᵀ`` itself, read off by index here.
    """
    S0 = _random_second_moments(rng, 4)
    i, j = PLANE_OF_AXIS[k]
    assert np.abs(S0[:, i, j]).min() > 1e-4 and np.ptp(np.diagonal(S0, axis1=1, axis2=2), axis=1).min() > 1e-4
    theta = np.concatenate([rng.uniform(-3.0, 3.0, size=(6, 4)), np.full((1, 4), np.pi / 4)])
    R = rotation_about(np.eye(3)[k], theta.ravel()).reshape(*theta.shape, 3, 3)
    S = R @ S0[None] @ np.swapaxes(R, -1, -2)
    got = centrifugal_update_33(S0, theta[..., None] * np.eye(3)[k])
    np.testing.assert_allclose(got[..., k], S[..., i, j], rtol=1e-12, atol=1e-15)
    # The other two moments take angles about the other axes, which are zero here: unchanged.
    for m in {0, 1, 2} - {k}:
        a, b = PLANE_OF_AXIS[m]
        np.testing.assert_allclose(got[..., m], np.broadcast_to(S0[:, a, b], theta.shape), rtol=1e-14)


def _turn_about_fixed_pole(rng: np.random.Generator, k: int, n: int = 9):
    """One body turning at a constant rate about world axis k through a fixed pole P off its COM.

    Starts from its reference pose at t = 0; the turn exceeds π so that every angle reading wraps.
    """
    R_ref = random_rotations(rng, ())
    pole = np.array([0.3, -0.2, 0.5])
    com_ref = pole + np.array([0.2, -0.1, 0.15])  # off the pole and off every world axis through it
    axis = np.eye(3)[k]
    t = np.linspace(0.0, 2.0, n)
    dR = rotation_about(axis, 1.7 * t)
    com = pole + dR @ (com_ref - pole)
    omega = np.broadcast_to(1.7 * axis, (n, 3))
    states = rigid_states(
        mass=np.array([2.0]),
        inertia_body=random_physical_inertia(rng, 1),
        rotation=(dR @ R_ref)[:, None],
        omega=omega[:, None],
        v_com=np.cross(omega, com - pole)[:, None],
        com=com[:, None],
        rotation_ref=R_ref[None],
        com_ref=com_ref[None],
        pole_body=(R_ref.T @ (pole - com_ref))[None],
    )
    np.testing.assert_allclose(states.pole, np.broadcast_to(pole, (n, 1, 3)), atol=1e-14)
    np.testing.assert_allclose(states.v_pole, 0.0, atol=1e-14)
    np.testing.assert_allclose(states.pole_ref[0], pole, atol=1e-14)
    return states, t


@pytest.mark.parametrize("convention", CONVENTIONS)
@pytest.mark.parametrize("k", [0, 1, 2], ids=["x", "y", "z"])
def test_eq37_paper_recipe_is_exact_for_a_turn_about_a_fixed_pole_off_the_com(
    rng: np.random.Generator, k: int, convention: str
) -> None:
    """Eq. (37) with J_P from the initial state (29) about a fixed pole: exact for a one-axis turn.

    The axial moment about P needs the parallel-axis term of the reference offset C - P.
    """
    states, t = _turn_about_fixed_pole(rng, k)
    angles = integrate_angular_velocity(states.omega, t)  # ω constant: the trapezoid rule is exact
    value = FORMULAS[f"alyushin_pole:paper:{convention}"](states, angles=angles)
    np.testing.assert_allclose(value, FORMULAS["exact"](states), rtol=1e-12)
    np.testing.assert_allclose(alyushin_pole(states, "current"), FORMULAS["exact"](states), rtol=1e-12)


@pytest.mark.parametrize("convention", CONVENTIONS)
def test_eq37_paper_recipe_reads_only_the_reference_offset(rng: np.random.Generator, convention: str) -> None:
    """The paper recipe takes its moments from the initial state: current C and P do not enter it."""
    states, t = _turn_about_fixed_pole(rng, 2)
    angles = integrate_angular_velocity(states.omega, t) if convention == "integrated" else None
    moved = states.with_motion(
        com=states.com + rng.normal(scale=0.3, size=states.com.shape),
        pole=states.pole + rng.normal(scale=0.3, size=states.pole.shape),
    )
    before = alyushin_pole(states, "paper", convention, angles=angles)
    np.testing.assert_allclose(alyushin_pole(moved, "paper", convention, angles=angles), before, rtol=1e-15)
    # The current recipe does read them: the perturbation is large enough to show.
    rel = np.abs(alyushin_pole(moved, "current") / alyushin_pole(states, "current") - 1)
    assert rel.min() > 1e-3


def test_double_angle_trig_hand_values_and_sin_cos(rng: np.random.Generator) -> None:
    angles = np.array([0.0, np.pi / 6, np.pi / 4, np.pi / 2, -np.pi / 3, np.pi, 3.0])
    sin2, cos2 = double_angle_trig(angles)
    hand_sin = [0.0, np.sqrt(3) / 2, 1.0, 0.0, -np.sqrt(3) / 2, 0.0, np.sin(6.0)]
    hand_cos = [1.0, 0.5, 0.0, -1.0, -0.5, 1.0, np.cos(6.0)]
    np.testing.assert_allclose(sin2, hand_sin, atol=1e-15)
    np.testing.assert_allclose(cos2, hand_cos, atol=1e-15)
    theta = rng.uniform(-4.0, 4.0, size=(50, 3))
    sin2, cos2 = double_angle_trig(theta)
    np.testing.assert_allclose(sin2, np.sin(2 * theta), atol=1e-15)
    np.testing.assert_allclose(cos2, np.cos(2 * theta), atol=1e-15)
