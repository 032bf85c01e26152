"""An engine's per-pose arrays as component planes, and the segment-state arithmetic on those planes.

An adapter copies each pose's engine arrays whole (one contiguous copy per array and pose, the cheapest
read of an engine's memory), then :func:`gather_planes` picks the segments' entries of every pose at once
into contiguous (k, P, B) planes, one per component.  The states are computed on those planes
(elementwise passes over contiguous memory) and handed to :class:`~koenig_check.segments.SegmentStates` as
(P, B, 3) and (P, B, 3, 3) views of them (:func:`vectors`, :func:`matrices`), so that the formulas'
component planes (:func:`~koenig_check.kernels.components`, :func:`~koenig_check.kernels.matrix_components`)
are these same arrays, without a copy.

The arithmetic is that of :func:`~koenig_check.kernels.rotate` and :func:`~koenig_check.kernels.cross`,
term by term in the same order: the same numbers.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from koenig_check.kernels import ROWS, dot3, fold, tile


def gather_planes(raw: np.ndarray, index: np.ndarray) -> np.ndarray:
    """Entries of every pose's flat engine array, as contiguous component planes.

    Parameters
    ----------
    raw : ndarray, shape (P, n)
        One row per pose: an engine array copied whole, flattened.
    index : ndarray of int, shape (k, B)
        ``index[c, b]``: the position in a row of component ``c`` of segment ``b``.

    Returns
    -------
    ndarray, shape (k, P, B), C-contiguous
    """
    out = np.empty((index.shape[0], raw.shape[0], index.shape[1]))
    n = index.shape[1]
    if n == 0:
        return out
    index = np.asarray(index, dtype=np.intp)
    step = int(index[0, 1] - index[0, 0]) if n > 1 else 0
    in_row = 0 <= int(index.min()) and int(index.max()) < raw.shape[1]
    if in_row and step >= 0 and (n == 1 or bool((np.diff(index, axis=1) == step).all())):
        # Every component's entries are ``step`` apart: the segments are consecutive rows of the engine's array
        # (or all the same row, step 0). One strided view per component, copied once, instead of a gather and
        # a transposing copy.
        for c, first in enumerate(index[:, 0].tolist()):
            out[c] = raw[:, first : first + step * (n - 1) + 1 : step] if step else raw[:, first, None]
        return out
    picked = np.take(raw, index, axis=1)  # (P, k, B): one gather over the batch, rows of B contiguous
    out[...] = np.swapaxes(picked, 0, 1)
    return out


def byte_view(a: np.ndarray) -> memoryview:
    """A C-contiguous array's memory as a flat memoryview of bytes, for the engine loops' per-pose copies.

    Slice assignment between byte views copies a pose's row in about 40 ns where numpy's indexed assignment
    (``out[p] = row``) takes about 100 ns, and an engine loop makes several per pose. The view writes
    through to the array; the caller keeps the array alive while it uses the view.

    Parameters
    ----------
    a : ndarray
        C-contiguous.

    Returns
    -------
    memoryview
        Format ``B``, ``a.nbytes`` long.

    Raises
    ------
    ValueError
        If ``a`` is not C-contiguous (its bytes are not one run).
    """
    if not a.flags.c_contiguous:
        raise ValueError(f"byte_view: array of shape {a.shape} is not C-contiguous")
    if a.size == 0:  # no bytes to copy (a batch of no poses); numpy's view of it cannot be cast
        return memoryview(bytearray())
    return a.data.cast("B")


def entry_index(rows: np.ndarray, width: int, entries: Sequence[int] | np.ndarray) -> np.ndarray:
    """The :func:`gather_planes` index of some entries of some rows of a (n, width) array.

    Parameters
    ----------
    rows : ndarray of int, shape (B,)
        The rows (bodies, joints) wanted, in segment order.
    width : int
        Entries per row of the engine's array.
    entries : sequence of int, length k
        The entries of a row wanted, in component order.

    Returns
    -------
    ndarray of int, shape (k, B)
    """
    return np.asarray(rows, dtype=np.intp)[None, :] * width + np.asarray(entries, dtype=np.intp)[:, None]


def vectors(planes: np.ndarray) -> np.ndarray:
    """(3, P, B) planes viewed as (P, B, 3) vectors (no copy)."""
    return np.moveaxis(planes, 0, -1)


def matrices(planes: np.ndarray) -> np.ndarray:
    """(9, P, B) planes of row-major entries viewed as (P, B, 3, 3) matrices (no copy)."""
    return np.moveaxis(planes.reshape(3, 3, *planes.shape[1:]), (0, 1), (-2, -1))


def rotate_constant(R: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R v`` with one vector per segment, the same at every pose: (9, P, B) and (B, 3) → (3, P, B).

    Parameters
    ----------
    R : ndarray, shape (9, P, B), C-contiguous
        Row-major entries.
    v : ndarray, shape (B, 3)

    Returns
    -------
    ndarray, shape (3, P, B)
    """
    Rf, k = fold(R)
    c = tile(np.ascontiguousarray(np.asarray(v, dtype=float).T), k)  # (3, k B)
    out = np.empty((3, *R.shape[1:]))
    folded = out.reshape(3, *Rf.shape[1:])
    for i in range(3):
        np.einsum(ROWS, Rf[3 * i : 3 * i + 3], c, out=folded[i])
    return out


def rotate_planes(R: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``R v`` per pose and segment: (9, P, B) and (3, P, B) → (3, P, B).

    Parameters
    ----------
    R : ndarray, shape (9, P, B)
    v : ndarray, shape (3, P, B)

    Returns
    -------
    ndarray, shape (3, P, B)
    """
    out = np.empty((3, *R.shape[1:]))
    tmp = np.empty(R.shape[1:])
    for i in range(3):
        dot3(R[3 * i], R[3 * i + 1], R[3 * i + 2], v[0], v[1], v[2], out[i], tmp)
    return out


def cross_planes(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a × b`` of (3, ...) planes, broadcasting, in :func:`~koenig_check.kernels.cross`'s order of terms.

    Parameters
    ----------
    a, b : ndarray, shape (3, ...)

    Returns
    -------
    ndarray, shape (3, ...)
    """
    out = np.empty((3, *np.broadcast_shapes(a.shape[1:], b.shape[1:])))
    tmp = np.empty(out.shape[1:])
    for i, j, l in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):  # a_j b_l − a_l b_j
        np.multiply(a[j], b[l], out=out[i])
        np.multiply(a[l], b[j], out=tmp)
        out[i] -= tmp
    return out


def moved_point_velocity(v_ref: np.ndarray, omega: np.ndarray, point: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """``v_ref + ω × (point − ref)``: the velocity of a point of the segment, (3, P, B) planes.

    Parameters
    ----------
    v_ref, omega, point : ndarray, shape (3, P, B)
    ref : ndarray, shape (3, P, B) or (3, P, 1)
        The point whose velocity is ``v_ref``.

    Returns
    -------
    ndarray, shape (3, P, B)
    """
    out = cross_planes(omega, np.subtract(point, ref))
    return np.add(v_ref, out, out=out)
