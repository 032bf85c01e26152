"""Analytic bodies and synthetic segment states for checks that need no engine."""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.segments import SegmentStates


def box_inertia(mass: float, a: float, b: float, c: float) -> np.ndarray:
    """Central inertia of a uniform box with edges ``a, b, c`` along x, y, z.

    Parameters
    ----------
    mass, a, b, c : float

    Returns
    -------
    ndarray, shape (3, 3)
        ``m/12 diag(b²+c², a²+c², a²+b²)``.
    """
    return mass / 12.0 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])


def cylinder_inertia(mass: float, radius: float, height: float) -> np.ndarray:
    """Central inertia of a uniform solid cylinder whose axis is z.

    Parameters
    ----------
    mass, radius, height : float

    Returns
    -------
    ndarray, shape (3, 3)
        ``diag(m(3r²+h²)/12, m(3r²+h²)/12, m r²/2)``.
    """
    side = mass * (3 * radius**2 + height**2) / 12.0
    return np.diag([side, side, 0.5 * mass * radius**2])


def rotation_about(axis: np.ndarray, angle: np.ndarray | float) -> np.ndarray:
    """Rotation matrices about a fixed axis.

    Parameters
    ----------
    axis : ndarray, shape (3,)
    angle : float or ndarray, shape (N,)

    Returns
    -------
    ndarray, shape (3, 3) or (N, 3, 3)
    """
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    angle = np.asarray(angle, dtype=float)
    return Rotation.from_rotvec(angle[..., None] * axis).as_matrix()


def random_rotations(rng: np.random.Generator, shape: tuple[int, ...]) -> np.ndarray:
    """Uniformly random rotation matrices.

    Parameters
    ----------
    rng : numpy.random.Generator
    shape : tuple of int

    Returns
    -------
    ndarray, shape ``shape + (3, 3)``
    """
    n = int(np.prod(shape)) if shape else 1
    q = rng.normal(size=(n, 4))
    return Rotation.from_quat(q).as_matrix().reshape(*shape, 3, 3)


def random_physical_inertia(rng: np.random.Generator, n: int, spread: float = 10.0) -> np.ndarray:
    """Random central inertia tensors that satisfy the triangle inequality strictly.

    Built from a random positive second-moment matrix ``S`` (``I = tr(S) 1 − S``), so that
    every tensor is physical, with principal axes in random directions.

    Parameters
    ----------
    rng : numpy.random.Generator
    n : int
    spread : float
        Ratio between the largest and smallest second moments drawn.

    Returns
    -------
    ndarray, shape (n, 3, 3)
    """
    s = np.exp(rng.uniform(0.0, np.log(spread), size=(n, 3))) * 0.01
    V = random_rotations(rng, (n,))
    S = V @ (s[..., None] * np.eye(3)) @ np.swapaxes(V, -1, -2)
    tr = np.trace(S, axis1=-2, axis2=-1)
    return tr[:, None, None] * np.eye(3) - S


