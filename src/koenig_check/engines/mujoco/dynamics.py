"""MuJoCo's dynamics: reported kinetic energy, mass matrix, inverse dynamics and their armature parts.

What MuJoCo 4.0 includes (verified, see ``self_consistency``): ``mj_energyVel`` (after ``mj_makeM``; it reads no
flag, ``mjENBL_ENERGY`` only makes ``mj_forward`` call it) is ``½ q̇ᵀ M q̇`` where ``M`` (``mj_fullM``) carries
``dof_armature`` on its diagonal, so the reported energy includes the armature; ``mj_rne`` excludes the armature,
``mj_inverse`` includes it.  Inverse dynamics here is ``mj_inverse`` with gravity zero and constraints, springs,
dampers and fluid forces disabled for the call (:func:`inverse_dynamics_options`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

import mujoco
import numpy as np

from koenig_check.engines.base import as_batches
from koenig_check.engines.energy import EnergyParts


@contextlib.contextmanager
def inverse_dynamics_options(model: mujoco.MjModel) -> Iterator[mujoco.MjModel]:
    """The model with gravity, fluid forces, constraints, springs and dampers off, for the ``with`` block only.

    The options are set on the model itself and restored, not on a copy: a copy of a model with large meshes
    weighed on the suite's memory (dm_control's fruitfly: 65 MB a copy).

    Parameters
    ----------
    model : mujoco.MjModel

    Yields
    ------
    mujoco.MjModel
        ``model`` itself.
    """
    opt = model.opt
    saved = (opt.gravity.copy(), float(opt.density), float(opt.viscosity), int(opt.disableflags))
    try:
        opt.gravity[:] = 0.0
        opt.density = 0.0
        opt.viscosity = 0.0
        off = mujoco.mjtDisableBit
        opt.disableflags |= int(off.mjDSBL_CONSTRAINT | off.mjDSBL_SPRING | off.mjDSBL_DAMPER)
        yield model
    finally:
        opt.gravity[:], opt.density, opt.viscosity, opt.disableflags = saved


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

    def _energy(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """Return ``mj_energyVel`` (``½ q̇ᵀ M q̇``, armature included) pose by pose."""
        model = self.model
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
        out = np.empty_like(qvel)
        with inverse_dynamics_options(self.model) as m:
            d = mujoco.MjData(m)
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
