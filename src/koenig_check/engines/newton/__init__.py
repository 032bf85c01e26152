"""Newton (optional extra ``[newton]``): the loader, the state map to canonical coordinates, the adapter, its causes."""

from koenig_check.engines.specs import EngineSpec

#: Newton computes in float32: its round-off relative to a quantity's scale is up to about 5e-6 on the project's
#: models and example-robot-data robots, and up to 1.4e-5 on real files with longer chains or a floating base
#: (pybullet_data's racecar 1.3e-5, robosuite's panda 1.4e-5 and iiwa 1.1e-5, where Newton's body_mass and
#: body_inertia equal the file's): two engines agree with Newton within 3e-5 relative.
PRECISION = 3e-5

#: Newton's facts (:mod:`koenig_check.engines.specs`): optional, attached to a model loaded in MuJoCo and Pinocchio.
SPEC = EngineSpec(
    name="newton",
    label="Newton",
    module="newton",
    extra="newton",
    attach="koenig_check.engines.newton.attach:attach",
    load_alone="koenig_check.engines.newton.attach:load_alone",
    color="tab:olive",
    formats=("mjcf", "urdf"),
    precision=PRECISION,
)
