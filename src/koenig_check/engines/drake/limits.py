"""What Drake's parsers are known not to read (measured on Drake 1.51): its parser limits, declared as data.

A model that uses one of these is another robot in Drake: Drake does not vote there
(:mod:`koenig_check.diagnosis.engine_limits`); named by the user, it could not check the model.
"""

from __future__ import annotations

from typing import Any

from koenig_check.engines.drake.inertia import MASS_IN_DRAKE
from koenig_check.engines.limit import ParserLimit, none_where_reference_has, one_of_several_joints
from koenig_check.findings import Finding, Kind


def _replaced(finding: Finding, mj_model: Any) -> bool:
    """An ``INERTIA`` finding on a moving link whose ``<inertial>`` Drake's URDF parser replaced by its own.

    A link welded to the world (in no segment: pybullet_data's kuka_iiwa base, a ROS base link) changes no energy
    and no M (measured: Drake's M of the kuka equals Pinocchio's to 7e-16): Drake still checks the robot.
    """
    return MASS_IN_DRAKE in finding.values and bool(finding.segments)


#: Drake's parser limits: the pos of a body with several joints dropped for the first of them (which moves
#: them all), the armature of joints no motor drives, the inertias it judges unphysical (a massless link with
#: a rotational inertia becomes a 1 kg body).
LIMITS = (
    ParserLimit("drops the pos of multi-joint bodies", kind=Kind.ANCHOR, when=one_of_several_joints),
    ParserLimit("ignores armature", kind=Kind.ARMATURE, when=none_where_reference_has),
    ParserLimit("replaces inertias it judges unphysical", names="links", kind=Kind.INERTIA, when=_replaced),
)
