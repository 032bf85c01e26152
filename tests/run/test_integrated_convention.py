"""The `integrated` angle convention along MuJoCo-simulated trajectories: it depends on the path."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.formulas.angles import integrate_angular_velocity, rotvec_angles
from koenig_check.run.poses import trajectory_poses

MODELS = Path(__file__).resolve().parents[2] / "models"

ONE_HINGE = """
<mujoco>
  <option integrator="RK4" timestep="0.001"/>
  <worldbody>
    <body name="rotor" pos="0.1 0.2 0.3">
      <joint name="spin" axis="0.3 -0.5 0.81"/>
      <inertial pos="0.05 0.02 -0.01" mass="1.3" fullinertia="0.03 0.05 0.06 0.004 -0.002 0.003"/>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_integrated_equals_rotvec_for_a_fixed_axis(tmp_path: Path, engine: str) -> None:
    path = tmp_path / "one_hinge.xml"
    path.write_text(ONE_HINGE)
    pair = load_model(path)
    poses = trajectory_poses(pair.mujoco.model, duration=1.5, samples=301, seed=2, velocity_scale=2.0)
    states = getattr(pair, engine).segment_states(poses.qpos, poses.qvel)
    integrated = integrate_angular_velocity(states.omega, poses.times)
    rotvec = rotvec_angles(states)
    assert np.abs(rotvec).max() > 0.5  # it really turned
    np.testing.assert_allclose(integrated, rotvec, atol=1e-9)


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_integrated_differs_from_rotvec_when_the_axis_changes(engine: str) -> None:
    pair = load_model(MODELS / "gimbal.xml")
    poses = trajectory_poses(pair.mujoco.model, duration=2.0, samples=2001, seed=0, velocity_scale=2.0)
    states = getattr(pair, engine).segment_states(poses.qpos, poses.qvel)
    inner = states.names.index("inner_x")
    integrated = integrate_angular_velocity(states.omega, poses.times)[:, inner]
    rotvec = rotvec_angles(states)[:, inner]
    np.testing.assert_allclose(integrated[0], 0.0, atol=0)
    np.testing.assert_allclose(rotvec[0], 0.0, atol=1e-12)  # the path starts at the reference pose
    # Compare where neither reading has wrapped past π (rotvec jumps there by design).
    below_pi = (np.linalg.norm(rotvec, axis=1) < 3.0) & (np.linalg.norm(integrated, axis=1) < 3.0)
    assert below_pi.sum() > 500
    assert np.abs(integrated - rotvec)[below_pi].max() > 1e-2
    # The outer segment turns about the fixed z axis: there the readings agree up to the quadrature
    # error of the trapezoid rule over the sampled (semi-implicit Euler) path, O(timestep).
    outer = states.names.index("outer_z")
    outer_int = integrate_angular_velocity(states.omega, poses.times)[:, outer]
    outer_rot = rotvec_angles(states)[:, outer]
    ok = (np.linalg.norm(outer_rot, axis=1) < 3.0) & (np.abs(outer_int[:, 2]) < 3.0)
    np.testing.assert_allclose(outer_int[ok, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(outer_int[ok, 2], outer_rot[ok, 2], atol=pair.mujoco.model.opt.timestep)
