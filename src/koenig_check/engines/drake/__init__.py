"""Drake (optional extra ``[drake]``): the loader, the state map to canonical coordinates, the adapter."""

from koenig_check.engines.specs import EngineSpec

#: Drake's facts (:mod:`koenig_check.engines.specs`): optional, attached to a model loaded in MuJoCo and Pinocchio.
SPEC = EngineSpec(
    name="drake",
    label="Drake",
    module="pydrake",
    distribution="drake",  # pip's name (the module is pydrake): the catalogue's versions are read from it
    extra="drake",
    attach="koenig_check.engines.drake.attach:attach",
    load_alone="koenig_check.engines.drake.building:load_drake_engine",
    color="tab:green",
    tie_breaker=True,
    mjcf_meshes=(".obj",),
)
