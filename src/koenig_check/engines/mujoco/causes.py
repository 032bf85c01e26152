"""The causes MuJoCo departs in (none declared yet beyond the others' readings), and MuJoCo's reading of a fixture."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.cause import Cause
from koenig_check.engines.measurement import Measurement

#: Constructs MuJoCo's compiler reads differently from the other engines.
CAUSES: tuple[Cause, ...] = ()


def measure(path: Path) -> Measurement:
    """MuJoCo's reading of a model file, from ``MjModel.from_xml_path`` and ``mj_fullM`` at ``qpos0``.

    Parameters
    ----------
    path : pathlib.Path

    Returns
    -------
    Measurement

    Raises
    ------
    ValueError
        MuJoCo refuses the file (its own text).
    """
    m = mujoco.MjModel.from_xml_path(str(path))
    d = mujoco.MjData(m)
    d.qpos[:] = m.qpos0
    mujoco.mj_forward(m, d)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    one_dof = {
        m.joint(j).name: int(m.jnt_dofadr[j])
        for j in range(m.njnt)
        if int(m.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
    }
    disabled = bool(m.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_GRAVITY)
    return Measurement(
        joints=tuple(sorted(m.joint(j).name for j in range(m.njnt))),
        mass=float(m.body_mass[m.body_weldid != 0].sum()),
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=(0.0, 0.0, 0.0) if disabled else tuple(float(g) for g in m.opt.gravity),
        armature={j: float(m.dof_armature[i]) for j, i in one_dof.items() if m.dof_armature[i]},
    )
