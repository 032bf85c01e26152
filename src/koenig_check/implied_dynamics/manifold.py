"""The canonical configuration manifold: MuJoCo's own integration, and where velocities are not rates.

Canonical positions are MuJoCo ``qpos`` and canonical velocities ``qvel``.  For hinges, slides and
the linear part of a free joint (world-frame velocity of the body origin) the velocity is the time
derivative of the coordinate.  For a ball joint and the angular part of a free joint it is the
angular velocity in the child (body) frame, ``Ṙ = R ω̂``: a *quasi-velocity*, not the rate of any
coordinate.  :func:`integrate` moves along exactly these directions (``mj_integratePos`` composes
the quaternion with ``exp(ω dt)`` on the body side), and :func:`rotation_blocks` names the dof
triples that are angular velocities in a body frame.
"""

from __future__ import annotations

import mujoco
import numpy as np


def integrate(model: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray, dt: float = 1.0) -> np.ndarray:
    """``qpos ⊕ dt·qvel`` on the configuration manifold, by ``mujoco.mj_integratePos`` (quaternions handled).

    Parameters
    ----------
    model : mujoco.MjModel
    qpos : ndarray, shape (N, nq)
    qvel : ndarray, shape (N, nv)
        Displacement directions in canonical velocity coordinates.
    dt : float

    Returns
    -------
    ndarray, shape (N, nq)
    """
    out = np.array(np.atleast_2d(qpos), dtype=float, copy=True)
    vel = np.ascontiguousarray(np.atleast_2d(qvel), dtype=float)
    for n in range(out.shape[0]):
        row = out[n]
        mujoco.mj_integratePos(model, row, vel[n], dt)
    return out


def rotation_blocks(model: mujoco.MjModel) -> np.ndarray:
    """Canonical dof triples that are angular velocities in a body frame (ball joints, free-joint rotation).

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    ndarray, shape (K, 3)
        Dof indices, one row per ball or free joint.
    """
    rows = []
    for j in range(model.njnt):
        adr = int(model.jnt_dofadr[j])
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_BALL:
            rows.append([adr, adr + 1, adr + 2])
        elif model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            rows.append([adr + 3, adr + 4, adr + 5])
    return np.array(rows, dtype=int).reshape(-1, 3)
