"""Rigid transforms for writing model files: poses as (position, rotation matrix), MuJoCo's quaternions."""

from __future__ import annotations

import math

import mujoco
import numpy as np

#: A rigid transform: position (3,) and rotation matrix (3, 3), child frame in parent frame.
Pose = tuple[np.ndarray, np.ndarray]


def quat_to_matrix(quat: np.ndarray) -> np.ndarray:
    """Rotation matrix of a unit quaternion ``(w, x, y, z)`` (MuJoCo's ``mju_quat2Mat``).

    Parameters
    ----------
    quat : ndarray, shape (4,)

    Returns
    -------
    ndarray, shape (3, 3)
    """
    out = np.zeros(9)
    mujoco.mju_quat2Mat(out, np.asarray(quat, dtype=float))
    return out.reshape(3, 3)


def matrix_to_quat(rot: np.ndarray) -> np.ndarray:
    """Unit quaternion ``(w, x, y, z)`` of a rotation matrix (MuJoCo's ``mju_mat2Quat``).

    Parameters
    ----------
    rot : ndarray, shape (3, 3)

    Returns
    -------
    ndarray, shape (4,)
    """
    out = np.zeros(4)
    mujoco.mju_mat2Quat(out, np.ascontiguousarray(rot, dtype=float).ravel())
    return out


def axis_motion(axis: np.ndarray, amount: float, hinge: bool) -> Pose:
    """The motion of a joint at coordinate ``amount``: a rotation about ``axis`` or a translation along it.

    Parameters
    ----------
    axis : ndarray, shape (3,)
        Unit axis.
    amount : float
        Angle (rad) for a hinge, distance for a slide.
    hinge : bool

    Returns
    -------
    Pose
    """
    axis = np.asarray(axis, dtype=float)
    if not hinge:
        return amount * axis, np.eye(3)
    quat = np.zeros(4)
    mujoco.mju_axisAngle2Quat(quat, axis, amount)
    return np.zeros(3), quat_to_matrix(quat)


def compose(a: Pose, b: Pose) -> Pose:
    """``a ∘ b``: the pose ``b`` given in frame ``a``, expressed in ``a``'s parent.

    Parameters
    ----------
    a, b : Pose

    Returns
    -------
    Pose
    """
    return a[0] + a[1] @ b[0], a[1] @ b[1]


def inverse(a: Pose) -> Pose:
    """The inverse transform.

    Parameters
    ----------
    a : Pose

    Returns
    -------
    Pose
    """
    return -a[1].T @ a[0], a[1].T


def translation(p: np.ndarray) -> Pose:
    """A pure translation.

    Parameters
    ----------
    p : ndarray, shape (3,)

    Returns
    -------
    Pose
    """
    return np.asarray(p, dtype=float).copy(), np.eye(3)


def matrix_to_rpy(rot: np.ndarray) -> np.ndarray:
    """URDF's roll-pitch-yaw (``R = Rz(yaw) Ry(pitch) Rx(roll)``) of a rotation matrix.

    Parameters
    ----------
    rot : ndarray, shape (3, 3)

    Returns
    -------
    ndarray, shape (3,)
        Roll, pitch, yaw in radians.
    """
    r = np.asarray(rot, dtype=float)
    pitch = math.atan2(-r[2, 0], math.hypot(r[0, 0], r[1, 0]))
    if abs(math.cos(pitch)) > 1e-12:
        roll = math.atan2(r[2, 1], r[2, 2])
        yaw = math.atan2(r[1, 0], r[0, 0])
    else:  # gimbal lock: yaw absorbed into roll
        yaw = 0.0
        roll = math.atan2(r[0, 1], r[1, 1]) if pitch > 0 else math.atan2(-r[0, 1], r[1, 1])
    return np.array([roll, pitch, yaw])


def rpy_to_matrix(rpy: np.ndarray) -> np.ndarray:
    """Rotation matrix of URDF roll-pitch-yaw angles (``Rz(yaw) Ry(pitch) Rx(roll)``).

    Parameters
    ----------
    rpy : ndarray, shape (3,)

    Returns
    -------
    ndarray, shape (3, 3)
    """
    r, p, y = (float(v) for v in rpy)
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def number(value: float) -> str:
    """A float at full precision: Python's shortest repr, which parses back to the same double.

    Parameters
    ----------
    value : float

    Returns
    -------
    str
    """
    v = float(value)
    if v == 0.0:
        return "0"
    text = repr(v)
    return text[:-2] if text.endswith(".0") else text


def numbers(values: np.ndarray) -> str:
    """Space-separated full-precision numbers (see :func:`number`).

    Parameters
    ----------
    values : array_like

    Returns
    -------
    str
    """
    return " ".join(number(v) for v in np.asarray(values, dtype=float).ravel())
