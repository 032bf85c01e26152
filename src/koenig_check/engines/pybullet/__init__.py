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
    # It diagonalizes every inertia (btMatrix3x3::diagonalize, threshold 1e-6, 30 steps) and drops what is left off
    # the diagonal: up to 1e-6 of the trace, 3e-6 of the largest moment (measured: 1.2e-6 on tiago's wheels, whose
    # two near-equal moments converge slowest; 6.3e-8 on panda's links).
    precision=3e-6,
    color="tab:red",
)
