"""Pinocchio: the loader (URDF and MJCF parsers), the state map to canonical coordinates, the adapter."""

from koenig_check.engines.specs import EngineSpec

#: Pinocchio's facts (:mod:`koenig_check.engines.specs`): every model is loaded in it.
SPEC = EngineSpec(
    name="pinocchio",
    label="Pinocchio",
    module="pinocchio",
    distribution="pin",
    required=True,
    load_alone="koenig_check.engines.pinocchio.alone:load_alone",
    color="tab:orange",
)
