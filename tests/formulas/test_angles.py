from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas.analytic import constant_rotation_states, random_rotations, rigid_states
from koenig_check.formulas.angles import (
    euler_xyz_angles,
    integrate_angular_velocity,
    paper_angles,
    rotvec_angles,
)
from koenig_check.formulas.paper_section3 import angular_velocity_39, rotation_39


def _single(R: np.ndarray, R_ref: np.ndarray | None = None):
    P = R.shape[0]
    return rigid_states(
        np.ones(1),
        np.eye(3)[None],
        R[:, None],
        np.zeros((P, 1, 3)),
        np.zeros((P, 1, 3)),
        rotation_ref=None if R_ref is None else R_ref[None],
    )


def test_rotvec_of_a_turn_about_a_world_axis(rng: np.random.Generator) -> None:
    R_ref = random_rotations(rng, ())
    axis = np.array([0.6, 0.0, 0.8])
    states = constant_rotation_states(1.0, np.eye(3), 0.9 * axis, np.linspace(0, 2, 5), rotation_ref=R_ref)
    np.testing.assert_allclose(rotvec_angles(states)[:, 0], np.linspace(0, 2, 5)[:, None] * 0.9 * axis, atol=1e-12)


def test_euler_xyz_is_extrinsic_x_then_y_then_z() -> None:
    a, b, c = 0.3, -0.4, 1.1
    Rx = rotation_39(0.0, a)
    Rz = rotation_39(c, 0.0)
    cb, sb = np.cos(b), np.sin(b)
    Ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    states = _single((Rz @ Ry @ Rx)[None])
    np.testing.assert_allclose(euler_xyz_angles(states)[0, 0], [a, b, c], atol=1e-12)


def _extrinsic_xyz(a: float, b: float, c: float) -> np.ndarray:
    """``R_z(c) R_y(b) R_x(a)`` by hand."""
    ca, sa, cb, sb, cc, sc = np.cos(a), np.sin(a), np.cos(b), np.sin(b), np.cos(c), np.sin(c)
    Rx = np.array([[1, 0, 0], [0, ca, -sa], [0, sa, ca]])
    Ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    Rz = np.array([[cc, -sc, 0], [sc, cc, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


@pytest.mark.parametrize("b", [np.pi / 2, -np.pi / 2])
def test_euler_xyz_at_gimbal_lock_sets_c_to_zero_among_ordinary_poses(b: float) -> None:
    """At |b| = π/2 only a ∓ c is defined: c is 0 and a carries it; the other poses of the batch are unaffected."""
    ordinary = (0.3, -0.4, 1.1)
    R = np.stack([_extrinsic_xyz(*ordinary), _extrinsic_xyz(0.4, b, 0.7), _extrinsic_xyz(*ordinary)])
    got = euler_xyz_angles(_single(R))[:, 0]
    np.testing.assert_allclose(got[[0, 2]], [ordinary, ordinary], atol=1e-12)
    assert got[1, 2] == 0.0
    np.testing.assert_allclose(got[1, 1], b, atol=1e-7)
    np.testing.assert_allclose(_extrinsic_xyz(*got[1]), R[1], atol=1e-12)


def test_integrated_angles_follow_the_path_not_the_state() -> None:
    """Along motion (39) the integral of ω differs from the rotation vector of the end state."""
    t = np.linspace(0.0, 1.0, 2001)
    R = rotation_39(1.3 * t, 0.8 * t)
    omega = angular_velocity_39(1.3 * t, np.full_like(t, 1.3), np.full_like(t, 0.8))
    states = rigid_states(np.ones(1), np.eye(3)[None], R[:, None], omega[:, None], np.zeros((t.size, 1, 3)))
    integrated = integrate_angular_velocity(states.omega, t)
    # The z component integrates exactly to 1.3 t; x, y follow the turning inner axis.
    np.testing.assert_allclose(integrated[-1, 0, 2], 1.3, rtol=1e-12)
    np.testing.assert_allclose(integrated[-1, 0, 0], 0.8 / 1.3 * np.sin(1.3), rtol=1e-6)
    assert np.abs(integrated[-1, 0] - rotvec_angles(states)[-1, 0]).max() > 1e-2


def test_integrate_validates_times() -> None:
    with pytest.raises(ValueError, match="strictly increasing"):
        integrate_angular_velocity(np.zeros((3, 1, 3)), np.array([0.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="does not match"):
        integrate_angular_velocity(np.zeros((3, 1, 3)), np.array([0.0, 1.0]))


def test_paper_angles_argument_rules(rng: np.random.Generator) -> None:
    states = _single(random_rotations(rng, (4,)))
    with pytest.raises(ValueError, match="needs the path integrals"):
        paper_angles(states, "integrated")
    with pytest.raises(ValueError, match=r"angles: shape"):
        paper_angles(states, "integrated", np.zeros((4, 2, 3)))
    for bad in (np.nan, np.inf):
        angles = np.zeros((4, 1, 3))
        angles[2, 0, 1] = bad
        with pytest.raises(ValueError, match="angles: non-finite"):
            paper_angles(states, "integrated", angles)
    with pytest.raises(ValueError, match="only used by convention 'integrated'"):
        paper_angles(states, "rotvec", np.zeros((4, 1, 3)))
    with pytest.raises(ValueError, match="unknown angle convention"):
        paper_angles(states, "quaternion")  # type: ignore[arg-type]
