"""PyBullet (optional extra ``[pybullet]``): a URDF read by ``loadURDF`` as its users load a robot for dynamics."""

from koenig_check.engines.specs import EngineSpec

#: PyBullet's facts (:mod:`koenig_check.engines.specs`): optional, attached to a model loaded in MuJoCo and Pinocchio.
SPEC = EngineSpec(
    name="pybullet",
    label="PyBullet",
    module="pybullet",
    extra="pybullet",
    attach="koenig_check.engines.pybullet.attach:attach",
    load_alone="koenig_check.engines.pybullet.attach:load_alone",
    formats=("urdf",),
    precision=1e-7,  # it diagonalizes every inertia (up to 6.3e-8 lost per link)
    color="tab:red",
)
