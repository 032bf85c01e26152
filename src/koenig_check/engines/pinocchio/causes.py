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

#: The releases of the other engines these readings were measured on.
_MUJOCO, _DRAKE, _NEWTON = "4.0.0", "1.51.1", "1.8.0"


def _mjcf(
    slug: str,
    construct: str,
    how: str,
    quantities: tuple[str, ...],
    brief: str,
    hint: str,
    fixture: str,
    drake: str = "",
    loses_joints: bool = False,
    twin: str = "",
    newton: str = "",
) -> Cause:
    """A construct of an MJCF file Pinocchio's parser reads differently; Drake reads it as written unless ``drake``.

    ``newton``: how Newton's ``add_mjcf`` reads it differently too (measured on real files: dm_control's cheetah).
    """
    return Cause(
        id=f"pinocchio.mjcf.{slug}",
        construct=construct,
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured=_MUJOCO),
            Reading("pinocchio", "differently", how, measured=MEASURED),
            Reading("drake", "differently", drake, measured=_DRAKE)
            if drake
            else Reading("drake", "as written", measured=_DRAKE),
            *([Reading("newton", "differently", newton, measured=_NEWTON)] if newton else []),
        ),
        quantities=quantities,
        brief=brief,
        hint=hint,
        fixture=fixture,
        loses_joints=loses_joints,
        twin=twin,
    )


