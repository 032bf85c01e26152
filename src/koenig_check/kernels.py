"""Small batched vector kernels, faster than their generic numpy forms on (..., 3) arrays.

``numpy.cross`` and ``numpy.einsum`` with a broadcast matrix operand are general but slow on
millions of 3-vectors; these do the same arithmetic with elementwise operations and ``matmul``.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

#: Target length of a row of folded component planes (see :func:`fold`).
_ROW = 2048
#: Elements per plane in one block of a transposing copy (see :func:`matrix_components`).
_BLOCK = 1024
#: ``numpy.einsum`` subscripts of ``Σ_k a[k] b[k]`` over stacked planes, ``b`` broadcast from the right (tiled
#: constants): :func:`dot3`'s sum in its order of terms, in one pass (each element read once, not five passes).
ROWS = "k...,k...->..."


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

    Elementwise on component planes (no stacked 3 × 3 ``matmul``), written into preallocated
    buffers; the result is a (P, B, K, 3) view of contiguous (K, 3, P, B) planes.  A point set
    symmetric about the centre of mass (the second half the negated first half, as the
    equimomental points) costs half: ``v_C ± ω × (R r_k)``.

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
    batch = v_com.shape[:-1]
    Rc, k = fold(matrix_components(R))
    w, v = fold(components(omega))[0], fold(components(v_com))[0]
    r = tile(np.moveaxis(np.asarray(offsets, dtype=float), 0, -1), k)  # (K, 3, k B)
    out = np.empty((K, 3, *batch))
    folded = out.reshape(K, 3, *Rc.shape[1:])
    a, tmp = np.empty((3, *Rc.shape[1:])), np.empty(Rc.shape[1:])
    for n in range(half if symmetric else K):
        for i in range(3):  # a = R r_n
            np.einsum(ROWS, Rc[3 * i : 3 * i + 3], r[n], out=a[i])
        for i, j, l in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):  # u_i = w_j a_l − w_l a_j = (ω × R r_n)_i
            u = folded[n, i]
            np.multiply(w[j], a[l], out=u)
            np.multiply(w[l], a[j], out=tmp)
            u -= tmp
            if symmetric:
                np.subtract(v[i], u, out=folded[n + half, i])
            np.add(v[i], u, out=u)
    return np.moveaxis(out, (0, 1), (2, 3))


def components(a: np.ndarray) -> np.ndarray:
    """The last axis moved first, contiguous: (..., K) → (K, ...), one plane per component.

    An array that already is a view of contiguous planes is returned without a copy.

    Parameters
    ----------
    a : ndarray, shape (..., K)

    Returns
    -------
    ndarray, shape (K, ...)
    """
    return np.ascontiguousarray(np.moveaxis(a, -1, 0), dtype=float)


def matrix_components(R: np.ndarray) -> np.ndarray:
    """Row-major entries of a batch of matrices as contiguous planes: (..., 3, 3) → (9, ...).

    ``components(R.reshape(..., 9))`` without the intermediate copy that ``reshape`` makes of a
    non-contiguous batch; no copy at all when ``R`` already is a view of such planes.

    Parameters
    ----------
    R : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (9, ...)
    """
    moved = np.moveaxis(R, (-2, -1), (0, 1))
    if moved.flags.c_contiguous and moved.dtype == np.float64:
        return moved.reshape(9, *R.shape[:-2])
    return _copy_planes(moved, 2).reshape(9, *R.shape[:-2])


def _copy_planes(moved: np.ndarray, n_components: int = 1) -> np.ndarray:
    """A contiguous copy of component planes (its first ``n_components`` axes the components), in blocks.

    The copy is a transposition when the source is not pose-major (the engines' per-segment
    arrays are often segment-major); blocks of the first batch axis of about a thousand elements
    per plane keep the source lines they read in cache for every component, which a single
    whole-array copy does not.
    """
    out = np.empty(moved.shape)
    batch = moved.shape[n_components:]
    if not batch:
        out[...] = moved
        return out
    rows = max(1, _BLOCK // max(math.prod(batch[1:]), 1))
    lead = (slice(None),) * n_components
    for start in range(0, batch[0], rows):
        block = (*lead, slice(start, start + rows))
        out[block] = moved[block]
    return out


@lru_cache(maxsize=256)
def _tile_factor(n_batch: int, n_segments: int) -> int:
    """The largest divisor ``k`` of ``n_batch`` with ``k * n_segments <= _ROW`` (at least 1)."""
    limit = max(1, _ROW // max(n_segments, 1))
    for k in range(min(limit, n_batch), 0, -1):
        if n_batch % k == 0:
            return k
    return 1


def fold(planes: np.ndarray) -> tuple[np.ndarray, int]:
    """View contiguous planes (n, ..., B) as (n, M // k, k B) rows, for tiled constants (:func:`tile`).

    A per-segment constant broadcast over the last axis of (P, B) planes makes numpy's inner loop
    only ``B`` long (several times the cost of a plain elementwise pass for a few segments).  With
    the ``M`` batch entries folded ``k`` at a time into rows of ``k B`` and the constant tiled ``k``
    times, every element meets the same constant in a long inner loop: the same numbers, faster.
    ``k`` is the largest divisor of ``M`` with ``k B <= 2048`` (1 when ``M`` is prime and large).

    Parameters
    ----------
    planes : ndarray, shape (n, ..., B), C-contiguous

    Returns
    -------
    folded : ndarray, shape (n, M // k, k B)
        A view of ``planes``.
    k : int
    """
    B = planes.shape[-1]
    M = math.prod(planes.shape[1:-1])
    k = _tile_factor(M, B)
    return planes.reshape(planes.shape[0], M // k, k * B), k


def tile(constants: np.ndarray, k: int) -> np.ndarray:
    """Per-segment constants (..., B) repeated ``k`` times along the last axis, to meet folded planes (:func:`fold`).

    Parameters
    ----------
    constants : ndarray, shape (..., B)
    k : int

    Returns
    -------
    ndarray, shape (..., k B)
    """
    out = np.empty((*constants.shape[:-1], k, constants.shape[-1]))
    out[...] = constants[..., None, :]
    return out.reshape(*constants.shape[:-1], -1)


def inertia_world_components(R: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """The six unique entries of ``R I Rᵀ`` from component planes, elementwise.

    ``A = R I`` then ``A Rᵀ``, each entry a sum of three products in index order, written into
    preallocated buffers on folded planes (:func:`fold`).

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
    Rf, k = fold(R)
    I = tile(np.moveaxis(np.asarray(inertia, dtype=float), 0, -1), k)  # (3, 3, k B): I[j, c] = inertia[:, j, c]
    shape = Rf.shape[1:]
    A, tmp = np.empty((3, 3, *shape)), np.empty(shape)  # A = R I
    for i in range(3):
        for c in range(3):
            np.einsum(ROWS, Rf[3 * i : 3 * i + 3], I[:, c], out=A[i, c])
    out = np.empty((6, *R.shape[1:]))
    folded = out.reshape(6, *shape)
    for n, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))):
        dot3(A[i, 0], A[i, 1], A[i, 2], Rf[3 * j], Rf[3 * j + 1], Rf[3 * j + 2], folded[n], tmp)
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
    Rf, k = fold(R)
    ref = tile(np.moveaxis(np.asarray(R_ref, dtype=float), 0, -1), k)  # (3, 3, k B)
    out = np.empty(R.shape)
    folded = out.reshape(Rf.shape)
    for i in range(3):
        for j in range(3):
            np.einsum(ROWS, Rf[3 * i : 3 * i + 3], ref[j], out=folded[3 * i + j])
    return out


