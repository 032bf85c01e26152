"""MuJoCo's gravity terms: the gravity it applies, ``g(q)`` and the potential energy, springs apart.

MuJoCo has no ``g(q)`` call; its maintainers point to ``qfrc_bias`` at zero velocity (``mj_rne`` without
acceleration), which honours ``<flag gravity="disable"/>`` and never includes springs (those are in
``qfrc_spring``).  ``mj_energyPos`` adds the joint and tendon spring energy to the gravity energy: the springs'
part is ``mj_energyPos`` with gravity disabled for the call, the gravity part the rest.  The disable flag leaves
``opt.gravity`` at its value and changes only the flag bit, so :meth:`MujocoGravity.gravity_vector` reads both.
"""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.base import as_batches
from koenig_check.engines.potential import PotentialParts

_GRAVITY_OFF = int(mujoco.mjtDisableBit.mjDSBL_GRAVITY)


def gravity_disabled(model: mujoco.MjModel) -> bool:
    """Whether the model disables gravity (``<flag gravity="disable"/>``).

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    bool
    """
    return bool(model.opt.disableflags & _GRAVITY_OFF)


class MujocoGravity:
    """The gravity methods of :class:`~koenig_check.engines.mujoco.adapter.MujocoEngine` (contract: ``Engine``'s)."""

    model: mujoco.MjModel
    nq: int
    nv: int

    def gravity_vector(self) -> np.ndarray:
        """Return ``opt.gravity``, or zero under ``<flag gravity="disable"/>``."""
        if gravity_disabled(self.model):
            return np.zeros(3)
        return np.array(self.model.opt.gravity, dtype=float)

    def generalized_gravity(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``qfrc_bias`` at zero velocity (``mj_rne`` without acceleration)."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        m = self.model
        d = mujoco.MjData(m)
        out = np.empty((qpos.shape[0], self.nv))
        for p in range(qpos.shape[0]):
            d.qpos[:] = qpos[p]
            d.qvel[:] = 0.0
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            mujoco.mj_comVel(m, d)
            mujoco.mj_rne(m, d, 0, out[p])
        return out

    def potential_energy(self, qpos: np.ndarray) -> PotentialParts:
        """Return ``mj_energyPos`` split into gravity and springs (the springs' part with gravity disabled)."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        total = _energy_pos(self.model, qpos)
        springs = _energy_pos(self.model, qpos, gravity=False)
        return PotentialParts(gravity=total - springs, springs=springs)


def _energy_pos(model: mujoco.MjModel, qpos: np.ndarray, gravity: bool = True) -> np.ndarray:
    """``mj_energyPos`` pose by pose, ``mjENBL_ENERGY`` (and gravity off if asked) set for the call only.

    The flags are set on the model itself and restored, not on a copy: a copy of a model with large meshes
    doubled the suite's memory (dm_control's fruitfly).
    """
    saved = (int(model.opt.enableflags), int(model.opt.disableflags))
    try:
        model.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
        if not gravity:
            model.opt.disableflags |= _GRAVITY_OFF
        d = mujoco.MjData(model)
        out = np.empty(qpos.shape[0])
        for p in range(qpos.shape[0]):
            d.qpos[:] = qpos[p]
            mujoco.mj_kinematics(model, d)
            mujoco.mj_comPos(model, d)
            mujoco.mj_tendon(model, d)
            mujoco.mj_energyPos(model, d)
            out[p] = d.energy[0]
        return out
    finally:
        model.opt.enableflags, model.opt.disableflags = saved
