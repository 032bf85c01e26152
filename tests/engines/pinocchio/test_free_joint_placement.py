"""A free joint Pinocchio places away from the world origin: the state map composes with its placement.

Pinocchio 4.1's MJCF parser places the ``<freejoint>`` of a root body that has both a ``pos`` and an orientation
at ``pos − R pos`` (checked below), and its URDF parser places a ``floating`` joint at its ``<origin>``; MuJoCo's
free ``qpos`` is the body's world pose.  The root body's world pose after the map is compared with MuJoCo's own
kinematics (``xpos``, ``xmat``) through Pinocchio's own ``forwardKinematics``, then every segment.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest
from engine_helpers import RTOL, rel_err

import koenig_check
from koenig_check.engines import load_model, random_states

MJCF = """<mujoco><worldbody><body name="l1" pos="0 0 1" euler="30 0 20"><freejoint name="j1"/>
  <inertial pos="0.1 0.2 0" mass="1" diaginertia="0.1 0.2 0.25"/>
  <body name="l2" pos="1 0 0"><joint name="j2" axis="1 0 0"/>
    <inertial pos="0.3 0.1 0" mass="1" diaginertia="0.1 0.2 0.25"/></body></body></worldbody></mujoco>"""
INERTIA = '<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.25"/>'
URDF = f"""<robot name="floating"><link name="base"/>
  <link name="l1"><inertial><origin xyz="0.1 0.2 0"/><mass value="1"/>{INERTIA}</inertial></link>
  <joint name="j1" type="floating"><parent link="base"/><child link="l1"/><origin xyz="0 0 1" rpy="0.4 0 0.3"/></joint>
  <link name="l2"><inertial><origin xyz="0.3 0.1 0"/><mass value="1"/>{INERTIA}</inertial></link>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="1 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>"""
FILES = {"freejoint.xml": MJCF, "floating.urdf": URDF}
HAS_DRAKE = importlib.util.find_spec("pydrake") is not None


@pytest.fixture(params=sorted(FILES))
def model_file(request: pytest.FixtureRequest, tmp_path: Path) -> Path:
    path = tmp_path / request.param
    path.write_text(FILES[request.param])
    return path


def test_pinocchio_places_the_free_joint_away_from_the_origin(model_file: Path) -> None:
    pm = (
        pin.buildModelFromMJCF(str(model_file))
        if model_file.suffix == ".xml"
        else pin.buildModelFromUrdf(str(model_file))
    )
    assert [pm.joints[k].shortname() for k in range(1, pm.njoints)] == ["JointModelFreeFlyer", "JointModelRX"]
    assert np.linalg.norm(pm.jointPlacements[1].translation) > 0.1  # the map has something to compose with


def test_the_root_body_sits_where_mujoco_puts_it_and_maps_back(model_file: Path) -> None:
    pair = load_model(model_file)
    m, pm = pair.mujoco.model, pair.pinocchio.model
    assert (m.nv, pm.nv) == (7, 7)
    qpos, _ = random_states(m, 10, seed=3)
    q = pair.state_map.to_pinocchio(qpos)
    data, pdata = mujoco.MjData(m), pm.createData()
    root = pm.getJointId("j1")
    for k in range(qpos.shape[0]):
        data.qpos[:] = qpos[k]
        mujoco.mj_kinematics(m, data)
        pin.forwardKinematics(pm, pdata, q[k])
        np.testing.assert_allclose(pdata.oMi[root].translation, data.xpos[m.body("l1").id], atol=1e-12)
        np.testing.assert_allclose(pdata.oMi[root].rotation, data.xmat[m.body("l1").id].reshape(3, 3), atol=1e-12)
    np.testing.assert_allclose(pair.state_map.from_pinocchio(q), qpos, atol=1e-12)


def test_engines_put_every_segment_in_the_same_place(model_file: Path) -> None:
    pair = load_model(model_file)
    qpos, qvel = random_states(pair.mujoco.model, 10, seed=4)
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=list(sm.names))
    for field in ("rotation", "com", "omega", "v_com", "pole", "v_pole"):
        assert rel_err(getattr(sp, field), getattr(sm, field)) < RTOL, field


@pytest.mark.skipif(not HAS_DRAKE, reason="Drake (the optional extra [drake]) is not installed")
def test_three_engines_agree(model_file: Path) -> None:
    check = koenig_check.compare(model_file, n_poses=5, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"])
    assert check.ok, check.reason()