def dot3(
    a0: np.ndarray,
    a1: np.ndarray,
    a2: np.ndarray,
    b0: np.ndarray,
    b1: np.ndarray,
    b2: np.ndarray,
    out: np.ndarray | None = None,
    tmp: np.ndarray | None = None,
) -> np.ndarray:
    """``a0 b0 + a1 b1 + a2 b2`` of planes, summed left to right (broadcasting), into ``out`` if given.

    The order of the plain expression ``a0 * b0 + a1 * b1 + a2 * b2``, hence its numbers, with one
    scratch plane instead of a temporary per term.

    Parameters
    ----------
    a0, a1, a2, b0, b1, b2 : ndarray
        Planes (or per-segment constants) broadcasting to the result's shape.
    out : ndarray, optional
        Where to write the result (not one of the inputs).
    tmp : ndarray, optional
        The scratch plane, of the result's shape (allocated if not given).

    Returns
    -------
    ndarray
    """
    first = np.multiply(a0, b0, out=out)
    tmp = np.multiply(a1, b1, out=tmp)
    first += tmp
    np.multiply(a2, b2, out=tmp)
    first += tmp
    return first


def scale(planes: np.ndarray, constants: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """``planes * constants`` for per-segment constants broadcast over the last axis, folded when possible.

    The same numbers as the broadcast product; on C-contiguous planes the product runs on
    rows folded by :func:`fold` against constants tiled by :func:`tile`.

    Parameters
    ----------
    planes : ndarray, shape (..., B)
    constants : ndarray, shape (B,)
    out : ndarray, shape of ``planes``, optional

    Returns
    -------
    ndarray, shape of ``planes``
    """
    shape = planes.shape
    if out is None:
        out = np.empty(shape)
    if len(shape) < 2 or planes.size == 0 or not (planes.flags.c_contiguous and out.flags.c_contiguous):
        return np.multiply(planes, constants, out=out)
    B = shape[-1]
    M = planes.size // B
    k = _tile_factor(M, B)
    if k == 1:
        return np.multiply(planes, constants, out=out)
    rows = (M // k, k * B)
    np.multiply(planes.reshape(rows), tile(constants, k), out=out.reshape(rows))
    return out
