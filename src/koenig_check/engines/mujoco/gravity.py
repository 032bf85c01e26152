"""MuJoCo's gravity terms: the gravity it applies, ``g(q)`` and the potential energy, springs apart.

MuJoCo has no ``g(q)`` call; its maintainers point to ``qfrc_bias`` at zero velocity (``mj_rne`` without
acceleration), which honours ``<flag gravity="disable"/>`` and never includes springs (those are in
``qfrc_spring``).  ``mj_energyPos`` adds the joint and tendon spring energy to the gravity energy: the springs'
part is ``mj_energyPos`` on a copy with gravity disabled, the gravity part the rest.  The disable flag leaves
``opt.gravity`` at its value and changes only the flag bit, so :meth:`MujocoGravity.gravity_vector` reads both.
"""

from __future__ import annotations

import copy

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
        springs_only = copy.copy(self.model)
        springs_only.opt.disableflags |= _GRAVITY_OFF
        springs = _energy_pos(springs_only, qpos)
        return PotentialParts(gravity=total - springs, springs=springs)


def _energy_pos(model: mujoco.MjModel, qpos: np.ndarray) -> np.ndarray:
    """``mj_energyPos`` (``mjENBL_ENERGY`` on a copy) pose by pose."""
    m = copy.copy(model)
    m.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    d = mujoco.MjData(m)
    out = np.empty(qpos.shape[0])
    for p in range(qpos.shape[0]):
        d.qpos[:] = qpos[p]
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_tendon(m, d)
        mujoco.mj_energyPos(m, d)
        out[p] = d.energy[0]
    return out
