"""Kane's form of the generalized inertia forces for ``exact``, from each engine's own Jacobians and kinematics.

``Q*_j = −Σ_bodies [ m a_C · ∂v_C/∂q̇_j + (I_C α + ω × I_C ω) · ∂ω/∂q̇_j ]`` (Kane & Levinson), every vector
in world axes, ``I_C`` the central inertia in world axes at the current pose.  Kane's equations hold
for any generalized speeds, so canonical velocities (body-frame angular velocity of ball and free
joints included) need no correction here: the partial velocities are the Jacobian columns in those
speeds.  The mass matrix follows from the same partial velocities,
``M = Σ m J_vᵀ J_v + J_ωᵀ I_C J_ω``.

* MuJoCo: per body with mass, ``mj_jac`` at the body's COM ``xipos`` gives ``J_v, J_ω`` in canonical
  speeds; ``mj_jacDot`` at the same point gives ``J̇``, so ``a_C = J_v q̈ + J̇_v q̇`` and
  ``α = J_ω q̈ + J̇_ω q̇``; ``I_C = ximat diag(body_inertia) ximatᵀ``.
* Pinocchio: per joint with mass (its inertia lumps the links fixed to it), ``getFrameJacobian`` and
  ``getFrameClassicalAcceleration`` at the COM placement in ``LOCAL_WORLD_ALIGNED`` after
  ``computeJointJacobians`` and ``forwardKinematics(q, v, a)``; Pinocchio's speeds ``v = T q̇``, so the
  canonical results are ``Tᵀ M T`` and ``Tᵀ Q*`` (the state map's velocity matrix ``T``).
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np
import pinocchio as pin


def _body_terms(
    mass: float, inertia: np.ndarray, Jv: np.ndarray, Jw: np.ndarray, acc: np.ndarray, alpha: np.ndarray, u: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """One body's contribution to ``M`` and to ``Q*`` (world axes, COM reference point)."""
    omega = Jw @ u
    M = mass * Jv.T @ Jv + Jw.T @ inertia @ Jw
    Q = -(mass * acc @ Jv + (inertia @ alpha + np.cross(omega, inertia @ omega)) @ Jw)
    return M, Q


def kane_mujoco(engine: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Kane's ``M`` and ``Q*`` with MuJoCo's ``mj_jac``/``mj_jacDot`` at each body's COM.

    Parameters
    ----------
    engine : MujocoEngine
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    M : ndarray, shape (P, nv, nv)
    Q : ndarray, shape (P, nv)
        Generalized inertia forces, canonical coordinates.
    """
    m = engine.model
    d = mujoco.MjData(m)
    qpos, qvel, qacc = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (qpos, qvel, qacc))
    P, nv = qvel.shape
    bodies = [b for b in range(1, m.nbody) if m.body_mass[b] > 0]
    jacp, jacr = np.zeros((3, nv)), np.zeros((3, nv))
    dotp, dotr = np.zeros((3, nv)), np.zeros((3, nv))
    M_out, Q_out = np.zeros((P, nv, nv)), np.zeros((P, nv))
    for p in range(P):
        d.qpos[:], d.qvel[:] = qpos[p], qvel[p]
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_comVel(m, d)
        for b in bodies:
            point = d.xipos[b].copy()
            mujoco.mj_jac(m, d, jacp, jacr, point, b)
            mujoco.mj_jacDot(m, d, dotp, dotr, point, b)
            R = d.ximat[b].reshape(3, 3)
            inertia = R @ np.diag(m.body_inertia[b]) @ R.T
            acc = jacp @ qacc[p] + dotp @ qvel[p]
            alpha = jacr @ qacc[p] + dotr @ qvel[p]
            M, Q = _body_terms(float(m.body_mass[b]), inertia, jacp, jacr, acc, alpha, qvel[p])
            M_out[p] += M
            Q_out[p] += Q
    return M_out, Q_out


def kane_pinocchio(engine: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Kane's ``M`` and ``Q*`` with Pinocchio's frame Jacobians and classical accelerations at each COM.

    Parameters
    ----------
    engine : PinocchioEngine
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    M : ndarray, shape (P, nv, nv)
    Q : ndarray, shape (P, nv)
        Generalized inertia forces, canonical coordinates.
    """
    model, sm = engine.model, engine.state_map
    data = model.createData()
    qpos, qvel, qacc = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (qpos, qvel, qacc))
    q, v = sm.to_pinocchio(qpos, qvel)
    a = sm.acceleration_to_pinocchio(qpos, qvel, qacc)
    P, nv = v.shape
    world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    joints = [i for i in range(1, model.njoints) if model.inertias[i].mass > 0]
    placements = {i: pin.SE3(np.eye(3), np.asarray(model.inertias[i].lever)) for i in joints}
    M_pin, Q_pin = np.zeros((P, nv, nv)), np.zeros((P, nv))
    for p in range(P):
        pin.computeJointJacobians(model, data, q[p])
        pin.forwardKinematics(model, data, q[p], v[p], a[p])
        for i in joints:
            Y = model.inertias[i]
            # a one-dof model's Jacobian comes out of the bindings as a (6,) vector, not (6, 1)
            J = np.reshape(pin.getFrameJacobian(model, data, i, placements[i], world), (6, nv))
            acc = pin.getFrameClassicalAcceleration(model, data, i, placements[i], world)
            R = data.oMi[i].rotation
            inertia = R @ Y.inertia @ R.T
            M, Q = _body_terms(float(Y.mass), inertia, J[:3], J[3:], acc.linear, acc.angular, v[p])
            M_pin[p] += M
            Q_pin[p] += Q
    T = sm.velocity_matrix(qpos)
    return np.swapaxes(T, -1, -2) @ M_pin @ T, np.einsum("pij,pi->pj", T, Q_pin)
