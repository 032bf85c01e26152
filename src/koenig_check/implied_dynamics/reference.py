"""Each engine's own rigid-body mass matrix and generalized inertia forces, armature taken out explicitly.

Both engines put the armature (rotor inertia) into their mass matrix and their inverse dynamics
(MuJoCo: ``mj_fullM`` and ``mj_inverse`` carry ``dof_armature``; Pinocchio 4.1: ``crba`` and ``rnea``
carry ``model.armature``).  No kinetic-energy formula has an armature term, so the reference here
is the engine's number *minus its own armature contribution*, computed from the engine's own
armature array (never from the other engine):

* MuJoCo: ``M − diag(dof_armature)``, ``τ − dof_armature ⊙ q̈``;
* Pinocchio: ``M − Tᵀ diag(armature) T`` and ``τ − Tᵀ (armature ⊙ a)`` with ``v = T q̇`` the state
  map's velocity matrix and ``a`` Pinocchio's acceleration (exact also for free joints, whose
  linear velocity is in a different frame in the two engines);
* Drake: its actuators' reflected inertia, the same way as MuJoCo's armature.

Each adapter says what its armature contributes (``armature_matrix``, ``armature_forces``).

``inverse_dynamics`` of both adapters already runs with gravity off, and MuJoCo's with constraints,
springs, dampers and fluid forces disabled; Pinocchio's ``rnea`` has no passive forces.  The
generalized inertia force is then ``Q* = −τ_rigid``.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def rigid_mass_matrix(engine: Any, qpos: np.ndarray) -> np.ndarray:
    """The engine's mass matrix without its armature.

    Parameters
    ----------
    engine : MujocoEngine, PinocchioEngine or DrakeEngine
    qpos : ndarray, shape (P, nq)

    Returns
    -------
    ndarray, shape (P, nv, nv)
    """
    return engine.mass_matrix(qpos) - engine.armature_matrix(qpos)


def rigid_inertia_forces(engine: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
    """The engine's generalized inertia forces ``Q* = −(τ − τ_armature)``.

    ``τ`` is the engine's inverse dynamics with gravity, springs, dampers and constraints off.

    Parameters
    ----------
    engine : MujocoEngine, PinocchioEngine or DrakeEngine
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    ndarray, shape (P, nv)
    """
    tau = engine.inverse_dynamics(qpos, qvel, qacc)
    return -(tau - engine.armature_forces(qpos, qvel, qacc))
