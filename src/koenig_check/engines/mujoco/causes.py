"""The causes MuJoCo departs in, and MuJoCo's reading of a fixture."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: Constructs MuJoCo's compiler reads differently from the other engines.
CAUSES: tuple[Cause, ...] = (
    Cause(
        id="mujoco.any.fusestatic-massless-inertia",
        construct="a static link or body of mass 0 with a non-zero inertia, fused by fusestatic",
        formats=("urdf", "mjcf"),
        readings=(
            Reading(
                "mujoco", "differently", "fuses it into its parent without its rotational inertia", measured="4.0.0"
            ),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading(
                "drake", "differently", "gives the massless link 1 kg (drake.urdf.replaced-inertia)", measured="1.51.1"
            ),
        ),
        quantities=("inertia",),
        brief="fusestatic dropped the rotational inertia of a massless link",
        hint="give the link its mass, or move its inertia to its parent",
        fixture="fusestatic_massless_inertia.urdf",
        twin="fusestatic_massless_inertia_twin.urdf",
    ),
)


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
    moving = m.body_weldid != 0
    mass = float(m.body_mass[moving].sum())
    com = (m.body_mass[moving, None] * d.xipos[moving]).sum(axis=0) / mass if mass > 0 else np.zeros(3)
    disabled = bool(m.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_GRAVITY)
    return Measurement(
        joints=tuple(sorted(m.joint(j).name for j in range(m.njnt))),
        mass=mass,
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=(0.0, 0.0, 0.0) if disabled else tuple(float(g) for g in m.opt.gravity),
        gravity_forces={j: float(d.qfrc_bias[i]) for j, i in one_dof.items()},  # q̇ = 0: g(q0)
        armature={j: float(m.dof_armature[i]) for j, i in one_dof.items() if m.dof_armature[i]},
        com=tuple(float(c) for c in com),
        spectrum=tuple(float(x) for x in np.linalg.eigvalsh(np.asarray(full, dtype=float))),
    )
