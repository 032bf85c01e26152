"""Pinocchio's joint placements (``data.oMi``) and velocities (``data.v``), read whole where the layout allows."""

from __future__ import annotations

import numpy as np
import pinocchio as pin


def placement_view(model: pin.Model, data: pin.Data) -> np.ndarray | None:
    """``data.oMi`` as one (njoints, 12) array over Pinocchio's own storage, or None.

    Pinocchio 4.1 hands the placements out one joint at a time (each accessor costs about 0.3 µs
    per joint); its ``SE3`` objects lie in one contiguous vector inside ``data``, and the bindings'
    ``rotation`` and ``translation`` are views of that memory.  Row ``i`` of the returned array is
    joint ``i``'s rotation in Eigen's column-major order then its translation, read from that
    vector, so that one copy per pose takes every placement.  The layout is verified, not assumed:
    every joint's ``rotation`` and ``translation`` must sit at the addresses and strides the view
    reads, and after forward-kinematics passes at two random configurations the view must equal every
    joint's ``homogeneous`` placement exactly; otherwise None (callers read the joints one by one).

    The view does not keep ``data`` alive and follows it: the caller holds ``data`` for as long as
    it uses the view, and copies it after each kinematic pass.

    Parameters
    ----------
    model : pinocchio.Model
    data : pinocchio.Data
        Created from ``model``.

    Returns
    -------
    ndarray, shape (njoints, 12), read-only, or None
    """
    placements = data.oMi
    n = len(placements)
    rotations = [placements[i].rotation for i in range(n)]
    translations = [placements[i].translation for i in range(n)]
    address = np.array([r.__array_interface__["data"][0] for r in rotations], dtype=np.int64)
    stride = int(address[1] - address[0]) if n > 1 else 96
    layout_ok = (
        n >= 1
        and stride >= 96
        and all(r.shape == (3, 3) and r.strides == (8, 24) and r.dtype == np.float64 for r in rotations)
        and all(t.shape == (3,) and t.strides == (8,) and t.dtype == np.float64 for t in translations)
        and np.array_equal(address, address[0] + stride * np.arange(n))
        and all(t.__array_interface__["data"][0] == a + 72 for t, a in zip(translations, address, strict=True))
    )
    if not layout_ok:
        return None
    view = np.lib.stride_tricks.as_strided(rotations[0], shape=(n, 12), strides=(stride, 8), writeable=False)
    # Two configurations: a snapshot taken when ``data`` already held the first one (a data object
    # checked before, or unpickled after its check) cannot match the second.
    rng = np.random.default_rng(0)
    for _ in range(2):
        moved = pin.integrate(model, pin.neutral(model), rng.uniform(-1.0, 1.0, model.nv))
        pin.forwardKinematics(model, data, moved)
        expected = np.array([M.homogeneous for M in placements.tolist()])
        R, origin = rotations_origins(view[None], True, slice(None))
        if not (np.array_equal(R[0], expected[:, :3, :3]) and np.array_equal(origin[0], expected[:, :3, 3])):
            return None
    return view


def rotations_origins(raw: np.ndarray, from_view: bool, joints: slice | np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rotations (P, B, 3, 3) and origins (P, B, 3) of some joints from :func:`placement_view` rows or 4 × 4 matrices.

    ``raw`` is (P, njoints, 12) or (P, njoints, 4, 4); ``joints`` selects along its joint axis.  From
    view rows, an index array is gathered and transposed in the same pass (``np.take`` into ``R``); the
    origins come contiguous (the state kernels read them faster than a strided view).

    Parameters
    ----------
    raw : ndarray, shape (P, njoints, 12) or (P, njoints, 4, 4)
    from_view : bool
        Whether ``raw`` holds :func:`placement_view` rows.
    joints : slice or ndarray
        The joints wanted, along ``raw``'s joint axis.

    Returns
    -------
    rotations : ndarray, shape (P, B, 3, 3)
    origins : ndarray, shape (P, B, 3)
    """
    if not from_view:
        H = raw[:, joints]
        return H[..., :3, :3], H[..., :3, 3]
    P = raw.shape[0]
    by_column = np.swapaxes(raw[..., :9].reshape(P, raw.shape[1], 3, 3), -1, -2)  # stored column by column
    if isinstance(joints, slice):
        R = np.empty(by_column[:, joints].shape)
        R[...] = by_column[:, joints]
        return R, np.ascontiguousarray(raw[:, joints, 9:])
    R = np.empty((P, len(joints), 3, 3))
    np.take(by_column, joints, axis=1, out=R)
    return R, np.take(raw[..., 9:], joints, axis=1)


def motion_view(model: pin.Model, data: pin.Data) -> np.ndarray | None:
    """``data.v`` as one (njoints, 6) array over Pinocchio's own storage, or None.

    Row ``i`` is joint ``i``'s spatial velocity in its own frame, linear then angular (``data.v[i].vector``),
    read from the contiguous vector of ``Motion`` objects inside ``data`` (the bindings' ``vector`` is a view
    of it).  As for :func:`placement_view`, the layout is verified, not assumed: every joint's ``vector``
    must sit at the address and stride the view reads, and after forward-kinematics passes with
    velocities at two random states the view must equal every joint's ``vector`` exactly; otherwise None
    (callers read the joints one by one).

    The view does not keep ``data`` alive and follows it: the caller holds ``data`` for as long as it
    uses the view, and copies it after each kinematic pass.

    Parameters
    ----------
    model : pinocchio.Model
    data : pinocchio.Data
        Created from ``model``.

    Returns
    -------
    ndarray, shape (njoints, 6), read-only, or None
    """
    motions = data.v
    n = len(motions)
    vectors = [motions[i].vector for i in range(n)]
    address = np.array([v.__array_interface__["data"][0] for v in vectors], dtype=np.int64)
    stride = int(address[1] - address[0]) if n > 1 else 48
    layout_ok = (
        n >= 1
        and stride >= 48
        and all(v.shape == (6,) and v.strides == (8,) and v.dtype == np.float64 for v in vectors)
        and np.array_equal(address, address[0] + stride * np.arange(n))
    )
    if not layout_ok:
        return None
    view = np.lib.stride_tricks.as_strided(vectors[0], shape=(n, 6), strides=(stride, 8), writeable=False)
    rng = np.random.default_rng(1)
    for _ in range(2):  # two states: a snapshot of the data as it was cannot match both
        q = pin.integrate(model, pin.neutral(model), rng.uniform(-1.0, 1.0, model.nv))
        pin.forwardKinematics(model, data, q, rng.uniform(-1.0, 1.0, model.nv))
        if not np.array_equal(view, np.array([m.vector for m in motions.tolist()]).reshape(n, 6)):
            return None
    return view
