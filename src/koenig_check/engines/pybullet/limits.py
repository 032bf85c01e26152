"""What PyBullet's URDF reader is known not to read as written (measured on 3.2.7): its parser limits, as data.

A model that uses one of these is another robot in PyBullet: PyBullet does not vote there
(:mod:`koenig_check.diagnosis.engine_limits`); named by the user, it could not check the model.  The findings
that show them are made by :mod:`koenig_check.engines.pybullet.traps`.
"""

from __future__ import annotations

from typing import Any

from koenig_check.engines.limit import ParserLimit
from koenig_check.engines.pybullet.traps import MOMENTS_IN_PYBULLET, ZEROED
from koenig_check.findings import Finding


def _zeroed(finding: Finding, mj_model: Any) -> bool:
    """An ``INERTIA`` finding on a link whose inertia PyBullet set to zero."""
    return MOMENTS_IN_PYBULLET in finding.values


#: PyBullet's parser limits: 1 kg and a unit inertia for a moving link (or a floating root) without
#: ``<inertial>``; zero for an inertia that breaks the triangle inequality.
LIMITS = (
    ParserLimit("gives a link without <inertial> 1 kg", names="links", cause="pybullet.urdf.link-without-inertial"),
    ParserLimit(
        "gives a floating root link without <inertial> 1 kg",
        names="links",
        cause="pybullet.urdf.floating-root-without-inertial",
    ),
    ParserLimit("sets inertias breaking A + B >= C to zero", names="links", cause=ZEROED, when=_zeroed),
)
