"""What Newton's parsers and ``finalize()`` are known not to read as the file says (measured on Newton 1.8.0).

A model whose findings carry one of these causes (and change the energy beyond Newton's precision) is another
robot in Newton: Newton does not vote there (:mod:`koenig_check.diagnosis.engine_limits`); named by the user, it
could not check the model.
"""

from __future__ import annotations

from koenig_check.engines.limit import ParserLimit
from koenig_check.engines.newton.causes import MULTI_JOINT_POS, NO_INERTIAL, VALIDATION

LIMITS = (
    ParserLimit("gives links without <inertial> the mass of their collision shapes", names="links", cause=NO_INERTIAL),
    ParserLimit("replaces inertias it judges unphysical (finalize's validation)", names="links", cause=VALIDATION),
    ParserLimit("turns every joint of a multi-joint body about the first joint's pos", cause=MULTI_JOINT_POS),
)
