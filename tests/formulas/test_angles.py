from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas.analytic import constant_rotation_states, random_rotations, rigid_states
from koenig_check.formulas.angles import (
    euler_xyz_angles,
    euler_xyz_double_angles,
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


def _entries(R: np.ndarray) -> np.ndarray:
    """Row-major entries of a stack of matrices as planes (9, n)."""
    return np.ascontiguousarray(R.reshape(-1, 9).T)


def test_euler_xyz_double_angles_are_sin_and_cos_of_twice_the_hand_angles(rng: np.random.Generator) -> None:
    """sin 2θ and cos 2θ of each extrinsic angle, read from the matrix entries without the angles.

    The expected values are those of the angles the matrices are built from (by hand, :func:`_extrinsic_xyz`);
    |b| stays below π/2 − 0.07, where a and c are determined to a few ulps over cos b.
    """
    angles = np.column_stack(
        [rng.uniform(-np.pi, np.pi, 300), rng.uniform(-1.5, 1.5, 300), rng.uniform(-np.pi, np.pi, 300)]
    )
    angles[:3] = [[0.0, 0.0, 0.0], [np.pi / 2, 0.0, -np.pi / 2], [np.pi, 0.0, np.pi / 4]]
    R = np.stack([_extrinsic_xyz(*abc) for abc in angles])
    sin2, cos2 = euler_xyz_double_angles(_entries(R))
    np.testing.assert_allclose(sin2, np.sin(2 * angles).T, atol=1e-13)
    np.testing.assert_allclose(cos2, np.cos(2 * angles).T, atol=1e-13)
    one_sin, one_cos = euler_xyz_double_angles(_entries(R[3:4])[:, 0])  # one matrix, entries (9,)
    np.testing.assert_allclose(one_sin, np.sin(2 * angles[3]), atol=1e-13)
    np.testing.assert_allclose(one_cos, np.cos(2 * angles[3]), atol=1e-13)


@pytest.mark.parametrize("b", [np.pi / 2, -np.pi / 2])
def test_euler_xyz_double_angles_at_gimbal_lock(b: float) -> None:
    """At |b| = π/2, c = 0 (sin 0, cos 0) and a carries a ∓ c, as the angles themselves (by hand)."""
    a, c = 0.4, 0.7
    carried = a - c if b > 0 else a + c
    R = np.stack([_extrinsic_xyz(0.3, -0.4, 1.1), _extrinsic_xyz(a, b, c)])
    sin2, cos2 = euler_xyz_double_angles(_entries(R))
    np.testing.assert_allclose(sin2[:, 1], [np.sin(2 * carried), 0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(cos2[:, 1], [np.cos(2 * carried), -1.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(sin2[:, 0], np.sin(2 * np.array([0.3, -0.4, 1.1])), atol=1e-13)


def test_euler_xyz_double_angles_of_undefined_angles_and_nan() -> None:
    """Where both entries of an angle vanish atan2 gives 0: (sin, cos) = (0, 1); a NaN entry stays NaN."""
    sin2, cos2 = euler_xyz_double_angles(np.zeros((9, 2)))
    np.testing.assert_array_equal(sin2, 0.0)
    np.testing.assert_array_equal(cos2, 1.0)
    r = _entries(np.eye(3)[None])
    r[7] = np.nan  # a = atan2(r₇, r₈)
    sin2, cos2 = euler_xyz_double_angles(r)
    assert np.isnan(sin2[0, 0]) and np.isnan(cos2[0, 0])
    np.testing.assert_array_equal(sin2[1:, 0], 0.0)


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
