"""An independent verdict for the engine cross-check: ½ q̇ᵀ M q̇ from each engine's own mass matrix.

``mujoco.mj_fullM`` and ``pinocchio.crba`` with each engine's armature taken off the diagonal; states drawn
with MuJoCo's own ``mj_integratePos`` and carried to Pinocchio by the pair's state map (the energy path of
the code under test is not used).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pinocchio as pin

AGREE = 1e-9  # relative difference under which the engines agree
DISAGREE = 1e-6  # relative difference over which they disagree (in between: no verdict)


def rigid_energies(pair, n_poses: int = 2, seed: int = 7) -> tuple[np.ndarray, np.ndarray]:
    """Rigid-body kinetic energies (MuJoCo, Pinocchio) at a few random states of a loaded pair."""
    m = pair.mujoco.model
    d = mujoco.MjData(m)
    pm = pair.pinocchio.model
    pd = pm.createData()
    rng = np.random.default_rng(seed)
    t_mj, t_pin = [], []
    for _ in range(n_poses):
        qpos = np.array(m.qpos0, dtype=float)
        mujoco.mj_integratePos(m, qpos, rng.uniform(-0.5, 0.5, m.nv), 1.0)
        qvel = rng.uniform(-1.0, 1.0, m.nv)
        d.qpos[:] = qpos
        mujoco.mj_forward(m, d)
        M = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, M)
        M -= np.diag(m.dof_armature)
        t_mj.append(0.5 * qvel @ M @ qvel)
        q, v = pair.state_map.to_pinocchio(qpos, qvel)
        Mp = np.array(pin.crba(pm, pd, q))
        Mp = np.triu(Mp) + np.triu(Mp, 1).T
        Mp -= np.diag(pm.armature)
        t_pin.append(0.5 * v @ Mp @ v)
    return np.array(t_mj), np.array(t_pin)


def engines_agree(pair, n_poses: int = 2) -> bool | None:
    """True / False when the independent energies clearly agree / disagree, None in between."""
    a, b = rigid_energies(pair, n_poses)
    rel = float(np.max(np.abs(a - b) / np.maximum(np.maximum(np.abs(a), np.abs(b)), 1e-300)))
    if rel <= AGREE:
        return True
    if rel >= DISAGREE:
        return False
    return None
