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
        id="pinocchio.mjcf.attach",
        construct="<attach> of a <model> asset (model composition)",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", versions=">=3.2", measured="4.0.0"),
            Reading(
                "pinocchio",
                "differently",
                "ignores <attach>: the attached model's bodies and joints are missing",
                measured=MEASURED,
            ),
            Reading(
                "drake",
                "differently",
                "ignores <attach> with a warning ('currently unsupported and will be ignored')",
                measured="1.51.1",
            ),
        ),
        quantities=("joints", "mass"),
        brief="<attach> not read by Pinocchio's MJCF parser",
        hint="load a file with the attached bodies written out (MuJoCo's MjSpec.to_xml of the composed model)",
        fixture="attach.xml",
        loses_joints=True,
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
    one_dof = {model.names[j]: model.joints[j].idx_v for j in range(1, model.njoints) if model.joints[j].nv == 1}
    moving = [j for j in range(1, model.njoints) if model.joints[j].nv > 0]
    return Measurement(
        joints=tuple(sorted(model.names[j] for j in moving)),
        mass=float(sum(model.inertias[j].mass for j in range(1, model.njoints))),
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in model.gravity.linear),
        armature={j: float(model.armature[i]) for j, i in one_dof.items() if model.armature[i]},
    )
