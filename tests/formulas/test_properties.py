"""Seeded property tests over random masses, physical inertias, rotations and velocities."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from koenig_check.formulas import FORMULAS
from koenig_check.formulas.analytic import random_states
from koenig_check.segments import SegmentStates

EXACT_EQUIVALENTS = ["koenig_principal", "alyushin_current", "point_masses"]
NON_NEGATIVE = ["exact", *EXACT_EQUIVALENTS]

seeds = st.integers(min_value=0, max_value=2**32 - 1)
sizes = st.integers(min_value=1, max_value=6)
PROPERTY_SETTINGS = settings(max_examples=150, deadline=None, derandomize=True)


def _rotate_world(states: SegmentStates, Q: np.ndarray, shift: np.ndarray) -> SegmentStates:
    """The same motion seen from a world frame rotated by Q and shifted."""
    rot = lambda v: np.einsum("ij,...j->...i", Q, v)  # noqa: E731
    return states.with_motion(
        com=rot(states.com) + shift,
        v_com=rot(states.v_com),
        rotation=Q @ states.rotation,
        omega=rot(states.omega),
        pole=rot(states.pole) + shift,
        v_pole=rot(states.v_pole),
        rotation_ref=Q @ states.rotation_ref,
        com_ref=rot(states.com_ref) + shift,
        pole_ref=rot(states.pole_ref) + shift,
    )


@PROPERTY_SETTINGS
@given(seed=seeds, n_poses=sizes, n_segments=sizes)
def test_exact_equivalents_agree_to_1e12(seed: int, n_poses: int, n_segments: int) -> None:
    states = random_states(np.random.default_rng(seed), n_poses, n_segments)
    exact = FORMULAS["exact"](states)
    for name in EXACT_EQUIVALENTS:
        np.testing.assert_allclose(FORMULAS[name](states), exact, rtol=1e-12, err_msg=name)


@PROPERTY_SETTINGS
@given(seed=seeds, n_poses=sizes, n_segments=sizes)
def test_exact_is_invariant_under_change_of_world_frame(seed: int, n_poses: int, n_segments: int) -> None:
    rng = np.random.default_rng(seed)
    states = random_states(rng, n_poses, n_segments)
    Q = random_states(rng, 1, 1).rotation[0, 0]
    moved = _rotate_world(states, Q, rng.normal(size=3) * 10)
    np.testing.assert_allclose(FORMULAS["exact"](moved), FORMULAS["exact"](states), rtol=1e-12)


@PROPERTY_SETTINGS
@given(seed=seeds, alpha=st.floats(min_value=-50, max_value=50, allow_nan=False).filter(lambda a: abs(a) > 1e-3))
def test_exact_scales_as_alpha_squared(seed: int, alpha: float) -> None:
    states = random_states(np.random.default_rng(seed), 3, 4)
    scaled = states.with_motion(v_com=alpha * states.v_com, omega=alpha * states.omega, v_pole=alpha * states.v_pole)
    np.testing.assert_allclose(FORMULAS["exact"](scaled), alpha**2 * FORMULAS["exact"](states), rtol=1e-12)


@PROPERTY_SETTINGS
@given(seed=seeds, n_poses=sizes, n_segments=sizes)
def test_exact_family_is_non_negative(seed: int, n_poses: int, n_segments: int) -> None:
    states = random_states(np.random.default_rng(seed), n_poses, n_segments)
    for name in NON_NEGATIVE:
        assert (FORMULAS[name](states) >= 0).all(), name


@PROPERTY_SETTINGS
@given(seed=seeds)
def test_zero_velocity_gives_zero_energy_for_every_formula(seed: int) -> None:
    states = random_states(np.random.default_rng(seed), 4, 3)
    still = states.with_motion(
        v_com=np.zeros_like(states.v_com),
        omega=np.zeros_like(states.omega),
        v_pole=np.zeros_like(states.v_pole),
    )
    for name, formula in FORMULAS.items():
        value = formula(still, angles=np.zeros((4, 3, 3)))
        np.testing.assert_array_equal(value, 0.0, err_msg=name)
