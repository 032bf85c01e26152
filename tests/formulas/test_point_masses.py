from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS
from koenig_check.formulas.analytic import random_states
from koenig_check.formulas.point_masses import (
    equimomental_points,
    point_masses,
    point_world_positions,
    rigid_point_velocities,
)


def test_equimomental_set_reproduces_mass_com_and_inertia(rng: np.random.Generator) -> None:
    states = random_states(rng, 1, 50)
    offsets, masses = equimomental_points(states.mass, states.inertia_body)
    np.testing.assert_allclose(masses.sum(axis=1), states.mass, rtol=1e-14)
    np.testing.assert_allclose(np.einsum("bk,bki->bi", masses, offsets), 0.0, atol=1e-15)
    r2 = np.einsum("bki,bki->bk", offsets, offsets)
    inertia = np.einsum(
        "bk,bkij->bij",
        masses,
        r2[..., None, None] * np.eye(3) - offsets[..., :, None] * offsets[..., None, :],
    )
    np.testing.assert_allclose(inertia, states.inertia_body, rtol=1e-12, atol=1e-12 * np.abs(states.inertia_body).max())


def test_non_physical_inertia_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match=r"segment 'arm'.*triangle inequality"):
        equimomental_points(np.array([1.0]), np.diag([1.0, 1.0, 3.0])[None], names=("arm",))


def _central_difference_point_velocities(states, offsets: np.ndarray, h: float = 1e-5) -> np.ndarray:
    """(x(t+h) − x(t−h)) / 2h of the points ``C + R r`` along the rigid motion (v_C, ω) of ``states``."""
    from scipy.spatial.transform import Rotation

    P, B = states.n_poses, states.n_segments

    def moved(sign: float):
        turn = Rotation.from_rotvec(sign * h * states.omega.reshape(-1, 3)).as_matrix().reshape(P, B, 3, 3)
        return states.with_motion(com=states.com + sign * h * states.v_com, rotation=turn @ states.rotation)

    return (point_world_positions(moved(1.0), offsets) - point_world_positions(moved(-1.0), offsets)) / (2 * h)


def test_supplied_point_velocities_are_used(rng: np.random.Generator) -> None:
    """Velocities measured by differencing the point positions give eq. (10) = the rigid-body energy."""
    states = random_states(rng, 5, 2)
    offsets, _ = equimomental_points(states.mass, states.inertia_body)
    v = _central_difference_point_velocities(states, offsets)
    exact = FORMULAS["exact"](states)
    np.testing.assert_allclose(point_masses(states, v), exact, rtol=1e-8)
    np.testing.assert_allclose(point_masses(states, 2 * v), 4 * point_masses(states, v), rtol=1e-14)
    still = states.with_motion(omega=np.zeros_like(states.omega))  # same states, points moved without turning
    v_still = _central_difference_point_velocities(still, offsets)
    np.testing.assert_allclose(point_masses(states, v_still), 0.5 * states.mass * (states.v_com**2).sum(-1), rtol=1e-8)
    with pytest.raises(ValueError, match="point_velocities: shape"):
        point_masses(states, v[:, :, :3])


def test_rigid_point_velocities_match_finite_differences(rng: np.random.Generator) -> None:
    """v = v_C + ω × (R r) against the finite difference of C + R r along the rigid motion."""
    from scipy.spatial.transform import Rotation

    states = random_states(rng, 1, 3)
    offsets, _ = equimomental_points(states.mass, states.inertia_body)
    h = 1e-6
    dR = Rotation.from_rotvec(h * states.omega[0]).as_matrix()
    later = states.with_motion(com=states.com + h * states.v_com, rotation=dR[None] @ states.rotation)
    fd = (point_world_positions(later, offsets) - point_world_positions(states, offsets)) / h
    np.testing.assert_allclose(fd, rigid_point_velocities(states, offsets), rtol=1e-5, atol=1e-5)
