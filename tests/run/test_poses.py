from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.run.poses import grid_poses, keyframe_poses, random_poses, trajectory_poses

MODELS = Path(__file__).resolve().parents[2] / "models"

BALL_FREE_SLIDE = """
<mujoco>
  <worldbody>
    <body name="float"><freejoint name="root"/><inertial pos="0 0 0" mass="1" diaginertia="1 2 2.5"/>
      <body name="b" pos="0.2 0 0"><joint name="ball" type="ball"/>
        <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
        <body name="s" pos="0.2 0 0"><joint name="slide" type="slide" axis="1 0 0" range="-0.1 0.3"/>
          <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
          <body name="h" pos="0.2 0 0"><joint name="hinge" axis="0 0 1" ref="0.5"/>
            <inertial pos="0.1 0 0" mass="1" diaginertia="1 1 1"/></body>
        </body>
      </body>
    </body>
  </worldbody>
  <keyframe><key name="home" qpos="0 0 1 1 0 0 0 1 0 0 0 0.1 0.7"/></keyframe>
</mujoco>
"""


@pytest.fixture(scope="module")
def mixed() -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(BALL_FREE_SLIDE)


def test_random_poses_respect_limits_and_unit_quaternions(mixed: mujoco.MjModel) -> None:
    poses = random_poses(mixed, 500, seed=1)
    assert poses.qpos.shape == (500, mixed.nq) and poses.qvel.shape == (500, mixed.nv)
    np.testing.assert_allclose(np.linalg.norm(poses.qpos[:, 3:7], axis=1), 1.0, rtol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(poses.qpos[:, 7:11], axis=1), 1.0, rtol=1e-14)
    slide = poses.qpos[:, 11]
    assert slide.min() >= -0.1 and slide.max() <= 0.3
    hinge = poses.qpos[:, 12]  # unlimited: over [-π, π]
    assert hinge.min() >= -np.pi and hinge.max() <= np.pi and np.ptp(hinge) > 5.5


def test_random_poses_are_seeded(mixed: mujoco.MjModel) -> None:
    a, b = random_poses(mixed, 5, seed=7), random_poses(mixed, 5, seed=7)
    np.testing.assert_array_equal(a.qpos, b.qpos)
    assert not np.array_equal(a.qpos, random_poses(mixed, 5, seed=8).qpos)


def test_velocity_scale_scales_and_zero_is_refused(mixed: mujoco.MjModel) -> None:
    np.testing.assert_allclose(
        random_poses(mixed, 4, seed=2, velocity_scale=3.0).qvel, 3.0 * random_poses(mixed, 4, seed=2).qvel
    )
    with pytest.raises(ValueError, match="velocity scale must be a finite number > 0"):
        random_poses(mixed, 4, velocity_scale=0.0)


def test_keyframes_at_rest_get_noted_velocities(mixed: mujoco.MjModel) -> None:
    poses = keyframe_poses(mixed, seed=3)
    assert poses.ids == ("key:home",)
    np.testing.assert_array_equal(poses.qpos[0], mixed.key_qpos[0])
    assert np.any(poses.qvel) and "at rest" in poses.notes[0]


def test_grid_sweeps_two_gimbal_joints() -> None:
    model = mujoco.MjModel.from_xml_path(str(MODELS / "gimbal.xml"))
    poses = grid_poses(model, "outer_z", "inner_x", n=5, rate_a=2.0, rate_b=-1.0)
    assert poses.n_poses == 25 and poses.grid["shape"] == (5, 5)
    a = model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, "outer_z")]
    assert np.unique(poses.qpos[:, a]).size == 5
    assert set(np.unique(poses.qvel).tolist()) == {-1.0, 2.0}
    with pytest.raises(ValueError, match="no joint named 'nope'"):
        grid_poses(model, "outer_z", "nope")


def test_trajectory_without_gravity_conserves_energy_and_is_timed() -> None:
    model = mujoco.MjModel.from_xml_path(str(MODELS / "double_pendulum.xml"))
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    poses = trajectory_poses(model, duration=0.5, samples=51, seed=4)
    assert poses.times is not None and poses.times[0] == 0.0
    np.testing.assert_allclose(np.diff(poses.times), 0.01, rtol=1e-9)
    data = mujoco.MjData(model)
    energies = []
    for q, v in zip(poses.qpos, poses.qvel, strict=True):
        data.qpos[:], data.qvel[:] = q, v
        mujoco.mj_forward(model, data)
        M = np.zeros((model.nv, model.nv))
        mujoco.mj_fullM(model, data, M)
        energies.append(0.5 * v @ M @ v)
    # Torque-free, gravity-free motion: kinetic energy is conserved by the integrator to high accuracy.
    np.testing.assert_allclose(energies, energies[0], rtol=1e-6)
    assert model.opt.gravity[2] != 0.0  # the caller's model is not modified
