"""The batched kernels give what the generic numpy forms give."""

from __future__ import annotations

import numpy as np

from koenig_check.analytic import random_rotations
from koenig_check.kernels import (
    body_point_velocities,
    components,
    congruence,
    cross,
    inertia_world_components,
    rotate,
    rotate_points,
    times_transpose,
    times_transpose_components,
)


def test_kernels_match_their_generic_forms(rng: np.random.Generator) -> None:
    R = random_rotations(rng, (5, 4))
    R_ref = random_rotations(rng, (4,))
    v = rng.normal(size=(5, 4, 3))
    pts = rng.normal(size=(4, 6, 3))
    I = rng.normal(size=(4, 3, 3))
    I = I + np.swapaxes(I, -1, -2)
    np.testing.assert_allclose(cross(v, v[::-1]), np.cross(v, v[::-1]), rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(rotate(R, v), np.einsum("pbij,pbj->pbi", R, v), rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(rotate_points(R, pts), np.einsum("pbij,bkj->pbki", R, pts), rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(congruence(R, I[None]), R @ I[None] @ np.swapaxes(R, -1, -2), rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(
        times_transpose(R, R_ref[None]), R @ np.swapaxes(R_ref, -1, -2)[None], rtol=1e-14, atol=1e-15
    )


def test_point_velocities_symmetric_and_general_sets(rng: np.random.Generator) -> None:
    R = random_rotations(rng, (5, 4))
    v_com, omega = rng.normal(size=(5, 4, 3)), rng.normal(size=(5, 4, 3))
    half = rng.normal(size=(4, 3, 3))
    for pts in (np.concatenate([half, -half], axis=1), rng.normal(size=(4, 6, 3)), half):
        expected = v_com[:, :, None] + np.cross(omega[:, :, None], np.einsum("pbij,bkj->pbki", R, pts))
        np.testing.assert_allclose(body_point_velocities(v_com, omega, R, pts), expected, rtol=1e-13, atol=1e-14)


def test_component_kernels_hand_computed() -> None:
    # A quarter turn about z: R maps x to y.  I = diag(1, 2, 3) plus a product of inertia 0.5 in xy.
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    I = np.array([[[1.0, 0.5, 0.0], [0.5, 2.0, 0.0], [0.0, 0.0, 3.0]]])
    planes = components(R.reshape(1, 1, 9))  # (9, P=1, B=1)
    assert planes.shape == (9, 1, 1) and planes.flags.c_contiguous
    np.testing.assert_array_equal(planes[:, 0, 0], R.ravel())
    # R I Rᵀ by hand: the x and y moments swap, the product of inertia changes sign.
    got = inertia_world_components(planes, I)[:, 0, 0]
    np.testing.assert_array_equal(got, [2.0, 1.0, 3.0, 0.0, 0.0, -0.5])  # xx, yy, zz, yz, xz, xy
    # R R_refᵀ with R_ref = R is the identity; with R_ref = 1 it is R.
    np.testing.assert_array_equal(times_transpose_components(planes, R[None])[:, 0, 0], np.eye(3).ravel())
    np.testing.assert_array_equal(times_transpose_components(planes, np.eye(3)[None])[:, 0, 0], R.ravel())


def test_component_kernels_match_generic_forms(rng: np.random.Generator) -> None:
    R = random_rotations(rng, (5, 4))
    R_ref = random_rotations(rng, (4,))
    I = rng.normal(size=(4, 3, 3))
    I = I + np.swapaxes(I, -1, -2)
    planes = components(R.reshape(5, 4, 9))
    full = R @ I[None] @ np.swapaxes(R, -1, -2)
    six = inertia_world_components(planes, I)
    for n, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))):
        np.testing.assert_allclose(six[n], full[..., i, j], rtol=1e-13, atol=1e-14)
    expected = (R @ np.swapaxes(R_ref, -1, -2)[None]).reshape(5, 4, 9)
    np.testing.assert_allclose(np.moveaxis(times_transpose_components(planes, R_ref), 0, -1), expected, atol=1e-15)
