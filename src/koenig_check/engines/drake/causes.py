"""The constructs Drake's parsers read differently from the file, and Drake's own reading of a fixture."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: The Drake release these readings were measured on.
MEASURED = "1.51.1"

#: The releases of the other engines these readings were measured on.
_MUJOCO, _PINOCCHIO = "4.0.0", "4.1.0"


def _drake(
    cause_id: str,
    construct: str,
    how: str,
    quantities: tuple[str, ...],
    brief: str,
    hint: str,
    fixture: str,
    mujoco: str = "as written",
    pinocchio: str = "",
    loses_joints: bool = False,
    twin: str = "",
    twin_causes: tuple[str, ...] = (),
) -> Cause:
    """A construct Drake's parser reads differently; Pinocchio reads it as written unless ``pinocchio`` says how."""
    other = {
        "refuses": "refuses the file (without --repair-inertia)",
        "differently": "fuses the massless link into its parent without its inertia "
        "(mujoco.any.fusestatic-massless-inertia)",
    }
    return Cause(
        id=f"drake.{cause_id}",
        construct=construct,
        formats=("mjcf", "urdf") if cause_id.startswith("any.") else (cause_id.split(".")[0],),
        readings=(
            Reading("mujoco", mujoco, other.get(mujoco, ""), measured=_MUJOCO),
            Reading("pinocchio", "differently", pinocchio, measured=_PINOCCHIO)
            if pinocchio
            else Reading("pinocchio", "as written", measured=_PINOCCHIO),
            Reading("drake", "differently", how, measured=MEASURED),
        ),
        quantities=quantities,
        brief=brief,
        hint=hint,
        fixture=fixture,
        loses_joints=loses_joints,
        twin=twin,
        twin_causes=twin_causes,
    )


CAUSES: tuple[Cause, ...] = (
    _drake(
        "mjcf.frame",
        "<frame> holding bodies or geoms",
        "skips the element and everything inside it",
        ("mass", "com", "joints"),
        "<frame> not read by Drake's MJCF parser",
        "give the bodies and geoms inside it the frame's pose and remove the <frame> (MuJoCo resolves it at "
        "compile time); koenig-check export MODEL --to mjcf writes it out",
        "frame.xml",
        pinocchio="skips the element and everything inside it (pinocchio.mjcf.frame)",
        loses_joints=True,
        twin="frame_twin.xml",
    ),
    _drake(
        "urdf.reflected-inertia",  # MJCF: a driven joint's armature is read as written (tests/engines/drake)
        "<transmission> actuator with drake:rotor_inertia and drake:gear_ratio",
        "adds the reflected inertia rotor inertia × gear ratio² to the joint",
        ("armature",),
        "reflected inertia (rotor inertia × gear ratio²) that MuJoCo's armature does not match",
        "Drake's extension: give MuJoCo the same armature, or compare without Drake",
        "reflected_inertia.urdf",
    ),
    _drake(
        "mjcf.unactuated-armature",
        "<joint armature=...> that no motor drives",
        "does not read it (a driven joint's armature it reads as the motor's reflected inertia)",
        ("armature",),
        "armature of a joint no motor drives not read by Drake's MJCF parser",
        "drive the joint with a <motor>, or compare without Drake",
        "unactuated_armature.xml",
    ),
    _drake(
        "urdf.replaced-inertia",
        "<inertial> Drake judges unphysical (a massless link with inertia, A + B < C, a negative moment)",
        "warns and builds the link from other values",
        ("mass", "inertia"),
        "inertia judged unphysical replaced by Drake's URDF parser",
        "write a physically valid inertia (A + B >= C, positive moments)",
        "replaced_inertia.urdf",
        mujoco="differently",
        twin="fusestatic_massless_inertia_twin.urdf",  # the same robot as replaced_inertia.urdf
    ),
    _drake(
        "mjcf.multi-joint-anchor",
        "a body with several joints and a pos",
        "drops the body's pos for its first joint: turns it about another point",
        ("kinematics",),
        "body pos dropped by Drake's MJCF parser for the first of several joints",
        "give each joint a body of its own",
        "multi_joint_anchor.xml",
    ),
    _drake(
        "mjcf.ignored-geom",
        "a <geom> Drake's MJCF parser does not support (e.g. a box given by fromto)",
        "warns that the geom will be ignored and builds the body without its mass",
        ("mass", "com", "inertia"),
        "geom ignored by Drake's MJCF parser",
        "write the geom with pos and size (or give the body an <inertial>)",
        "ignored_geom.xml",
    ),
    _drake(
        "mjcf.inline-mesh",
        "<mesh> given by its vertices in the file (no file=), used by a <geom>",
        "ignores the mesh and the geoms that use it (with warnings): their mass is missing",
        ("mass", "com", "inertia"),
        "mesh given by vertices in the file ignored by Drake's MJCF parser",
        "write the mesh to a file (OBJ) and give the <mesh> its file=, or give the body an <inertial>",
        "inline_mesh.xml",
        pinocchio="counts a mesh-typed geom as 1 kg with unit inertia (pinocchio.mjcf.mesh-mass)",
        twin="mesh_mass_twin.xml",
    ),
    _drake(
        "mjcf.flag-gravity-disable",
        '<option><flag gravity="disable"/>',
        "ignores the flag (with a warning): the file's gravity",
        ("gravity",),
        '<flag gravity="disable"/> ignored: the file\'s gravity applied',
        "call plant.mutable_gravity_field().set_gravity_vector([0, 0, 0])",
        "flag_gravity_disable.xml",
        pinocchio="ignores all of <option>: gravity (0, 0, -9.81) (pinocchio.mjcf.flag-gravity-disable)",
        twin="flag_gravity_disable_twin.xml",
        twin_causes=("pinocchio.mjcf.option-gravity",),
    ),
    _drake(
        "mjcf.class-joint-default",
        "<joint> default inherited through a <default> class with no <joint> of its own",
        "loses them: the joint gets Drake's defaults (axis 0 0 1)",
        ("kinematics", "gravity"),  # a planar arm's M cannot see the axis, g(q) does
        "joint default inherited through a class without <joint> lost: wrong joint axis",
        "write the <joint> attributes in the class the body uses",
        "class_joint_inherited.xml",
    ),
)


