"""What iDynTree's URDF reader is known not to read as written (measured on 15.1): its parser limits, as data.

A model that uses one of these is another robot in iDynTree: iDynTree does not vote there
(:mod:`koenig_check.diagnosis.engine_limits`); named by the user, it could not check the model.
"""

from __future__ import annotations

from koenig_check.engines.limit import ParserLimit

#: iDynTree's parser limits: a massless link with a rotational inertia, fixed to another link, made a frame.
LIMITS = (
    ParserLimit(
        "makes a massless link with inertia a frame (its inertia dropped)",
        names="links",
        cause="idyntree.urdf.massless-link-inertia",
    ),
)
