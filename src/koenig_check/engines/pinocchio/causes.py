"""The constructs Pinocchio's parsers read differently from the file: its entries in the catalogue of causes."""

from __future__ import annotations

from koenig_check.causes import Cause, Reading

_MEASURED = "mujoco 4.0.0, pin 4.1.0, drake 1.51.1"
_OPTION_IGNORED = "ignores all of <option>: its gravity is always (0, 0, -9.81)"

CAUSES = (
    Cause(
        id="pinocchio.mjcf.option-gravity",
        construct="<option gravity>",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", "uses the file's gravity", "", _MEASURED),
            Reading("pinocchio", "differently", _OPTION_IGNORED, "", _MEASURED),
            Reading("drake", "as written", "uses the file's gravity", "", _MEASURED),
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
            Reading("mujoco", "as written", "no gravity (opt.gravity kept, the flag bit set)", "", _MEASURED),
            Reading("pinocchio", "differently", _OPTION_IGNORED, "", _MEASURED),
            Reading(
                "drake", "differently", "ignores the flag (with a warning): the file's gravity", measured=_MEASURED
            ),
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
            Reading("mujoco", "as written", "places the body, and all it carries, at its pose", "", _MEASURED),
            Reading(
                "pinocchio", "differently", "drops the pose: the robot is rotated against gravity", measured=_MEASURED
            ),
            Reading("drake", "as written", "welds the body at its pose", "", _MEASURED),
        ),
        quantities=("gravity",),
        brief="pose of a welded root body dropped: tilted against gravity",
        hint="add a free joint to the root body or rotate Pinocchio's gravity into the body's frame",
        fixture="welded_mount_tilted.xml",
    ),
)
