"""MuJoCo's kinetic energy and inverse dynamics evaluated on the loaded model itself (no copies): the same numbers as
MuJoCo's own calls on a copy set up for them, and the model's options as they were afterwards."""

from __future__ import annotations

import copy

import mujoco
import numpy as np
import pytest

from koenig_check.engines import load_model, random_states

#: Gravity, a spring, a damper, a joint limit and air: every option the inverse dynamics turns off.
MODEL = """<mujoco>
  <option gravity="0 0 -9.81" density="1.2" viscosity="0.1"/>
  <worldbody>
    <body name="upper"><joint name="shoulder" type="hinge" axis="0 1 0" stiffness="3" damping="0.5" springref="0.2"
        limited="true" range="-0.1 0.1"/>
      <geom type="capsule" fromto="0 0 0 0.4 0 0" size="0.05"/>
      <body name="lower" pos="0.4 0 0"><joint name="elbow" type="hinge" axis="0 0 1" armature="0.01"/>
        <geom type="box" size="0.2 0.03 0.02" pos="0.2 0 0"/>
      </body>
    </body>
  </worldbody>
</mujoco>"""


def _options(m: mujoco.MjModel) -> tuple:
    o = m.opt
    return (tuple(o.gravity), o.density, o.viscosity, o.disableflags, o.enableflags)


@pytest.fixture
def engine(tmp_path):
    """The arm loaded, its model's options as the file has them (the loader turns some off on the loaded model)."""
    path = tmp_path / "arm.xml"
    path.write_text(MODEL)
    engine = load_model(str(path)).engine("mujoco")
    opt = engine.model.opt
    opt.gravity[:], opt.density, opt.viscosity, opt.disableflags = (0.0, 0.0, -9.81), 1.2, 0.1, 0
    return engine


def test_inverse_dynamics_is_mj_inverse_with_the_options_off_and_leaves_them_as_they_were(engine) -> None:
    m = engine.model
    before = _options(m)
    qpos, qvel = random_states(m, 5, seed=3)
    qacc = np.random.default_rng(3).normal(size=qvel.shape)
    tau = engine.inverse_dynamics(qpos, qvel, qacc)
    assert _options(m) == before
    off = copy.copy(m)  # MuJoCo's own call on a copy with gravity, air, constraints, springs and dampers off
    off.opt.gravity[:], off.opt.density, off.opt.viscosity = 0.0, 0.0, 0.0
    bits = mujoco.mjtDisableBit
    off.opt.disableflags |= int(bits.mjDSBL_CONSTRAINT | bits.mjDSBL_SPRING | bits.mjDSBL_DAMPER)
    d = mujoco.MjData(off)
    for p in range(qpos.shape[0]):
        d.qpos[:], d.qvel[:], d.qacc[:] = qpos[p], qvel[p], qacc[p]
        mujoco.mj_inverse(off, d)
        assert np.array_equal(tau[p], d.qfrc_inverse)


def test_kinetic_energy_is_mj_energy_vel_with_the_energy_flag(engine) -> None:
    m = engine.model
    before = _options(m)
    qpos, qvel = random_states(m, 5, seed=4)
    reported = engine.kinetic_energy(qpos, qvel).reported
    assert _options(m) == before
    flagged = copy.copy(m)
    flagged.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    d = mujoco.MjData(flagged)
    for p in range(qpos.shape[0]):
        d.qpos[:], d.qvel[:] = qpos[p], qvel[p]
        mujoco.mj_forward(flagged, d)  # with the flag, mj_forward computes the energy itself
        assert reported[p] == pytest.approx(d.energy[1], rel=1e-12)
