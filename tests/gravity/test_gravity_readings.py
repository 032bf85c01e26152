"""Each engine's g(q) and V(q) - V(q_ref) on the two-link arm against the hand computation (gravity_arm.py)."""

from __future__ import annotations

import numpy as np
import pytest
from gravity_arm import arm_xml, engines_of, fixed_gravity, free_gravity

from koenig_check.engines.registry import installed
from koenig_check.gravity.readings import read_gravity

_NO_DRAKE = pytest.mark.skipif(not installed("drake"), reason="Drake is not installed")
ENGINES = ["mujoco", "pinocchio", pytest.param("drake", marks=_NO_DRAKE)]
G = np.array([0.0, 0.0, -9.81])  # no <option>: every engine's default
#: g(q) is a few tens of newton-metres here: 1e-12 relative is round-off.
RTOL = 1e-12


def _poses(n: int, free: bool) -> np.ndarray:
    rng = np.random.default_rng(7)
    q = rng.uniform(-np.pi, np.pi, size=(n, 2))
    if not free:
        return q
    quat = rng.normal(size=(n, 4))
    quat /= np.linalg.norm(quat, axis=1, keepdims=True)
    return np.hstack([rng.normal(size=(n, 3)), quat, q])


@pytest.mark.parametrize("engine", ENGINES)
def test_fixed_arm_by_hand(engine: str, write) -> None:
    loaded = engines_of(write(arm_xml()))
    q = _poses(9, free=False)
    r = read_gravity(loaded.engines[engine], q, loaded.mujoco.model.qpos0)
    g, V = fixed_gravity(q, G)
    V0 = fixed_gravity(np.zeros((1, 2)), G)[1]
    np.testing.assert_allclose(r.vector, G, rtol=0, atol=0)
    np.testing.assert_allclose(r.g, g, rtol=RTOL, atol=RTOL * np.abs(g).max())
    np.testing.assert_allclose(r.dv_gravity, V - V0, rtol=RTOL, atol=RTOL * np.abs(V).max())
    assert np.all(r.dv_springs == 0.0) or np.abs(r.dv_springs).max() < 1e-12 * np.abs(V).max()


@pytest.mark.parametrize("engine", ENGINES)
def test_free_base_by_hand_in_canonical_coordinates(engine: str, write) -> None:
    """The free joint's rows are MuJoCo's (world force, torque in the base's axes), whatever the engine's own."""
    loaded = engines_of(write(arm_xml(free=True)))
    q = _poses(7, free=True)
    r = read_gravity(loaded.engines[engine], q, loaded.mujoco.model.qpos0)
    g = free_gravity(q, G)
    np.testing.assert_allclose(r.g, g, rtol=RTOL, atol=RTOL * np.abs(g).max())
    assert np.abs(g[:, 3:6]).max() > 1.0  # the torque rows are not trivially zero


@pytest.mark.parametrize("engine", ENGINES)
def test_springs_are_not_gravity(engine: str, write) -> None:
    """Joint springs change neither g(q) nor the gravity part of V; MuJoCo counts their energy apart."""
    loaded = engines_of(write(arm_xml(spring=' stiffness="40" springref="0.3"')))
    q = _poses(6, free=False)
    r = read_gravity(loaded.engines[engine], q, loaded.mujoco.model.qpos0)
    g, V = fixed_gravity(q, G)
    np.testing.assert_allclose(r.g, g, rtol=RTOL, atol=RTOL * np.abs(g).max())
    np.testing.assert_allclose(r.dv_gravity, V - fixed_gravity(np.zeros((1, 2)), G)[1], rtol=RTOL, atol=1e-12)
    if engine == "mujoco":  # ½ k (q - ref)² per joint, against q_ref = 0
        springs = 0.5 * 40 * (((q - 0.3) ** 2).sum(axis=1) - 2 * 0.3**2)
        np.testing.assert_allclose(r.dv_springs, springs, rtol=RTOL, atol=1e-12)
