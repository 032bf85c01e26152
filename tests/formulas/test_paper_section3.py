"""The paper's section-3 motion (z external, x internal), eqs. (39)-(41), and its concluding energy."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS
from koenig_check.formulas.analytic import box_inertia, rigid_states
from koenig_check.formulas.paper_section3 import (
    angular_velocity_39,
    concluding_energy,
    coordinates_39,
    integrand_41,
    rotation_39,
    velocities_40,
)
from koenig_check.formulas.point_masses import equimomental_points

POLE = np.array([0.1, -0.2, 0.3])
COM_OFFSET = np.array([0.25, 0.15, -0.1])  # off both rotation axes
MASS = 2.0
# An asymmetric box with tilted principal axes, as a cloud of six point masses.
_R0 = rotation_39(0.4, 0.7)
INERTIA = _R0 @ box_inertia(MASS, 0.5, 0.3, 0.1) @ _R0.T
_offsets, _masses = equimomental_points(np.array([MASS]), INERTIA[None])
MASSES = _masses[0]
LAGRANGE = POLE + COM_OFFSET + _offsets[0]  # initial coordinates (α, β, γ)

GRID = np.linspace(-np.pi, np.pi, 25)
TZ, TX = np.meshgrid(GRID, GRID, indexing="ij")
RATE_Z, RATE_X = 1.7, -0.9


def test_coordinates_39_are_the_rotation_rz_rx_about_the_pole() -> None:
    x = coordinates_39(LAGRANGE, POLE, TZ, TX)
    expected = POLE + np.einsum("gij,nj->gni", rotation_39(TZ, TX).reshape(-1, 3, 3), LAGRANGE - POLE)
    np.testing.assert_allclose(x.reshape(-1, len(MASSES), 3), expected, atol=1e-14)


def test_coordinates_39_reduce_to_the_one_axis_equations() -> None:
    """(39) with Δθ_x = 0 is eq. (3); with Δθ_z = 0 it is eq. (5)."""
    a, b, g = (LAGRANGE - POLE).T
    t = 0.8
    only_z = coordinates_39(LAGRANGE, POLE, t, 0.0)
    np.testing.assert_allclose(only_z[:, 0], POLE[0] + a * np.cos(t) - b * np.sin(t), atol=1e-15)
    np.testing.assert_allclose(only_z[:, 1], POLE[1] + a * np.sin(t) + b * np.cos(t), atol=1e-15)
    np.testing.assert_allclose(only_z[:, 2], LAGRANGE[:, 2], atol=1e-15)
    only_x = coordinates_39(LAGRANGE, POLE, 0.0, t)
    np.testing.assert_allclose(only_x[:, 0], LAGRANGE[:, 0], atol=1e-15)
    np.testing.assert_allclose(only_x[:, 1], POLE[1] + b * np.cos(t) - g * np.sin(t), atol=1e-15)
    np.testing.assert_allclose(only_x[:, 2], POLE[2] + b * np.sin(t) + g * np.cos(t), atol=1e-15)


def test_velocities_40_match_finite_differences_of_39() -> None:
    h = 1e-6
    ahead = coordinates_39(LAGRANGE, POLE, TZ + h * RATE_Z, TX + h * RATE_X)
    behind = coordinates_39(LAGRANGE, POLE, TZ - h * RATE_Z, TX - h * RATE_X)
    fd = (ahead - behind) / (2 * h)
    np.testing.assert_allclose(velocities_40(LAGRANGE, POLE, TZ, TX, RATE_Z, RATE_X), fd, atol=1e-8)


def test_integrand_41_is_the_squared_speed_pointwise() -> None:
    v = velocities_40(LAGRANGE, POLE, TZ, TX, RATE_Z, RATE_X)
    np.testing.assert_allclose(
        integrand_41(LAGRANGE, POLE, TX, RATE_Z, RATE_X),
        np.einsum("...i,...i->...", v, v),
        rtol=1e-12,
        atol=1e-14,
    )


def _exact_on_grid() -> tuple[np.ndarray, np.ndarray]:
    """Energy two ways: eq. (10) summed over the particles, and `exact` on the rigid-body state."""
    v = velocities_40(LAGRANGE, POLE, TZ, TX, RATE_Z, RATE_X)
    integrated = 0.5 * np.einsum("n,...ni,...ni->...", MASSES, v, v)
    R = rotation_39(TZ, TX).reshape(-1, 1, 3, 3)
    omega = angular_velocity_39(TZ, RATE_Z, RATE_X).reshape(-1, 1, 3)
    arm = np.einsum("pbij,j->pbi", R, COM_OFFSET)
    states = rigid_states(np.array([MASS]), INERTIA[None], R, omega, v_com=np.cross(omega, arm), com=POLE + arm)
    return integrated, FORMULAS["exact"](states).reshape(TZ.shape)


def test_exact_formula_equals_eq10_integrated_over_the_particles() -> None:
    integrated, exact = _exact_on_grid()
    np.testing.assert_allclose(exact, integrated, rtol=1e-12)


def test_concluding_energy_against_exact_over_the_angle_grid() -> None:
    """The paper's concluding formula holds where Δθ_x = 0 and fails elsewhere on this body."""
    _, exact = _exact_on_grid()
    paper = concluding_energy(MASSES, LAGRANGE, POLE, np.full_like(TZ, RATE_Z), np.full_like(TZ, RATE_X))
    rel = paper / exact - 1
    at_zero = np.isclose(TX, 0.0, atol=1e-12)
    np.testing.assert_allclose(rel[at_zero], 0.0, atol=1e-12)
    # The exact energy depends on Δθ_x only (the z rotation is about the fixed axis of the outer joint).
    np.testing.assert_allclose(exact, exact[:1, :].repeat(len(GRID), axis=0), rtol=1e-12)
    assert np.abs(rel[~at_zero]).max() > 1e-2
    # Both signs occur: the paper's formula over- and under-estimates on this grid.
    assert (rel > 1e-6).any() and (rel < -1e-6).any()


@pytest.mark.parametrize("pole_shift", [np.zeros(3), np.array([0.0, 0.0, 1.0])])
def test_one_axis_special_cases_match_the_paper(pole_shift: np.ndarray) -> None:
    """Rotation about x only gives ½θ_x²J_P^x, about z only ½θ_z²J_P^z (section 3)."""
    pole = POLE + pole_shift
    a, b, g = (LAGRANGE - pole).T
    only_x = 0.5 * MASSES @ integrand_41(LAGRANGE, pole, 0.6, 0.0, RATE_X)
    np.testing.assert_allclose(only_x, 0.5 * RATE_X**2 * MASSES @ (b**2 + g**2), rtol=1e-12)
    only_z = 0.5 * MASSES @ integrand_41(LAGRANGE, pole, 0.0, RATE_Z, 0.0)
    np.testing.assert_allclose(only_z, 0.5 * RATE_Z**2 * MASSES @ (a**2 + b**2), rtol=1e-12)
