"""MuJoCo: the loader (MJCF or URDF through MuJoCo's compiler, inertia repair) and the adapter."""

from koenig_check.engines.specs import EngineSpec

#: MuJoCo's facts (:mod:`koenig_check.engines.specs`): every model is loaded in it; it defines the canonical layout.
SPEC = EngineSpec(name="mujoco", label="MuJoCo", module="mujoco", required=True, color="tab:blue", reference=True)
