"""Each engine's own rigid-body mass matrix and generalized inertia forces, armature taken out explicitly.

Both engines put the armature (rotor inertia) into their mass matrix and their inverse dynamics
(MuJoCo: ``mj_fullM`` and ``mj_inverse`` carry ``dof_armature``; Pinocchio 4.1: ``crba`` and ``rnea``
carry ``model.armature``).  No kinetic-energy formula has an armature term, so the reference here
is the engine's number *minus its own armature contribution*, computed from the engine's own
armature array (never from the other engine):

* MuJoCo: ``M − diag(dof_armature)``, ``τ − dof_armature ⊙ q̈``;
* Pinocchio: ``M − Tᵀ diag(armature) T`` and ``τ − Tᵀ (armature ⊙ a)`` with ``v = T q̇`` the state
  map's velocity matrix and ``a`` Pinocchio's acceleration (exact also for free joints, whose
  linear velocity is in a different frame in the two engines).

``inverse_dynamics`` of both adapters already runs with gravity off, and MuJoCo's with constraints,
springs, dampers and fluid forces disabled; Pinocchio's ``rnea`` has no passive forces.  The
generalized inertia force is then ``Q* = −τ_rigid``.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def armature_matrix(engine: Any, qpos: np.ndarray) -> np.ndarray:
    """The armature part of an engine's mass matrix, in canonical coordinates.

    Parameters
    ----------
    engine : MujocoEngine or PinocchioEngine
    qpos : ndarray, shape (P, nq)

    Returns
    -------
    ndarray, shape (P, nv, nv)
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    P = qpos.shape[0]
    if engine.engine == "mujoco":
        return np.broadcast_to(np.diag(np.asarray(engine.model.dof_armature, dtype=float)), (P, engine.nv, engine.nv))
    arm = np.diag(np.asarray(engine.model.armature, dtype=float))
    return engine.state_map.matrix_to_canonical(qpos, np.broadcast_to(arm, (P, *arm.shape)))


def armature_forces(engine: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
    """The armature part of an engine's inverse dynamics, in canonical coordinates.

    Parameters
    ----------
    engine : MujocoEngine or PinocchioEngine
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    ndarray, shape (P, nv)
    """
    qacc = np.atleast_2d(np.asarray(qacc, dtype=float))
    if engine.engine == "mujoco":
        return qacc * np.asarray(engine.model.dof_armature, dtype=float)
    sm = engine.state_map
    a = sm.acceleration_to_pinocchio(qpos, qvel, qacc)
    return sm.force_to_canonical(qpos, a * np.asarray(engine.model.armature, dtype=float))


def rigid_mass_matrix(engine: Any, qpos: np.ndarray) -> np.ndarray:
    """The engine's mass matrix without its armature.

    Parameters
    ----------
    engine : MujocoEngine or PinocchioEngine
    qpos : ndarray, shape (P, nq)

    Returns
    -------
    ndarray, shape (P, nv, nv)
    """
    return engine.mass_matrix(qpos) - armature_matrix(engine, qpos)


def rigid_inertia_forces(engine: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
    """The engine's generalized inertia forces ``Q* = −(τ − τ_armature)``.

    ``τ`` is the engine's inverse dynamics with gravity, springs, dampers and constraints off.

    Parameters
    ----------
    engine : MujocoEngine or PinocchioEngine
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    ndarray, shape (P, nv)
    """
    tau = engine.inverse_dynamics(qpos, qvel, qacc)
    return -(tau - armature_forces(engine, qpos, qvel, qacc))
