"""MuJoCo's dynamics: reported kinetic energy, mass matrix, inverse dynamics and their armature parts.

What MuJoCo 4.0 includes (verified, see ``self_consistency``): ``mj_energyVel`` (with ``mjENBL_ENERGY``, after
``mj_makeM``) is ``½ q̇ᵀ M q̇`` where ``M`` (``mj_fullM``) carries ``dof_armature`` on its diagonal, so the
reported energy includes the armature; ``mj_rne`` excludes the armature, ``mj_inverse`` includes it.  Inverse
dynamics here is ``mj_inverse`` on a copy with gravity zero and constraints, springs, dampers and fluid forces
disabled.
"""

from __future__ import annotations

import copy

import mujoco
import numpy as np

from koenig_check.engines.base import as_batches
from koenig_check.engines.energy import EnergyParts


def energy_model(model: mujoco.MjModel) -> mujoco.MjModel:
    """A copy of the model whose ``mj_energyVel`` evaluates the kinetic energy (``mjENBL_ENERGY`` on).

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    mujoco.MjModel
    """
    out = copy.copy(model)
    out.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    return out


def inverse_dynamics_model(model: mujoco.MjModel) -> mujoco.MjModel:
    """A copy of the model with gravity, fluid forces, constraints, springs and dampers off.

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    mujoco.MjModel
    """
    out = copy.copy(model)
    out.opt.gravity[:] = 0.0
    out.opt.density = 0.0
    out.opt.viscosity = 0.0
    off = mujoco.mjtDisableBit
    out.opt.disableflags |= int(off.mjDSBL_CONSTRAINT | off.mjDSBL_SPRING | off.mjDSBL_DAMPER)
    return out


class MujocoDynamics:
    """The dynamics methods of :class:`~koenig_check.engines.mujoco.adapter.MujocoEngine`.

    Each method's contract (parameters, shapes, returns) is :class:`~koenig_check.engines.base.Engine`'s.

    Attributes
    ----------
    model : mujoco.MjModel
    nq, nv : int
    """

    model: mujoco.MjModel
    nq: int
    nv: int
    _data: mujoco.MjData
    _m_energy: mujoco.MjModel  # energy_model(model)
    _m_dyn: mujoco.MjModel  # inverse_dynamics_model(model)

    def _energy(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """Return ``mj_energyVel`` (``½ q̇ᵀ M q̇``, armature included) pose by pose."""
        model = self._m_energy
        d = mujoco.MjData(model)
        reported = np.empty(qpos.shape[0])
        for p in range(qpos.shape[0]):
            d.qpos[:] = qpos[p]
            d.qvel[:] = qvel[p]
            mujoco.mj_kinematics(model, d)
            mujoco.mj_comPos(model, d)
            mujoco.mj_makeM(model, d)
            mujoco.mj_energyVel(model, d)
            reported[p] = d.energy[1]
        return reported

    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return ``mj_energyVel``, the rigid-body energy and the armature term.

        The rigid-body energy is ``½ q̇ᵀ (M − diag(dof_armature)) q̇`` with MuJoCo's own mass matrix
        (``mj_energyVel`` minus the armature term):
        MuJoCo builds ``M`` as the composite-rigid-body matrix plus ``dof_armature`` on the
        diagonal.  Zeroing ``dof_armature`` on a compiled copy would not do: for the dofs MuJoCo
        treats as *simple* (``dof_simplenum``: e.g. a slide or an aligned hinge on a body attached
        to the world) the diagonal of ``M``, armature included, is precomputed at compile time
        (``dof_M0``) and the copy would still count the armature as rigid-body energy.
        """
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        reported = self._energy(qpos, qvel)
        armature = 0.5 * (qvel**2) @ self.model.dof_armature
        return EnergyParts(rigid=reported - armature, armature=armature, reported=reported)

    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``mj_fullM`` (armature included) for a batch of poses."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        m, d = self.model, self._data
        out = np.zeros((qpos.shape[0], self.nv, self.nv))
        for p in range(qpos.shape[0]):
            d.qpos[:] = qpos[p]
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            mujoco.mj_makeM(m, d)
            mujoco.mj_fullM(m, d, out[p])
        return out

    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return ``mj_inverse`` forces with gravity, constraints and passive forces off."""
        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        m = self._m_dyn
        d = mujoco.MjData(m)
        out = np.empty_like(qvel)
        for p in range(qpos.shape[0]):
            d.qpos[:] = qpos[p]
            d.qvel[:] = qvel[p]
            d.qacc[:] = qacc[p]
            mujoco.mj_inverse(m, d)
            out[p] = d.qfrc_inverse
        return out

    def armature_per_dof(self) -> np.ndarray:
        """Return ``dof_armature``: ``mj_fullM`` has it on the diagonal, ``mj_inverse`` adds ``dof_armature ⊙ q̈``."""
        return np.array(self.model.dof_armature, dtype=float)
