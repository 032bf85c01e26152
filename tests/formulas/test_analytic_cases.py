"""Hand-computed energies of a uniform box and a solid cylinder, for every formula that applies."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS, integrate_angular_velocity
from koenig_check.formulas.analytic import box_inertia, constant_rotation_states, cylinder_inertia

# Formulas that must give the textbook values in these one-axis cases.
ONE_AXIS_FORMULAS = sorted(FORMULAS)

BODIES = {
    # name: (mass, inertia, spin axis index, hand-computed spin moment about that axis)
    "box 0.4x0.3x0.2, 3 kg, about z": (3.0, box_inertia(3.0, 0.4, 0.3, 0.2), 2, 3.0 / 12 * (0.16 + 0.09)),
    "box 0.4x0.3x0.2, 3 kg, about x": (3.0, box_inertia(3.0, 0.4, 0.3, 0.2), 0, 3.0 / 12 * (0.09 + 0.04)),
    "cylinder r=0.1 h=0.5, 2 kg, about its axis": (2.0, cylinder_inertia(2.0, 0.1, 0.5), 2, 0.5 * 2.0 * 0.01),
    "cylinder r=0.1 h=0.5, 2 kg, about a diameter": (
        2.0,
        cylinder_inertia(2.0, 0.1, 0.5),
        1,
        2.0 * (3 * 0.01 + 0.25) / 12,
    ),
}


@pytest.mark.parametrize("formula", ONE_AXIS_FORMULAS)
@pytest.mark.parametrize("body", sorted(BODIES))
def test_spin_about_principal_axis_is_half_j_omega_squared(formula: str, body: str) -> None:
    mass, inertia, axis, J = BODIES[body]
    rate = 4.0
    omega = np.zeros(3)
    omega[axis] = rate
    times = np.linspace(0.0, 2.0, 9)
    states = constant_rotation_states(mass, inertia, omega, times)
    angles = integrate_angular_velocity(states.omega, times)
    energy = FORMULAS[formula](states, angles=angles)[:, 0]
    np.testing.assert_allclose(energy, 0.5 * J * rate**2, rtol=1e-12)


@pytest.mark.parametrize("formula", ONE_AXIS_FORMULAS)
@pytest.mark.parametrize("body", sorted(BODIES))
def test_pure_translation_is_half_m_v_squared(formula: str, body: str) -> None:
    mass, inertia, _, _ = BODIES[body]
    v = np.array([0.3, -1.2, 2.0])
    times = np.linspace(0.0, 1.0, 5)
    states = constant_rotation_states(mass, inertia, np.zeros(3), times, v_com=v)
    angles = integrate_angular_velocity(states.omega, times)
    energy = FORMULAS[formula](states, angles=angles)[:, 0]
    np.testing.assert_allclose(energy, 0.5 * mass * (0.09 + 1.44 + 4.0), rtol=1e-12)


def test_hand_values_are_the_textbook_ones() -> None:
    # Guard the table itself: box about z is m(a²+b²)/12, cylinder about its axis is mr²/2.
    assert box_inertia(3.0, 0.4, 0.3, 0.2)[2, 2] == pytest.approx(0.0625)
    assert cylinder_inertia(2.0, 0.1, 0.5)[2, 2] == pytest.approx(0.01)