def rigid_states(
    mass: np.ndarray,
    inertia_body: np.ndarray,
    rotation: np.ndarray,
    omega: np.ndarray,
    v_com: np.ndarray,
    com: np.ndarray | None = None,
    rotation_ref: np.ndarray | None = None,
    com_ref: np.ndarray | None = None,
    pole_body: np.ndarray | None = None,
    names: tuple[str, ...] | None = None,
) -> SegmentStates:
    """Build :class:`SegmentStates` of rigid segments from their motion.

    The pole is a point fixed in each segment at ``pole_body`` (segment axes, relative to
    the centre of mass; default: the centre of mass); its position and velocity follow
    from the rigid motion, ``P = C + R p`` and ``v_P = v_C + ω × (R p)``.

    Parameters
    ----------
    mass : ndarray, shape (B,)
    inertia_body : ndarray, shape (B, 3, 3)
    rotation : ndarray, shape (P, B, 3, 3)
    omega, v_com : ndarray, shape (P, B, 3)
    com : ndarray, shape (P, B, 3), optional
        Default: the origin.
    rotation_ref : ndarray, shape (B, 3, 3), optional
        Default: identity.
    com_ref : ndarray, shape (B, 3), optional
        Default: the origin.
    pole_body : ndarray, shape (B, 3), optional
    names : tuple of str, optional

    Returns
    -------
    SegmentStates
    """
    mass = np.atleast_1d(np.asarray(mass, dtype=float))
    B = mass.shape[0]
    rotation = np.asarray(rotation, dtype=float)
    P = rotation.shape[0]
    com = np.zeros((P, B, 3)) if com is None else np.asarray(com, dtype=float)
    rotation_ref = np.broadcast_to(np.eye(3), (B, 3, 3)) if rotation_ref is None else rotation_ref
    com_ref = np.zeros((B, 3)) if com_ref is None else np.asarray(com_ref, dtype=float)
    p_body = np.zeros((B, 3)) if pole_body is None else np.asarray(pole_body, dtype=float)
    arm = np.einsum("pbij,bj->pbi", rotation, p_body)
    arm_ref = np.einsum("bij,bj->bi", rotation_ref, p_body)
    return SegmentStates(
        names=names or tuple(f"segment{b}" for b in range(B)),
        mass=mass,
        inertia_body=inertia_body,
        com=com,
        v_com=v_com,
        rotation=rotation,
        omega=omega,
        pole=com + arm,
        v_pole=v_com + np.cross(omega, arm),
        rotation_ref=rotation_ref,
        com_ref=com_ref,
        pole_ref=com_ref + arm_ref,
    )


def random_states(rng: np.random.Generator, n_poses: int, n_segments: int) -> SegmentStates:
    """Random physical segments in random motion, with random reference orientations.

    Parameters
    ----------
    rng : numpy.random.Generator
    n_poses, n_segments : int

    Returns
    -------
    SegmentStates
    """
    P, B = n_poses, n_segments
    return rigid_states(
        mass=rng.uniform(0.1, 10.0, size=B),
        inertia_body=random_physical_inertia(rng, B),
        rotation=random_rotations(rng, (P, B)),
        omega=rng.normal(scale=3.0, size=(P, B, 3)),
        v_com=rng.normal(size=(P, B, 3)),
        com=rng.normal(size=(P, B, 3)),
        rotation_ref=random_rotations(rng, (B,)),
        com_ref=rng.normal(size=(B, 3)),
        pole_body=rng.normal(scale=0.3, size=(B, 3)),
    )


def constant_rotation_states(
    mass: float,
    inertia_body: np.ndarray,
    omega: np.ndarray,
    times: np.ndarray,
    rotation_ref: np.ndarray | None = None,
    v_com: np.ndarray | None = None,
) -> SegmentStates:
    """One body turning at a constant world angular velocity from its reference orientation.

    ``R(t) = exp(t ω^) R_ref``, so the path integral of ω is ``ω t`` and the rotation
    axis never changes.

    Parameters
    ----------
    mass : float
    inertia_body : ndarray, shape (3, 3)
    omega : ndarray, shape (3,)
        World angular velocity.
    times : ndarray, shape (P,)
    rotation_ref : ndarray, shape (3, 3), optional
    v_com : ndarray, shape (3,), optional
        Constant centre-of-mass velocity (default zero).

    Returns
    -------
    SegmentStates
        With ``P`` poses and one segment.
    """
    times = np.asarray(times, dtype=float)
    omega = np.asarray(omega, dtype=float)
    R_ref = np.eye(3) if rotation_ref is None else np.asarray(rotation_ref, dtype=float)
    R = Rotation.from_rotvec(times[:, None] * omega).as_matrix() @ R_ref
    v = np.zeros(3) if v_com is None else np.asarray(v_com, dtype=float)
    P = times.shape[0]
    return rigid_states(
        mass=np.array([mass]),
        inertia_body=np.asarray(inertia_body, dtype=float)[None],
        rotation=R[:, None],
        omega=np.broadcast_to(omega, (P, 1, 3)),
        v_com=np.broadcast_to(v, (P, 1, 3)),
        com=times[:, None, None] * v,
        rotation_ref=R_ref[None],
    )
