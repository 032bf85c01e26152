"""The batched kernels give what the generic numpy forms give."""

from __future__ import annotations

import numpy as np

from koenig_check.analytic import random_rotations
from koenig_check.kernels import body_point_velocities, congruence, cross, rotate, rotate_points, times_transpose


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