def measure(path: Path) -> Measurement:
    """Drake's reading of a model file: ``Parser.AddModels``, ``CalcMassMatrix`` at the default context.

    Parameters
    ----------
    path : pathlib.Path

    Returns
    -------
    Measurement

    Raises
    ------
    Exception
        Drake refuses the file (its own exception).
    """
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import MultibodyPlant
    from pydrake.multibody.tree import BodyIndex

    plant = MultibodyPlant(0.0)
    Parser(plant).AddModels(path)
    plant.Finalize()
    context = plant.CreateDefaultContext()
    full = plant.CalcMassMatrix(context)
    applied = -np.asarray(plant.CalcGravityGeneralizedForces(context))  # Drake's is the force gravity exerts
    joints = [plant.get_joint(i) for i in plant.GetJointIndices()]
    moving = [j for j in joints if j.num_velocities() > 0]
    one_dof = {j.name(): j.velocity_start() for j in moving if j.num_velocities() == 1}
    welded = {b.index() for b in plant.GetBodiesWeldedTo(plant.world_body())}
    bodies = [plant.get_body(BodyIndex(i)) for i in range(plant.num_bodies())]
    moving_bodies = [b for b in bodies if b.index() not in welded]
    mass = float(sum(b.default_mass() for b in moving_bodies))
    weighted = sum(
        (b.default_mass() * (b.EvalPoseInWorld(context) @ b.default_com()) for b in moving_bodies), np.zeros(3)
    )
    armature: dict[str, float] = {}
    for a in (plant.get_joint_actuator(i) for i in plant.GetJointActuatorIndices()):
        reflected = float(a.default_reflected_inertia())
        if reflected and a.joint().name() in one_dof:
            armature[a.joint().name()] = reflected
    return Measurement(
        joints=tuple(sorted(j.name() for j in moving)),
        mass=mass,
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in plant.gravity_field().gravity_vector()),
        gravity_forces={j: float(applied[i]) for j, i in one_dof.items()},
        armature=armature,
        com=tuple(float(c) for c in (weighted / mass if mass > 0 else np.zeros(3))),
        spectrum=tuple(float(x) for x in np.linalg.eigvalsh(np.asarray(full, dtype=float))),
    )
