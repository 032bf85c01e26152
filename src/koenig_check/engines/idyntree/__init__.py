"""iDynTree (optional extra ``[idyntree]``): a URDF read by its ``ModelLoader``, dynamics by ``KinDynComputations``."""

from koenig_check.engines.specs import EngineSpec

#: iDynTree's facts (:mod:`koenig_check.engines.specs`): optional, attached to a model loaded in MuJoCo and Pinocchio.
SPEC = EngineSpec(
    name="idyntree",
    label="iDynTree",
    module="idyntree",
    extra="idyntree",
    attach="koenig_check.engines.idyntree.attach:attach",
    load_alone="koenig_check.engines.idyntree.attach:load_alone",
    formats=("urdf",),
    precision=1e-12,  # double precision throughout
    color="tab:olive",
)
