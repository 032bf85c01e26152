"""Small batched vector kernels, faster than their generic numpy forms on (..., 3) arrays.

``numpy.cross`` and ``numpy.einsum`` with a broadcast matrix operand are general but slow on
millions of 3-vectors; these do the same arithmetic with elementwise operations and ``matmul``.
"""

from __future__ import annotations

import numpy as np


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product over the last axis, broadcasting like ``numpy.cross``.

    Parameters
    ----------
    a, b : ndarray, shape (..., 3)

    Returns
    -------
    ndarray, shape (..., 3)
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def rotate(R: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R v`` for batches of matrices and vectors: ``einsum("...ij,...j->...i")``.

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)
    v : ndarray, shape (..., 3), broadcastable against ``R``'s batch axes

    Returns
    -------
    ndarray, shape (..., 3)
    """
    out = np.empty(np.broadcast_shapes(R.shape[:-1], v.shape))
    v0, v1, v2 = v[..., 0], v[..., 1], v[..., 2]
    for i in range(3):  # elementwise: a stacked 3 x 3 matmul pays a per-matrix overhead
        o = out[..., i]
        np.multiply(R[..., i, 0], v0, out=o)
        o += R[..., i, 1] * v1
        o += R[..., i, 2] * v2
    return out


def rotate_points(R: np.ndarray, points: np.ndarray) -> np.ndarray:
    """``R r_k`` for K points per matrix: ``einsum("pbij,bkj->pbki")``.

    Parameters
    ----------
    R : ndarray, shape (P, B, 3, 3)
    points : ndarray, shape (B, K, 3)

    Returns
    -------
    ndarray, shape (P, B, K, 3)
    """
    return np.swapaxes(R @ np.swapaxes(points, -1, -2)[None], -1, -2)


def congruence(R: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """``R I Rᵀ`` for batches of rotations and symmetric matrices, symmetric by construction.

    One ``matmul`` for ``A = R I``, then the six distinct entries of ``A Rᵀ`` elementwise
    (``matmul`` of stacked 3 × 3 matrices pays a per-matrix overhead that dominates here).

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)
    inertia : ndarray, shape (..., 3, 3), broadcastable against ``R``; symmetric

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    A = R @ inertia
    out = np.empty(A.shape)
    for i in range(3):
        for j in range(i, 3):
            v = A[..., i, 0] * R[..., j, 0] + A[..., i, 1] * R[..., j, 1] + A[..., i, 2] * R[..., j, 2]
            out[..., i, j] = v
            if i != j:
                out[..., j, i] = v
    return out


def times_transpose(R: np.ndarray, R_ref: np.ndarray) -> np.ndarray:
    """``R R_refᵀ`` for a batch ``R`` (..., 3, 3) and matrices ``R_ref`` broadcast against it, elementwise.

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)
    R_ref : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    out = np.empty(np.broadcast_shapes(R.shape, R_ref.shape))
    for i in range(3):
        for j in range(3):
            out[..., i, j] = (
                R[..., i, 0] * R_ref[..., j, 0] + R[..., i, 1] * R_ref[..., j, 1] + R[..., i, 2] * R_ref[..., j, 2]
            )
    return out


def body_point_velocities(v_com: np.ndarray, omega: np.ndarray, R: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """Velocities of points fixed in rigid segments, ``v_C + ω × (R r_k)``.

    Elementwise on component planes (no stacked 3 × 3 ``matmul``); the result is a (P, B, K, 3)
    view of contiguous (K, 3, P, B) planes.  A point set symmetric about the centre of mass (the
    second half the negated first half, as the equimomental points) costs half:
    ``v_C ± ω × (R r_k)``.

    Parameters
    ----------
    v_com, omega : ndarray, shape (P, B, 3)
        Centre-of-mass velocity and angular velocity, world frame.
    R : ndarray, shape (P, B, 3, 3)
        World ← segment.
    offsets : ndarray, shape (B, K, 3)
        From the centre of mass, segment axes.

    Returns
    -------
    ndarray, shape (P, B, K, 3)
    """
    K = offsets.shape[1]
    half = K // 2
    symmetric = K % 2 == 0 and np.array_equal(offsets[:, half:], -offsets[:, :half])
    Rc = components(R.reshape(*R.shape[:-2], 9))
    w, v = components(omega), components(v_com)
    out = np.empty((K, 3, *v.shape[1:]))
    for k in range(half if symmetric else K):
        r = offsets[:, k]
        a = [Rc[3 * i] * r[:, 0] + Rc[3 * i + 1] * r[:, 1] + Rc[3 * i + 2] * r[:, 2] for i in range(3)]  # R r_k
        u = (w[1] * a[2] - w[2] * a[1], w[2] * a[0] - w[0] * a[2], w[0] * a[1] - w[1] * a[0])  # ω × R r_k
        for i in range(3):
            np.add(v[i], u[i], out=out[k, i])
            if symmetric:
                np.subtract(v[i], u[i], out=out[k + half, i])
    return np.moveaxis(out, (0, 1), (2, 3))


def components(a: np.ndarray) -> np.ndarray:
    """The last axis moved first, contiguous: (..., K) → (K, ...), one plane per component.

    Parameters
    ----------
    a : ndarray, shape (..., K)

    Returns
    -------
    ndarray, shape (K, ...)
    """
    return np.ascontiguousarray(np.moveaxis(a, -1, 0), dtype=float)


def inertia_world_components(R: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """The six unique entries of ``R I Rᵀ`` from component planes, elementwise.

    Parameters
    ----------
    R : ndarray, shape (9, P, B)
        Row-major entries of the rotations.
    inertia : ndarray, shape (B, 3, 3)
        Symmetric matrices (segment axes), the same at every pose.

    Returns
    -------
    ndarray, shape (6, P, B)
        ``(xx, yy, zz, yz, xz, xy)``.
    """
    A = np.empty((3, 3, *R.shape[1:]))  # A = R I
    for i in range(3):
        for k in range(3):
            A[i, k] = R[3 * i] * inertia[:, 0, k] + R[3 * i + 1] * inertia[:, 1, k] + R[3 * i + 2] * inertia[:, 2, k]
    out = np.empty((6, *R.shape[1:]))
    for n, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))):
        out[n] = A[i, 0] * R[3 * j] + A[i, 1] * R[3 * j + 1] + A[i, 2] * R[3 * j + 2]
    return out


def times_transpose_components(R: np.ndarray, R_ref: np.ndarray) -> np.ndarray:
    """``R R_refᵀ`` from component planes: ``R`` (9, P, B), ``R_ref`` (B, 3, 3) → (9, P, B).

    Parameters
    ----------
    R : ndarray, shape (9, ...)
        Row-major entries.
    R_ref : ndarray, shape (B, 3, 3)
        Broadcast against the last axis of ``R``'s planes.

    Returns
    -------
    ndarray, shape (9, ...)
    """
    out = np.empty(R.shape)
    for i in range(3):
        for j in range(3):
            out[3 * i + j] = R[3 * i] * R_ref[:, j, 0] + R[3 * i + 1] * R_ref[:, j, 1] + R[3 * i + 2] * R_ref[:, j, 2]
    return out
