"""SegmentStates: the one data type every kinetic-energy formula consumes.

A *segment* is the set of bodies that move together, keyed by the joint that moves
them.  Every array is batched over ``P`` poses and ``B`` segments; quantities that do
not depend on the pose (mass, body-frame inertia, reference configuration) carry only
the segment axis.  All vectors are expressed in the world frame unless the field name
says otherwise.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from koenig_check.roundoff import relative_zeros

#: Relative tolerance used to decide whether an inertia tensor is symmetric.
SYMMETRY_RTOL = 1e-9
#: Absolute tolerance on ``R^T R - 1`` used to decide whether a rotation is orthonormal.
ROTATION_ATOL = 1e-6

_PER_SEGMENT = {"mass": (), "inertia_body": (3, 3), "rotation_ref": (3, 3), "com_ref": (3,), "pole_ref": (3,)}
_PER_POSE = {
    "com": (3,),
    "v_com": (3,),
    "rotation": (3, 3),
    "omega": (3,),
    "pole": (3,),
    "v_pole": (3,),
}


@dataclass(frozen=True)
class SegmentStates:
    """Mass properties and motion of ``B`` rigid segments at ``P`` poses.

    Parameters
    ----------
    names : tuple of str
        One name per segment (the joint that moves it), length ``B``.
    mass : ndarray, shape (B,)
        Segment mass, strictly positive.
    inertia_body : ndarray, shape (B, 3, 3)
        Full inertia tensor about the segment centre of mass, in the segment's own
        frame (constant over poses), symmetric.
    com, v_com : ndarray, shape (P, B, 3)
        Centre-of-mass position and velocity, world frame.
    rotation : ndarray, shape (P, B, 3, 3)
        Orientation of the segment frame: world <- segment.
    omega : ndarray, shape (P, B, 3)
        Angular velocity, world frame.
    pole, v_pole : ndarray, shape (P, B, 3)
        The joint anchor that moves the segment (the paper's pole P) and its
        velocity, world frame.
    rotation_ref : ndarray, shape (B, 3, 3)
        Segment orientation at the reference configuration (the paper's
        "initial state": MuJoCo ``qpos0``, Pinocchio neutral).
    com_ref, pole_ref : ndarray, shape (B, 3)
        Centre of mass and pole at the reference configuration.

    Raises
    ------
    ValueError
        On construction, naming the field and the offending segment, when a shape
        is wrong, a value is not finite, a mass is not positive, an inertia is not
        symmetric or a rotation is not orthonormal.
    """

    names: tuple[str, ...]
    mass: np.ndarray
    inertia_body: np.ndarray
    com: np.ndarray
    v_com: np.ndarray
    rotation: np.ndarray
    omega: np.ndarray
    pole: np.ndarray
    v_pole: np.ndarray
    rotation_ref: np.ndarray
    com_ref: np.ndarray
    pole_ref: np.ndarray

    def __post_init__(self) -> None:
        names = tuple(str(n) for n in self.names)
        object.__setattr__(self, "names", names)
        n_seg = len(names)
        if len(set(names)) != n_seg:
            dup = sorted({n for n in names if names.count(n) > 1})
            raise ValueError(f"SegmentStates.names: duplicate segment names {dup}")
        n_pose = None
        for f in fields(self):
            if f.name == "names":
                continue
            arr = np.array(getattr(self, f.name), dtype=float, copy=True)
            if f.name in _PER_SEGMENT:
                expected = (n_seg, *_PER_SEGMENT[f.name])
            else:
                if arr.ndim < 1:
                    raise ValueError(f"SegmentStates.{f.name}: expected a pose axis, got a scalar")
                if n_pose is None:
                    n_pose = arr.shape[0]
                expected = (n_pose, n_seg, *_PER_POSE[f.name])
            if arr.shape != expected:
                raise ValueError(f"SegmentStates.{f.name}: shape {arr.shape}, expected {expected}")
            bad = ~np.isfinite(arr)
            if bad.any():
                idx = np.argwhere(bad)[0]
                seg = idx[0] if f.name in _PER_SEGMENT else idx[1]
                where = "" if f.name in _PER_SEGMENT else f" at pose {idx[0]}"
                raise ValueError(f"SegmentStates.{f.name}: non-finite value for segment {names[seg]!r}{where}")
            arr.setflags(write=False)
            object.__setattr__(self, f.name, arr)
        self._check_physics()

    def _check_physics(self) -> None:
        for b in np.flatnonzero(self.mass <= 0.0):
            raise ValueError(f"SegmentStates.mass: segment {self.names[b]!r} has non-positive mass {self.mass[b]:g}")
        asym = np.abs(self.inertia_body - np.swapaxes(self.inertia_body, -1, -2)).max(axis=(-1, -2))
        scale = np.abs(self.inertia_body).max(axis=(-1, -2))
        for b in np.flatnonzero(asym > SYMMETRY_RTOL * np.maximum(scale, 1e-300)):
            raise ValueError(
                f"SegmentStates.inertia_body: segment {self.names[b]!r} is not symmetric "
                f"(max |I - I^T| = {asym[b]:.3g})"
            )
        for name in ("rotation", "rotation_ref"):
            R = getattr(self, name)
            err = np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max(axis=(-1, -2))
            det = np.linalg.det(R)
            bad = (err > ROTATION_ATOL) | (det < 0)
            if bad.any():
                idx = np.argwhere(bad)[0]
                seg = idx[-1]
                where = f" at pose {idx[0]}" if R.ndim == 4 else ""
                raise ValueError(f"SegmentStates.{name}: segment {self.names[seg]!r}{where} is not a proper rotation")

    @classmethod
    def trusted(cls, **values: object) -> SegmentStates:
        """Build from arrays an engine adapter has just computed, without re-validating them.

        For internal paths only (the engines' sweeps), where the shapes are correct by
        construction and the physics was checked when the model was loaded.

        Parameters
        ----------
        **values
            Every field of the dataclass.

        Returns
        -------
        SegmentStates
        """
        obj = object.__new__(cls)
        for f in fields(cls):
            value = values[f.name]
            object.__setattr__(obj, f.name, tuple(value) if f.name == "names" else value)  # type: ignore[arg-type]
        return obj

    # ------------------------------------------------------------------ shape
    @property
    def n_poses(self) -> int:
        """Number of poses ``P``."""
        return self.com.shape[0]

    @property
    def n_segments(self) -> int:
        """Number of segments ``B``."""
        return self.mass.shape[0]

    # --------------------------------------------------------------- derived
    def inertia_world(self) -> np.ndarray:
        """Return the central inertia tensor in world axes at every pose.

        Returns
        -------
        ndarray, shape (P, B, 3, 3)
            ``R I_body R^T``.
        """
        from koenig_check.kernels import congruence

        return congruence(self.rotation, self.inertia_body[None])

    def inertia_about_anchor(self) -> np.ndarray:
        """Return each segment's size of inertia about the anchor that moves it, at the first pose.

        The largest central principal moment plus ``m |com - pole|²``: what rotating the segment about its
        anchor weighs, against which a difference of its central inertia is measured (a point mass on a lever
        has no central moment of its own, and a moment of 1e-15 kg m² there is not a difference of 100 %).

        Returns
        -------
        ndarray, shape (B,)
            In kg m².
        """
        largest = np.abs(np.linalg.eigvalsh(self.inertia_world()[0])).max(axis=-1, initial=0.0)
        lever = np.sum((self.com[0] - self.pole[0]) ** 2, axis=-1)
        return largest + self.mass * lever

    def inertia_world_ref(self) -> np.ndarray:
        """Return the central inertia tensor in world axes at the reference configuration.

        Returns
        -------
        ndarray, shape (B, 3, 3)
            ``R_ref I_body R_ref^T``.
        """
        from koenig_check.kernels import congruence

        return congruence(self.rotation_ref, self.inertia_body)

    def select(self, poses: np.ndarray | slice | None = None, segments: list[str] | None = None) -> SegmentStates:
        """Return a subset of poses and/or segments.

        Parameters
        ----------
        poses : index, optional
            Any numpy index along the pose axis (kept 1-D).
        segments : list of str, optional
            Segment names to keep, in the order given.

        Returns
        -------
        SegmentStates
        """
        p = slice(None) if poses is None else poses
        if segments is None:
            s = np.arange(self.n_segments)
        else:
            missing = [n for n in segments if n not in self.names]
            if missing:
                raise KeyError(f"unknown segments {missing}; known: {list(self.names)}")
            s = np.array([self.names.index(n) for n in segments], dtype=int)
        kwargs: dict[str, object] = {"names": tuple(self.names[i] for i in s)}
        for name in _PER_SEGMENT:
            kwargs[name] = getattr(self, name)[s]
        for name in _PER_POSE:
            arr = getattr(self, name)[p]
            if arr.ndim == len(_PER_POSE[name]) + 1:  # a single integer pose index dropped the axis
                arr = arr[None]
            kwargs[name] = arr[:, s]
        return SegmentStates(**kwargs)  # type: ignore[arg-type]

    def with_motion(self, **changes: np.ndarray) -> SegmentStates:
        """Return a copy with some per-pose fields replaced (validated again).

        Parameters
        ----------
        **changes : ndarray
            New values for any of ``com, v_com, rotation, omega, pole, v_pole`` or the
            per-segment fields.

        Returns
        -------
        SegmentStates
        """
        unknown = set(changes) - set(_PER_POSE) - set(_PER_SEGMENT)
        if unknown:
            raise KeyError(f"unknown SegmentStates fields {sorted(unknown)}")
        kwargs = {f.name: getattr(self, f.name) for f in fields(self)}
        kwargs.update(changes)
        return SegmentStates(**kwargs)  # type: ignore[arg-type]


def second_moments(inertia: np.ndarray) -> np.ndarray:
    """Return the second-moment matrix ``S = ∫ r r^T dm`` of an inertia tensor.

    ``I = tr(S) 1 - S`` hence ``S = ½ tr(I) 1 - I``.  The diagonal of ``S`` holds the
    paper's planar moments ``∫x² dm, ∫y² dm, ∫z² dm`` and its off-diagonal the
    centrifugal moments ``∫xy dm`` etc. of eq. (27)/(32).

    Parameters
    ----------
    inertia : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    tr = np.trace(inertia, axis1=-2, axis2=-1)
    return 0.5 * tr[..., None, None] * np.eye(3) - inertia


def inertia_from_second_moments(S: np.ndarray) -> np.ndarray:
    """Inverse of :func:`second_moments`: ``I = tr(S) 1 - S``.

    Parameters
    ----------
    S : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    tr = np.trace(S, axis1=-2, axis2=-1)
    return tr[..., None, None] * np.eye(3) - S


def principal_moments(inertia: np.ndarray) -> np.ndarray:
    """The principal moments of an inertia tensor: the eigenvalues of its symmetric part, ascending.

    Parameters
    ----------
    inertia : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3)
    """
    inertia = np.asarray(inertia, dtype=float)
    return np.linalg.eigvalsh(0.5 * (inertia + np.swapaxes(inertia, -1, -2)))


def check_physical_inertia(mass: float, inertia: np.ndarray, rtol: float = 1e-9) -> str | None:
    """Describe why an inertia tensor is not physical, or return ``None``.

    Parameters
    ----------
    mass : float
    inertia : ndarray, shape (3, 3)
        Central inertia tensor.
    rtol : float
        Relative tolerance on the principal moments and on the triangle inequality.

    Returns
    -------
    str or None
        A short reason naming the principal moments, or ``None`` if physical.
    """
    if not np.isfinite(mass) or mass <= 0:
        return f"mass {mass:g} is not positive"
    inertia = np.asarray(inertia, dtype=float)
    if not np.all(np.isfinite(inertia)):
        return "inertia has non-finite entries"
    scale = max(np.abs(inertia).max(), 1e-300)
    if np.abs(inertia - inertia.T).max() > rtol * scale:
        return "inertia is not symmetric"
    lam = principal_moments(inertia)
    moments = relative_zeros(lam)  # round-off of a rotated inertia as 0, at the scale of the largest
    if lam[0] < -rtol * scale:
        return f"inertia is not positive semi-definite (principal moments {moments})"
    a, b, c = lam
    if a + b < c * (1 - rtol) - rtol * scale:
        return f"principal moments {moments} violate the triangle inequality A + B >= C"
    return None