CAUSES: tuple[Cause, ...] = (
    _mjcf(
        "class-geom-mass",
        "<geom mass> given by a <default> class",
        "ignores the class's mass: density × volume of the geom",
        ("mass", "inertia"),
        "geom mass from a default class not applied by Pinocchio",
        "write mass= on the geom itself",
        "class_geom_mass.xml",
    ),
    _mjcf(
        "class-geom-pos",
        "<geom pos> given by a <default> class",
        "ignores the class's pos: the geom at the body origin",
        ("com", "inertia"),
        "geom pos from a default class not applied by Pinocchio",
        "write pos= on the geom itself",
        "class_geom_pos.xml",
    ),
    _mjcf(
        "class-joint-pos",
        "<joint pos> given by a <default> class",
        "ignores the class's pos: the joint turns about the body origin",
        ("kinematics",),
        "joint pos from a default class not applied by Pinocchio",
        "write pos= on the joint itself",
        "class_joint_pos.xml",
    ),
    _mjcf(
        "include",
        "<include file=...>",
        "ignores the element: the included bodies, joints and default classes are missing",
        ("mass", "com", "inertia", "joints"),
        "<include> ignored by Pinocchio's MJCF parser",
        "load a file without <include> (e.g. the robot's own file)",
        "include.xml",
        loses_joints=True,
    ),
    _mjcf(
        "frame",
        "<frame> holding bodies or geoms",
        "skips the element and everything inside it",
        ("mass", "com", "joints"),
        "<frame> not read by Pinocchio's MJCF parser",
        "give the bodies and geoms inside it the frame's pose and remove the <frame> (MuJoCo resolves it at "
        "compile time); koenig-check export MODEL --to mjcf writes it out",
        "frame.xml",
        drake="skips the element and everything inside it (drake.mjcf.frame)",
        loses_joints=True,
        twin="frame_twin.xml",
    ),
    _mjcf(
        "bare-body",
        "<body> without any attribute",
        "skips the body: its geoms and joints are missing, its child bodies hang from its parent",
        ("mass", "com", "joints"),
        "<body> without any attribute skipped by Pinocchio's MJCF parser",
        "give the body a name (or any attribute)",
        "bare_body.xml",
        loses_joints=True,
    ),
    _mjcf(
        "axisangle-length",
        "axisangle= with an axis of other than unit length",
        "does not normalize the axis: the rotation it builds is distorted",
        ("inertia", "kinematics"),
        "axisangle axis not normalized",
        "write a unit axis",
        "axisangle_length.xml",
    ),
    _mjcf(
        "replicate",
        "<replicate count=...>",
        "skips the element: the copies MuJoCo makes are missing",
        ("mass", "com", "joints"),
        "<replicate> not read by Pinocchio's MJCF parser",
        "koenig-check export MODEL --to mjcf writes the copies out (no <replicate>, no <frame>)",
        "replicate.xml",
        drake="skips the element and everything inside it: the copies are missing",
        loses_joints=True,
        twin="replicate_twin.xml",
        newton="skips the element and everything inside it: the copies are missing",
    ),
    _mjcf(
        "root-bodies",
        "several <body> elements directly in <worldbody>",
        "reads only the first root body",
        ("mass", "com", "joints"),
        "Pinocchio's MJCF parser reads only the first root body",
        "put the robot in one root body, or load each root body's file alone",
        "root_bodies.xml",
        loses_joints=True,
    ),
    _mjcf(
        "root-pose",
        "pos / orientation of a root body without a joint",
        "drops the pose: the robot stands at the world origin",
        ("kinematics", "com"),
        "jointless root body's pose dropped by Pinocchio",
        "a constant world transform between the engines: koenig-check compares segments after removing it",
        "root_pose.xml",
    ),
    _mjcf(
        "settotalmass",
        "<compiler settotalmass=...>",
        "ignores the option: the file's masses unscaled",
        ("mass", "inertia"),
        "settotalmass not applied by Pinocchio",
        "scale the masses in the file and remove settotalmass",
        "settotalmass.xml",
        drake="ignores the option (with a warning): the file's masses unscaled",
        twin="settotalmass_twin.xml",
        newton="ignores the option too: the file's masses unscaled (model.body_mass)",
    ),
    _mjcf(
        "mesh-mass",
        "<geom> with a mesh",
        "does not compute mass and inertia from the mesh: a mesh-typed geom counts as 1 kg with unit inertia, a "
        "primitive fitted to a mesh as nothing",
        ("mass", "com", "inertia"),
        "geoms with a mesh, weighed otherwise by Pinocchio",
        "give the body an <inertial> (mass, pos, inertia)",
        "mesh_mass.xml",  # a mesh file; one given by vertices in the file Drake ignores: drake.mjcf.inline-mesh
        twin="mesh_mass_twin.xml",
    ),
    _mjcf(
        "visual-geoms",
        '<geom contype="0" conaffinity="0">',
        "reads the geom as visual only and leaves its mass out",
        ("mass", "com", "inertia"),
        "contype=0 and conaffinity=0 geoms left out by Pinocchio",
        "give the body an <inertial>, or give the geoms that weigh contype or conaffinity",
        "visual_geoms.xml",
    ),
    _mjcf(
        "inertiagrouprange",
        "<compiler inertiagrouprange=...>",
        "ignores the option: every geom's mass counted",
        ("mass", "com", "inertia"),
        "inertiagrouprange not applied by Pinocchio",
        "give the geoms left out mass 0 (or density 0) and remove inertiagrouprange",
        "inertiagrouprange.xml",
        drake="ignores the option (with a warning): every geom's mass counted",
        twin="inertiagrouprange_twin.xml",
    ),
    Cause(
        id="pinocchio.urdf.planar-axis",
        construct='<joint type="planar"> with an <axis> other than z',
        formats=("urdf",),
        readings=(
            Reading("mujoco", "as written", measured=_MUJOCO),
            Reading("pinocchio", "differently", "one planar joint about z: ignores the axis", measured=MEASURED),
            Reading(
                "drake",
                "differently",
                "one planar joint, not MuJoCo's three, in the same plane (the same M spectrum and g(q))",
                measured=_DRAKE,
            ),
        ),
        quantities=("joints", "kinematics"),
        brief="URDF planar joint read about z by Pinocchio, ignoring its axis",
        hint='write <axis xyz="0 0 1"/> and turn the joint\'s <origin> so that its z is the normal',
        fixture="planar_axis.urdf",
        twin="planar_axis_twin.xml",
    ),
    Cause(
        id="pinocchio.mjcf.option-gravity",
        construct="<option gravity>",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "differently", _OPTION_IGNORED, measured=MEASURED),
            Reading("drake", "as written", measured="1.51.1"),
            Reading("newton", "differently", "add_mjcf ignores it too: model.gravity (0, 0, -9.81)", measured=_NEWTON),
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
        twin="flag_gravity_disable_twin.xml",
        twin_causes=("pinocchio.mjcf.option-gravity",),
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
            Reading("newton", "differently", "add_mjcf ignores <attach> too", measured=_NEWTON),
        ),
        quantities=("joints", "mass"),
        brief="<attach> not read by Pinocchio's MJCF parser",
        hint="load a file with the attached bodies written out (MuJoCo's MjSpec.to_xml of the composed model)",
        fixture="attach.xml",
        loses_joints=True,
        twin="attach_twin.xml",
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
    pin.forwardKinematics(model, data, q0)
    masses = [model.inertias[j].mass for j in range(1, model.njoints)]
    mass = float(sum(masses))
    weighted = sum(
        (m * data.oMi[j].act(model.inertias[j].lever) for j, m in zip(range(1, model.njoints), masses, strict=True)),
        np.zeros(3),
    )
    return Measurement(
        joints=tuple(sorted(model.names[j] for j in moving)),
        mass=mass,
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in model.gravity.linear),
        gravity_forces={j: float(tau[i]) for j, i in one_dof.items()},
        armature={j: float(model.armature[i]) for j, i in one_dof.items() if model.armature[i]},
        com=tuple(float(c) for c in (weighted / mass if mass > 0 else np.zeros(3))),
        spectrum=tuple(float(x) for x in np.linalg.eigvalsh(np.asarray(full, dtype=float))),
    )
