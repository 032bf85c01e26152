"""Eq. (16): plane-parallel motion, defined only where the motion really is plane-parallel."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from koenig_check.exceptions import NotPlaneParallelError
from koenig_check.formulas.exact import translational
from koenig_check.segments import SegmentStates

#: Default relative tolerance for the plane-parallel test.
PLANAR_RTOL = 1e-9


def _infer_normals(states: SegmentStates) -> np.ndarray:
    """Per segment, a candidate normal of the plane of motion.

    The direction of the largest angular velocity in the batch; for a segment that
    never rotates, the direction least spanned by its centre-of-mass velocities.
    """
    norms = np.linalg.norm(states.omega, axis=-1)  # (P, B)
    best = np.argmax(norms, axis=0)  # (B,)
    w = states.omega[best, np.arange(states.n_segments)]  # (B, 3)
    n = np.linalg.norm(w, axis=-1, keepdims=True)
    # Right singular vector of the smallest singular value of the (P, 3) velocity stack.
    v_stack = np.swapaxes(states.v_com, 0, 1)  # (B, P, 3)
    least = np.linalg.svd(v_stack, full_matrices=False)[2][:, -1, :]  # (B, 3)
    return np.where(n > 0, w / np.where(n > 0, n, 1.0), least)


def infer_normals(states: SegmentStates) -> np.ndarray:
    """Per segment, the normal :func:`planar` infers from a batch of states.

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (B, 3)
        Unit vectors.
    """
    return _infer_normals(states)


def planar(
    states: SegmentStates,
    normal: np.ndarray | None = None,
    rtol: float = PLANAR_RTOL,
    atol: float = 1e-12,
    pose_labels: Sequence[str] | None = None,
) -> np.ndarray:
    """Eq. (16): ``E = ½ m (x_t² + y_t²)_C + ½ θ_z,t² J_C^z`` for plane-parallel motion.

    The plane of motion has a fixed world normal ``n`` (the paper's z axis).  Motion is
    plane-parallel when, at every pose and for every segment, the angular velocity is
    parallel to ``n`` and the centre-of-mass velocity has no component along ``n``:
    ``|ω − (ω·n)n| <= atol + rtol |ω|`` and ``|v_C·n| <= atol + rtol |v_C|``.

    Parameters
    ----------
    states : SegmentStates
    normal : ndarray, shape (3,) or (B, 3), optional
        Normal of the plane of motion.  By default it is inferred per segment as the
        direction of the largest angular velocity in the batch (for a segment that
        does not rotate, the direction its centre-of-mass velocities span least).
    rtol, atol : float
        Tolerances of the plane-parallel test.
    pose_labels : sequence of str, optional
        How the refusal names a pose (default: its index in the batch).

    Returns
    -------
    ndarray, shape (P, B)

    Raises
    ------
    NotPlaneParallelError
        Naming the first segment and pose that leave the plane.
    """
    if normal is None:
        n = _infer_normals(states)
    else:
        n = np.broadcast_to(np.asarray(normal, dtype=float), (states.n_segments, 3))
        length = np.linalg.norm(n, axis=-1, keepdims=True)
        if np.any(length == 0) or not np.all(np.isfinite(n)):
            raise ValueError(f"planar: normal {normal!r} is not a finite non-zero vector")
        n = n / length
    # The first offending (pose, segment) is in the first poses when it is anywhere there: test them
    # first, so that a refusal does not pay for the whole batch.
    for poses in (slice(0, 8), slice(None)):
        omega, v_com = states.omega[poses], states.v_com[poses]
        w_n = np.einsum("pbi,bi->pb", omega, n)
        w_perp = np.linalg.norm(omega - w_n[..., None] * n[None], axis=-1)
        v_n = np.abs(np.einsum("pbi,bi->pb", v_com, n))
        bad_w = w_perp > atol + rtol * np.linalg.norm(omega, axis=-1)
        bad_v = v_n > atol + rtol * np.linalg.norm(v_com, axis=-1)
        bad = bad_w | bad_v
        if bad.any():
            p, b = np.argwhere(bad)[0]
            pose = pose_labels[p] if pose_labels is not None else p
            what = (
                f"angular velocity leaves the normal by {w_perp[p, b]:.3g} rad/s"
                if bad_w[p, b]
                else f"centre of mass moves out of the plane at {v_n[p, b]:.3g} m/s"
            )
            raise NotPlaneParallelError(
                f"planar (eq. 16): segment {states.names[b]!r} at pose {pose} is not in plane-parallel motion "
                f"with normal {np.round(n[b], 6).tolist()}: {what}"
            )
    w_n = np.einsum("pbi,bi->pb", states.omega, n)
    J_n = np.einsum("pbi,bi->pb", (states.inertia_world() @ n[None, :, :, None])[..., 0], n)
    return translational(states) + 0.5 * w_n**2 * J_n
