"""The constructs Pinocchio's parsers read differently from the file (MuJoCo and Drake read them as written).

Each :class:`~koenig_check.causes.Cause` is measured on its fixture by the suite (``tests/causes/``) with
:func:`measure`, Pinocchio's own reading of a file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: The Pinocchio release these readings were measured on.
MEASURED = "4.1.0"
#: What Pinocchio's MJCF parser does with <option>.
_OPTION_IGNORED = "ignores all of <option>: its gravity is always (0, 0, -9.81)"

CAUSES: tuple[Cause, ...] = (
    Cause(
        id="pinocchio.mjcf.class-geom-mass",
        construct="<geom mass> given by a <default> class",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading(
                "pinocchio", "differently", "ignores the class's mass: density × volume of the geom", measured=MEASURED
            ),
            Reading("drake", "as written", measured="1.51.1"),
        ),
        quantities=("mass", "inertia"),
        brief="geom mass from a default class not applied by Pinocchio",
        hint="write mass= on the geom itself",
        fixture="class_geom_mass.xml",
    ),
    Cause(
        id="pinocchio.mjcf.option-gravity",
        construct="<option gravity>",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "differently", _OPTION_IGNORED, measured=MEASURED),
            Reading("drake", "as written", measured="1.51.1"),
        ),
        quantities=("gravity",),
        brief="<option gravity> ignored: gravity (0, 0, -9.81)",
        hint="set pinocchio_model.gravity to the file's vector after loading",
        fixture="option_gravity_moon.xml",
    ),
    Cause(
        id="pinocchio.mjcf.flag-gravity-disable",
        construct='<option><flag gravity="disable"/>',
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "differently", _OPTION_IGNORED, measured=MEASURED),
            Reading("drake", "differently", "ignores the flag (with a warning): the file's gravity", measured="1.51.1"),
        ),
        quantities=("gravity",),
        brief='<flag gravity="disable"/> ignored: gravity (0, 0, -9.81)',
        hint="set pinocchio_model.gravity to zero after loading",
        fixture="flag_gravity_disable.xml",
    ),
    Cause(
        id="pinocchio.mjcf.welded-root-pose",
        construct="pose of a top-level <body> without a joint",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading(
                "pinocchio", "differently", "drops the pose: the robot is rotated against gravity", measured=MEASURED
            ),
            Reading("drake", "as written", measured="1.51.1"),
        ),
        quantities=("gravity",),
        brief="pose of a welded root body dropped: tilted against gravity",
        hint="add a free joint to the root body or rotate Pinocchio's gravity into the body's frame",
        fixture="welded_mount_tilted.xml",
    ),
)


def measure(path: Path) -> Measurement:
    """Pinocchio's reading of a model file: its parser, ``crba`` at the neutral configuration.

    Parameters
    ----------
    path : pathlib.Path
        An MJCF (``.xml``) or URDF (``.urdf``) file.

    Returns
    -------
    Measurement

    Raises
    ------
    Exception
        Pinocchio refuses the file (its own exception).
    """
    model = pin.buildModelFromUrdf(str(path)) if path.suffix == ".urdf" else pin.buildModelFromMJCF(str(path))
    data = model.createData()
    q0 = pin.neutral(model)
    full = pin.crba(model, data, q0)
    full = np.triu(full) + np.triu(full, 1).T
    tau = pin.computeGeneralizedGravity(model, data, q0)
    one_dof = {model.names[j]: model.joints[j].idx_v for j in range(1, model.njoints) if model.joints[j].nv == 1}
    moving = [j for j in range(1, model.njoints) if model.joints[j].nv > 0]
    return Measurement(
        joints=tuple(sorted(model.names[j] for j in moving)),
        mass=float(sum(model.inertias[j].mass for j in range(1, model.njoints))),
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in model.gravity.linear),
        gravity_forces={j: float(tau[i]) for j, i in one_dof.items()},
        armature={j: float(model.armature[i]) for j, i in one_dof.items() if model.armature[i]},
    )
