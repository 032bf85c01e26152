"""Seeded random canonical states."""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines import random_states

MODEL = """
<mujoco><compiler angle="radian" autolimits="true"/><worldbody>
  <body name="f"><freejoint name="free"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
    <body name="a"><joint name="limited" axis="0 0 1" range="-0.3 0.5"/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <body name="b"><joint name="unlimited" axis="0 1 0"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
        <body name="c"><joint name="ball" type="ball"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
          <body name="d"><joint name="slide" type="slide" axis="1 0 0" range="0.1 0.2"/>
            <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></body></body></body></body>
</worldbody></mujoco>
"""


def test_random_states_respect_limits_and_are_seeded():
    model = mujoco.MjModel.from_xml_string(MODEL)
    qpos, qvel = random_states(model, 500, seed=3, velocity_scale=2.0)
    assert qpos.shape == (500, model.nq) and qvel.shape == (500, model.nv)
    adr = {model.joint(j).name: model.jnt_qposadr[j] for j in range(model.njnt)}
    assert np.allclose(np.linalg.norm(qpos[:, adr["free"] + 3 : adr["free"] + 7], axis=1), 1.0)
    assert np.allclose(np.linalg.norm(qpos[:, adr["ball"] : adr["ball"] + 4], axis=1), 1.0)
    assert np.all(np.abs(qpos[:, adr["free"] : adr["free"] + 3]) <= 1.0)
    lim = qpos[:, adr["limited"]]
    assert lim.min() >= -0.3 and lim.max() <= 0.5 and lim.max() - lim.min() > 0.7
    unl = qpos[:, adr["unlimited"]]
    assert unl.min() >= -np.pi and unl.max() <= np.pi and unl.max() - unl.min() > 6.0
    sl = qpos[:, adr["slide"]]
    assert sl.min() >= 0.1 and sl.max() <= 0.2
    assert 1.8 < qvel.std() < 2.2
    again = random_states(model, 500, seed=3, velocity_scale=2.0)
    assert np.array_equal(again[0], qpos) and np.array_equal(again[1], qvel)
    assert not np.array_equal(random_states(model, 500, seed=4)[0], qpos)
