"""The per-state cache shared by the formulas: every formula through it equals the formula alone."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from koenig_check.formulas import FORMULAS, integrate_angular_velocity
from koenig_check.formulas.analytic import random_rotations, random_states
from koenig_check.formulas.angles import euler_xyz_of, quaternion_of, rotvec_of
from koenig_check.formulas.cache import SharedStates


def _evaluate(name: str, states, angles):
    try:
        return FORMULAS[name](states, angles=angles)
    except ValueError as err:  # planar refuses off-plane motion: the refusal must be the same
        return str(err)


@pytest.mark.parametrize("order", ["registry", "reversed"])
def test_every_formula_through_the_shared_cache_equals_the_formula_alone(rng: np.random.Generator, order) -> None:
    states = random_states(rng, n_poses=40, n_segments=5)
    angles = integrate_angular_velocity(states.omega, np.linspace(0.0, 1.0, states.n_poses))
    names = list(FORMULAS) if order == "registry" else list(reversed(FORMULAS))
    shared = SharedStates(states)
    through_cache = {name: _evaluate(name, shared, angles) for name in names}
    assert len(shared._memo) >= 8  # the derived arrays really are shared
    for name in FORMULAS:
        alone = _evaluate(name, states, angles)
        if isinstance(alone, str):
            assert through_cache[name] == alone
        else:
            np.testing.assert_array_equal(through_cache[name], alone, err_msg=name)


@pytest.mark.parametrize("name", [n for n in FORMULAS if n != "planar"])
def test_each_formula_first_in_a_fresh_cache_equals_the_formula_alone(rng: np.random.Generator, name: str) -> None:
    """Filled by the formula itself, then read back by a second call: both equal the formula alone."""
    states = random_states(rng, n_poses=16, n_segments=3)
    angles = integrate_angular_velocity(states.omega, np.linspace(0.0, 1.0, states.n_poses))
    shared = SharedStates(states)
    alone = FORMULAS[name](states, angles=angles)
    np.testing.assert_array_equal(FORMULAS[name](shared, angles=angles), alone)
    np.testing.assert_array_equal(FORMULAS[name](shared, angles=angles), alone)


def _hard_rotations(rng: np.random.Generator) -> np.ndarray:
    R = random_rotations(rng, (200,))
    axes = rng.normal(size=(60, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.concatenate([np.full(20, np.pi), np.pi - np.logspace(-9, -2, 20), np.logspace(-12, -2, 20)])
    near = Rotation.from_rotvec(axes * angles[:, None]).as_matrix()
    return np.concatenate([R, near, np.eye(3)[None]])


def test_numpy_rotation_vectors_match_scipy(rng: np.random.Generator) -> None:
    R = _hard_rotations(rng)
    expected = Rotation.from_matrix(R).as_rotvec()
    got = rotvec_of(R)
    # At exactly π the axis sign is arbitrary: compare the rotations they describe.
    np.testing.assert_allclose(Rotation.from_rotvec(got).as_matrix(), R, atol=1e-12)
    regular = np.linalg.norm(expected, axis=1) < np.pi - 1e-6
    np.testing.assert_allclose(got[regular], expected[regular], atol=1e-12)
    q = quaternion_of(R)
    np.testing.assert_allclose(np.linalg.norm(q, axis=-1), 1.0, rtol=1e-14)
    assert np.all(q[:, 3] >= 0)


def test_numpy_euler_angles_match_scipy(rng: np.random.Generator) -> None:
    R = _hard_rotations(rng)
    np.testing.assert_allclose(euler_xyz_of(R), Rotation.from_matrix(R).as_euler("xyz"), atol=1e-10)
    a, c = 0.4, 0.0  # gimbal lock: b = ±π/2, c set to 0, a carries the rest
    for b in (np.pi / 2, -np.pi / 2):
        lock = Rotation.from_euler("xyz", [a, b, c]).as_matrix()
        np.testing.assert_allclose(Rotation.from_euler("xyz", euler_xyz_of(lock)).as_matrix(), lock, atol=1e-12)


@pytest.mark.parametrize("name", ["alyushin_paper:integrated", "alyushin_pole:paper:integrated"])
def test_other_integrated_angles_on_the_same_cache_are_not_served_stale(rng: np.random.Generator, name: str) -> None:
    """Two different angle sets given as temporaries (lists): the second must not get the first's entries."""
    states = random_states(rng, n_poses=12, n_segments=3)
    first = integrate_angular_velocity(states.omega, np.linspace(0.0, 1.0, states.n_poses))
    second = 2.0 * first
    shared = SharedStates(states)
    for angles in (first, second, first):
        np.testing.assert_array_equal(
            FORMULAS[name](shared, angles=angles.tolist()), FORMULAS[name](states, angles=angles)
        )


def test_values_per_model_are_computed_once_per_constants_read_only_and_not_kept_on_error() -> None:
    """per_model: equal constants (another chunk of the model) reuse the value; other constants compute afresh."""
    from koenig_check.formulas.cache import per_model

    calls: list[int] = []

    def compute(a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        calls.append(1)
        return a * 2.0, a + 1.0

    a = np.arange(6.0).reshape(2, 3)
    first = per_model("test:double", (a,), lambda: compute(a))
    again = per_model("test:double", (a.copy(),), lambda: compute(a))  # equal values, another array
    assert again is first and len(calls) == 1
    assert not first[0].flags.writeable and not first[1].flags.writeable
    other = a.copy()
    other[1, 2] = 7.0
    np.testing.assert_array_equal(per_model("test:double", (other,), lambda: compute(other))[0], other * 2.0)
    assert per_model("test:other-name", (a,), lambda: compute(a)) is not first and len(calls) == 3

    def failing() -> None:
        calls.append(1)
        raise ValueError("non-physical")

    for _ in range(2):  # an error is raised every time, not kept
        with pytest.raises(ValueError, match="non-physical"):
            per_model("test:failing", (a,), failing)
    assert len(calls) == 5
