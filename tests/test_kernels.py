"""The batched kernels give what the generic numpy forms give."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas.analytic import random_rotations
from koenig_check.formulas.terms import SYM6
from koenig_check.kernels import (
    ROWS,
    body_point_velocities,
    components,
    congruence,
    cross,
    fold,
    inertia_world_components,
    matrix_components,
    rotate,
    rotate_points,
    scale,
    tile,
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


def test_rows_subscripts_sum_the_three_terms_against_broadcast_rows(rng: np.random.Generator) -> None:
    """Σ_k a_k b_k over stacked planes, b broadcast from the right (tiled constants), within rounding of the terms."""
    out = np.empty(1)
    np.einsum(ROWS, np.array([[1.0], [2.0], [3.0]]), np.array([[4.0], [5.0], [-6.0]]), out=out)
    np.testing.assert_array_equal(out, -4.0)
    a, b = rng.normal(size=(3, 7, 10)), rng.normal(size=(3, 10))
    out = np.einsum(ROWS, a, b, out=np.empty((7, 10)))
    bound = 4 * np.finfo(float).eps * (np.abs(a[0] * b[0]) + np.abs(a[1] * b[1]) + np.abs(a[2] * b[2]))
    assert np.all(np.abs(out - (a[0] * b[0] + a[1] * b[1] + a[2] * b[2])) <= bound)


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


@pytest.mark.parametrize(("P", "B"), [(1, 1), (7, 3), (97, 5), (4096, 6), (1000, 32), (2, 2049), (0, 3), (5, 0)])
def test_folded_products_equal_the_broadcast_bit_for_bit(rng: np.random.Generator, P: int, B: int) -> None:
    planes = rng.normal(size=(2, P, B))
    c = rng.normal(size=B)
    folded, k = fold(planes)
    assert (planes.size == 0 or np.shares_memory(folded, planes)) and P % max(k, 1) == 0 and (k * B <= 2048 or k == 1)
    np.testing.assert_array_equal(folded * tile(c, k), (planes * c).reshape(folded.shape))
    np.testing.assert_array_equal(scale(planes[1], c), planes[1] * c)
    np.testing.assert_array_equal(scale(planes[1].T.copy().T, c), planes[1] * c)  # not contiguous: plain broadcast
    out = np.empty((P, B))
    assert scale(planes[0], c, out=out) is out
    np.testing.assert_array_equal(out, planes[0] * c)


def _layouts(a: np.ndarray) -> list[np.ndarray]:
    """The same (P, B, ...) values in the memory layouts the engines hand out: pose-major, segment-major, planes."""
    segment_major = np.ascontiguousarray(np.swapaxes(a, 0, 1)).swapaxes(0, 1)
    tail = a.ndim - 2
    planes = np.ascontiguousarray(np.moveaxis(a, tuple(range(2, a.ndim)), tuple(range(tail))))
    plane_backed = np.moveaxis(planes, tuple(range(tail)), tuple(range(2, a.ndim)))
    return [a, segment_major, plane_backed]


@pytest.mark.parametrize(("P", "B"), [(12, 5), (700, 3)])  # one block of the copy, several blocks
def test_component_planes_from_every_layout(rng: np.random.Generator, P: int, B: int) -> None:
    R = random_rotations(rng, (P, B))
    v = rng.normal(size=(P, B, 3))
    homogeneous = np.zeros((B, P, 4, 4))
    homogeneous[..., :3, :3] = np.swapaxes(R, 0, 1)
    expected_R = np.stack([R[..., i, j] for i in range(3) for j in range(3)])  # row-major entries, by hand
    for layout in [*_layouts(R), np.swapaxes(homogeneous, 0, 1)[..., :3, :3]]:
        got = matrix_components(layout)
        assert got.shape == (9, P, B) and got.flags.c_contiguous
        np.testing.assert_array_equal(got, expected_R)
    for layout in _layouts(v):
        got = components(layout)
        assert got.shape == (3, P, B) and got.flags.c_contiguous
        np.testing.assert_array_equal(got, np.stack([v[..., 0], v[..., 1], v[..., 2]]))
    # Arrays that already are views of contiguous planes are not copied.
    R_planes, v_planes = _layouts(R)[2], _layouts(v)[2]
    assert np.shares_memory(matrix_components(R_planes), R_planes)
    assert np.shares_memory(components(v_planes), v_planes)


@pytest.mark.parametrize("P", [1, 13, 64])
def test_planar_kernels_equal_the_plain_broadcast_expressions_bit_for_bit(rng: np.random.Generator, P: int) -> None:
    """The folded, buffered kernels do the plain expressions' arithmetic in the same order: equal to the bit."""
    B = 7
    R = random_rotations(rng, (P, B))
    R_ref = random_rotations(rng, (B,))
    I = rng.normal(size=(B, 3, 3))
    I = I + np.swapaxes(I, -1, -2)
    r = components(R.reshape(P, B, 9))
    A = [
        [r[3 * i] * I[:, 0, k] + r[3 * i + 1] * I[:, 1, k] + r[3 * i + 2] * I[:, 2, k] for k in range(3)]
        for i in range(3)
    ]
    six = [A[i][0] * r[3 * j] + A[i][1] * r[3 * j + 1] + A[i][2] * r[3 * j + 2] for i, j in SYM6]
    np.testing.assert_array_equal(inertia_world_components(r, I), np.stack(six))
    dR = [
        r[3 * i] * R_ref[:, j, 0] + r[3 * i + 1] * R_ref[:, j, 1] + r[3 * i + 2] * R_ref[:, j, 2]
        for i in range(3)
        for j in range(3)
    ]
    np.testing.assert_array_equal(times_transpose_components(r, R_ref), np.stack(dR))
    for v_com, omega, R_in in zip(
        _layouts(rng.normal(size=(P, B, 3))), _layouts(rng.normal(size=(P, B, 3))), _layouts(R), strict=True
    ):
        pts = rng.normal(size=(B, 3, 3))
        pts = np.concatenate([pts, -pts], axis=1)
        w, v = components(omega), components(v_com)
        expected = np.empty((6, 3, P, B))
        for n in range(3):
            a = [r[3 * i] * pts[:, n, 0] + r[3 * i + 1] * pts[:, n, 1] + r[3 * i + 2] * pts[:, n, 2] for i in range(3)]
            u = (w[1] * a[2] - w[2] * a[1], w[2] * a[0] - w[0] * a[2], w[0] * a[1] - w[1] * a[0])
            for i in range(3):
                expected[n, i], expected[n + 3, i] = v[i] + u[i], v[i] - u[i]
        got = body_point_velocities(v_com, omega, R_in, pts)
        np.testing.assert_array_equal(got, np.moveaxis(expected, (0, 1), (2, 3)))
        # and the independent route: v_C + ω × (R r) with numpy's cross and einsum
        reference = v_com[:, :, None] + np.cross(omega[:, :, None], np.einsum("pbij,bkj->pbki", R_in, pts))
        np.testing.assert_allclose(got, reference, rtol=1e-13, atol=1e-14)
