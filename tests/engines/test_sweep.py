"""The engines' one-pass sweep gives what their public methods give, state by state."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.formulas.point_masses import equimomental_points
from koenig_check.run.poses import random_poses

FREE_BALL_HINGE = Path(__file__).resolve().parents[1] / "data" / "free_ball_hinge.xml"
MODELS = Path(__file__).resolve().parents[2] / "models"


@pytest.mark.parametrize("model", [FREE_BALL_HINGE, MODELS / "armature_chain.xml", MODELS / "serial7.urdf"])
@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_sweep_equals_the_public_methods(model: Path, engine: str) -> None:
    eng = getattr(load_model(model), engine)
    poses = random_poses(eng.model if engine == "mujoco" else load_model(model).mujoco.model, 25, seed=4)
    states, pv, rigid, armature = eng.sweep(poses.qpos, poses.qvel, None)
    public = eng.segment_states(poses.qpos, poses.qvel)
    for name in ("com", "v_com", "rotation", "omega", "pole", "v_pole", "rotation_ref", "com_ref", "pole_ref"):
        np.testing.assert_array_equal(getattr(states, name), getattr(public, name), err_msg=name)
    energy = eng.kinetic_energy(poses.qpos, poses.qvel)
    np.testing.assert_array_equal(rigid, energy.rigid)
    np.testing.assert_array_equal(armature, energy.armature)
    offsets, _ = equimomental_points(states.mass, states.inertia_body)
    _, pv, _, _ = eng.sweep(poses.qpos, poses.qvel, offsets)
    # MuJoCo: the same route (cvel); Pinocchio: the world Jacobian's twist here, data.v in the public method.
    np.testing.assert_allclose(pv, eng.point_velocities(poses.qpos, poses.qvel, offsets), rtol=1e-12, atol=1e-12)
    assert pv.shape == (25, states.n_segments, 6, 3)
