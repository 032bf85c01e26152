"""The one sampler of random canonical states: its documented distribution, joint type by joint type.

Expected values come from the distribution's definition, not from the sampler: a uniform variable on
``[lo, hi]`` has mean ``(lo + hi) / 2`` and variance ``(hi − lo)² / 12``; a uniform unit quaternion with
``w >= 0`` has ``E[w] = 4 / (3π)`` (the density of ``w`` on the 3-sphere is proportional to ``√(1 − w²)``)
and ``E[x²] = E[y²] = E[z²] = 1/4``; a uniform rotation has ``E[R] = 0`` (rotations from MuJoCo's
``mju_quat2Mat``).  Sample statistics are compared with five of their standard errors.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from common import dm_control_root

from koenig_check.engines import random_states
from koenig_check.engines.coupling import joint_relations
from koenig_check.engines.sampling import POSITION_RANGE, RANDOM_BLOCK, random_state_range
from koenig_check.run.poses import keyframe_poses, random_poses

MODELS = Path(__file__).resolve().parents[2] / "models"
N = 4000  # poses: standard errors of about 1.5 % of a spread

MIXED = """
<mujoco><compiler angle="radian" autolimits="true"/><worldbody>
  <body name="f" pos="0.5 -2 1"><freejoint name="free"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
    <body name="a"><joint name="limited" axis="0 0 1" range="-0.3 0.5"/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <body name="b"><joint name="unlimited" axis="0 1 0"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
        <body name="c"><joint name="ball" type="ball"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
          <body name="d"><joint name="slide" type="slide" axis="1 0 0" range="0.1 0.2"/>
            <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
            <body name="e"><joint name="rail" type="slide" axis="0 1 0" ref="0.25"/>
              <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></body></body></body></body></body>
</worldbody>
<keyframe><key name="moving" qpos="0 0 0 1 0 0 0 0.1 0 1 0 0 0 0.15 0" qvel="1 0 0 0 0 0 0 0 0 0 0 0 0"/>
  <key name="still" qpos="0 0 0 1 0 0 0 0.2 0 1 0 0 0 0.15 0"/></keyframe>
