"""MuJoCo's frames as the adapter reads them: free-joint velocity frames, and each segment's pole.

The canonical state is MuJoCo's; these conventions are what the Pinocchio state map converts from
(``tests/engines/pinocchio/test_pinocchio_state_map.py``).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from all_joints import ALL_JOINTS_MJCF

from koenig_check.engines import load_model, random_states


@pytest.fixture(scope="module")
def mjcf_pair(tmp_path_factory):
    path = tmp_path_factory.mktemp("state_map") / "all_joints.xml"
    path.write_text(ALL_JOINTS_MJCF)
    return load_model(path)


def test_mujoco_free_joint_velocity_frames():
    """MuJoCo 4.0 free-joint qvel: linear = world velocity of the body origin, angular = body frame."""
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><body name="b" pos="0 0 1"><freejoint/>'
        '<inertial pos="0.2 0.1 0" mass="1" diaginertia="0.1 0.2 0.3"/></body></worldbody></mujoco>'
    )
    qpos, qvel = random_states(model, 1, seed=8)
    data = mujoco.MjData(model)

    def pose(q):
        data.qpos[:] = q
        mujoco.mj_kinematics(model, data)
        return data.xpos[1].copy(), data.xmat[1].reshape(3, 3).copy()

    x0, R0 = pose(qpos[0])
    h = 1e-7
    q1 = qpos[0].copy()
    mujoco.mj_integratePos(model, q1, qvel[0], h)
    x1, R1 = pose(q1)
    assert np.allclose((x1 - x0) / h, qvel[0, :3], atol=1e-6)
    W = R0.T @ (R1 - R0) / h  # skew(ω_local)
    assert np.allclose([W[2, 1], W[0, 2], W[1, 0]], qvel[0, 3:], atol=1e-5)


def test_mujoco_pole_is_xanchor_except_for_slides(mjcf_pair):
    mj = mjcf_pair.mujoco
    model, data = mj.model, mujoco.MjData(mj.model)
    qpos, qvel = random_states(model, 1, seed=9)
    states = mj.segment_states(qpos, qvel)
    data.qpos[:] = qpos[0]
    mujoco.mj_kinematics(model, data)
    for b, name in enumerate(states.names):
        j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
        same = np.allclose(states.pole[0, b], data.xanchor[j], atol=1e-12)
        assert same == (model.jnt_type[j] != mujoco.mjtJoint.mjJNT_SLIDE), name
