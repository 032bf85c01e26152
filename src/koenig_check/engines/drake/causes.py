"""The constructs Drake's parsers read differently from the file: its entries in the catalogue of causes."""

from __future__ import annotations

from koenig_check.causes import Cause, Reading

_MEASURED = "mujoco 4.0.0, pin 4.1.0, drake 1.51.1"

CAUSES = (
    Cause(
        id="drake.mjcf.flag-gravity-disable",
        construct='<option><flag gravity="disable"/>',
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", "no gravity (opt.gravity kept, the flag bit set)", "", _MEASURED),
            Reading("pinocchio", "differently", "ignores all of <option>: gravity (0, 0, -9.81)", "", _MEASURED),
            Reading(
                "drake", "differently", "ignores the flag (with a warning): the file's gravity", measured=_MEASURED
            ),
        ),
        quantities=("gravity",),
        brief='<flag gravity="disable"/> ignored: the file\'s gravity applied',
        hint="call plant.mutable_gravity_field().set_gravity_vector([0, 0, 0])",
        fixture="flag_gravity_disable.xml",
    ),
    Cause(
        id="drake.mjcf.class-joint-default",
        construct="<joint> default inherited through a <default> class with no <joint> of its own",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", "inherits the parent class's joint attributes", "", _MEASURED),
            Reading("pinocchio", "as written", "inherits the parent class's joint attributes", "", _MEASURED),
            Reading(
                "drake", "differently", "loses them: the joint gets Drake's defaults (axis 0 0 1)", measured=_MEASURED
            ),
        ),
        quantities=("kinematics", "joints"),
        brief="joint default inherited through a class without <joint> lost: wrong joint axis",
        hint="write the <joint> attributes in the class the body uses",
        fixture="class_joint_inherited.xml",
    ),
)