</mujoco>
"""


def _dm(rel: str) -> Path:
    root = dm_control_root()
    if root is None:
        pytest.skip("dm_control is not installed")
    return root / rel


#: Models with every joint type: free, ball, limited and unlimited hinges and slides (dm_control: humanoid has a
#: free root and limited hinges, swimmer unlimited slides and hinges, fish a free root and unlimited hinges).
MODEL_FILES = {
    "mixed": None,
    "free_body.xml": lambda: MODELS / "free_body.xml",
    "serial7.xml": lambda: MODELS / "serial7.xml",
    "dm_control humanoid": lambda: _dm("suite/humanoid.xml"),
    "dm_control swimmer": lambda: _dm("suite/swimmer.xml"),
    "dm_control fish": lambda: _dm("suite/fish.xml"),
}


@pytest.fixture(params=list(MODEL_FILES), scope="module")
def model(request: pytest.FixtureRequest) -> mujoco.MjModel:
    path = MODEL_FILES[request.param]
    if path is None:
        return mujoco.MjModel.from_xml_string(MIXED)
    return mujoco.MjModel.from_xml_path(str(path()))


def _close(sample: np.ndarray, expected: float, std: float) -> bool:
    """The sample mean within five standard errors of ``expected``."""
    return abs(float(np.mean(sample)) - expected) <= 5 * std / np.sqrt(len(sample)) + 1e-12


def _uniform(sample: np.ndarray, lo: float, hi: float) -> None:
    assert sample.min() >= lo and sample.max() <= hi, (sample.min(), sample.max(), lo, hi)
    width = hi - lo
    assert _close(sample, (lo + hi) / 2, width / np.sqrt(12)), (sample.mean(), lo, hi)
    var = (sample - (lo + hi) / 2) ** 2  # E = width²/12, std = width²/(6√5)
    assert _close(var, width**2 / 12, width**2 / (6 * np.sqrt(5))), (var.mean(), width**2 / 12)


def _uniform_quaternions(quat: np.ndarray) -> None:
    np.testing.assert_allclose(np.linalg.norm(quat, axis=1), 1.0, rtol=1e-14)
    assert np.all(quat[:, 0] >= 0)
    w_std = np.sqrt(0.25 - (4 / (3 * np.pi)) ** 2)
    assert _close(quat[:, 0], 4 / (3 * np.pi), w_std), quat[:, 0].mean()
    for k in (1, 2, 3):
        assert _close(quat[:, k] ** 2, 0.25, np.sqrt(1 / 8 - 1 / 16)), (k, (quat[:, k] ** 2).mean())
    rot = np.empty((len(quat), 9))
    for i, q in enumerate(quat):
        mujoco.mju_quat2Mat(rot[i], q)
    assert np.all(np.abs(rot.mean(axis=0)) <= 5 * np.sqrt(1 / 3) / np.sqrt(len(quat)))  # E[R] = 0, entries var 1/3


def test_each_joint_type_has_its_documented_distribution(model: mujoco.MjModel) -> None:
    scale = 2.5
    qpos, qvel = random_states(model, N, seed=3, velocity_scale=scale)
    assert qpos.shape == (N, model.nq) and qvel.shape == (N, model.nv)
    followers = {r.follower for r in joint_relations(model)}
    for j in range(model.njnt):
        if j in followers:
            continue
        adr, kind, q0 = int(model.jnt_qposadr[j]), int(model.jnt_type[j]), model.qpos0
        lo, hi = model.jnt_range[j]
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            for axis in range(3):
                _uniform(qpos[:, adr + axis], q0[adr + axis] - POSITION_RANGE, q0[adr + axis] + POSITION_RANGE)
            _uniform_quaternions(qpos[:, adr + 3 : adr + 7])
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            _uniform_quaternions(qpos[:, adr : adr + 4])
        elif model.jnt_limited[j] and hi > lo:
            _uniform(qpos[:, adr], lo, hi)
        elif kind == mujoco.mjtJoint.mjJNT_HINGE:
            _uniform(qpos[:, adr], -np.pi, np.pi)
        else:
            _uniform(qpos[:, adr], q0[adr] - POSITION_RANGE, q0[adr] + POSITION_RANGE)
    z = qvel.ravel() / scale
    assert _close(z, 0.0, 1.0) and _close(z**2, 1.0, np.sqrt(2.0))  # normal: E[z²] = 1, Var[z²] = 2


def test_the_mixed_model_covers_every_joint_type() -> None:
    kinds = set(mujoco.MjModel.from_xml_string(MIXED).jnt_type.tolist())
    assert kinds == {int(mujoco.mjtJoint.mjJNT_FREE), int(mujoco.mjtJoint.mjJNT_BALL)} | {
        int(mujoco.mjtJoint.mjJNT_SLIDE),
        int(mujoco.mjtJoint.mjJNT_HINGE),
    }


def test_a_seed_gives_the_same_states_and_another_seed_others() -> None:
    model = mujoco.MjModel.from_xml_string(MIXED)
    qpos, qvel = random_states(model, 50, seed=3)
    again = random_states(model, 50, seed=3)
    assert np.array_equal(again[0], qpos) and np.array_equal(again[1], qvel)
    assert not np.array_equal(random_states(model, 50, seed=4)[0], qpos)


def test_any_range_is_a_slice_of_the_sequence() -> None:
    model = mujoco.MjModel.from_xml_string(MIXED)
    qpos, qvel = random_states(model, RANDOM_BLOCK + 30, seed=5)
    part = random_state_range(model, RANDOM_BLOCK - 10, RANDOM_BLOCK + 20, seed=5)  # crosses a block boundary
    assert np.array_equal(part[0], qpos[RANDOM_BLOCK - 10 : RANDOM_BLOCK + 20])
    assert np.array_equal(part[1], qvel[RANDOM_BLOCK - 10 : RANDOM_BLOCK + 20])


def test_pose_sets_and_keyframes_at_rest_draw_from_the_one_sampler() -> None:
    model = mujoco.MjModel.from_xml_string(MIXED)
    qpos, qvel = random_states(model, 6, seed=9, velocity_scale=0.5)
    poses = random_poses(model, 6, seed=9, velocity_scale=0.5)
    assert np.array_equal(poses.qpos, qpos) and np.array_equal(poses.qvel, qvel)
    keys = keyframe_poses(model, seed=9, velocity_scale=0.5)
    assert np.array_equal(keys.qvel[0], model.key_qvel[0])  # a moving keyframe keeps its velocities
    assert np.array_equal(keys.qvel[1], qvel[1])  # keyframe 1 at rest moves as random pose 1
    assert any("'still' is at rest" in n for n in keys.notes) and not any("'moving'" in n for n in keys.notes)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda m: random_states(m, 0), "number of poses must be >= 1"),
        (lambda m: random_states(m, 3, seed=-1), "seed must be >= 0"),
        (lambda m: random_states(m, 3, velocity_scale=0.0), "velocity scale must be a finite number > 0"),
        (lambda m: random_state_range(m, 5, 5), "need 0 <= start < stop"),
    ],
)
def test_bad_requests_are_refused(call, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        call(mujoco.MjModel.from_xml_string(MIXED))
