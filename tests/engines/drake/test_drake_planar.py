"""A URDF ``planar`` joint in Drake: one ``PlanarJoint`` with MuJoCo's own coordinates (x, y, θ) and rates.

Drake 1.51's ``PlanarJoint`` has ``q = (x, y, θ)`` and ``v = (ẋ, ẏ, θ̇)`` (rates in the parent frame, not the
joint's turned frame as Pinocchio's); MuJoCo's import makes the joint slides ``_TX``, ``_TY`` and hinge ``_RZ``.
The independent route: Drake's own ``CalcMassMatrix`` at the coordinates written out by hand from the joint
names against MuJoCo's ``mj_fullM``, and the mass the joint carries on the x, y diagonal at θ = 0.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from planar_urdfs import MODELS, carried_mass, write_planar

import koenig_check
from koenig_check.engines import load_model, random_states
from koenig_check.roundoff import ROUNDOFF

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed: its tests are skipped")


def _drake_index(plant, mj: mujoco.MjModel) -> np.ndarray:
    """Drake's coordinate of each MuJoCo one-coordinate joint (``qpos`` and ``qvel`` alike), by name, by hand."""
    index = np.full(mj.nq, -1)
    for j in plant.GetJointIndices():
        joint = plant.get_joint(j)
        if joint.num_positions() == 0:
            continue
        assert joint.position_start() == joint.velocity_start()  # no quaternion before it in these models
        parts = ("_TX", "_TY", "_RZ") if joint.type_name() == "planar" else ("",)
        for k, suffix in enumerate(parts):
            index[mj.joint(joint.name() + suffix).qposadr[0]] = joint.position_start() + k
    assert sorted(index) == list(range(mj.nq))
    return index


@pytest.mark.parametrize("name", sorted(MODELS))
def test_drakes_mass_matrix_and_energy_are_mujocos_at_the_same_coordinates(tmp_path, name: str) -> None:
    loaded = load_model(write_planar(tmp_path, name))
    drake = loaded.attach("drake")
    mj, plant = loaded.mujoco.model, drake.plant
    assert plant.num_positions() == mj.nq  # every joint here has as many coordinates as rates
    data, context = mujoco.MjData(mj), plant.CreateDefaultContext()
    qpos, qvel = random_states(mj, 5, seed=4)
    qpos[0, mj.joint("slider_RZ").qposadr[0]] = 0.0
    xy = [mj.joint("slider_TX").dofadr[0], mj.joint("slider_TY").dofadr[0]]
    index = _drake_index(plant, mj)
    for k in range(len(qpos)):
        data.qpos[:] = qpos[k]
        mujoco.mj_forward(mj, data)
        m_mj = np.zeros((mj.nv, mj.nv))
        mujoco.mj_fullM(mj, data, m_mj)
        q_drake = np.zeros(mj.nq)
        q_drake[index] = qpos[k]
        plant.SetPositions(context, q_drake)
        m_drake = plant.CalcMassMatrix(context)
        # canonical dof k is Drake's dof index[k] (one coordinate per dof here)
        assert np.abs(m_drake[np.ix_(index, index)] - m_mj).max() <= ROUNDOFF * np.abs(m_mj).max()
        assert np.abs(drake.mass_matrix(qpos[k][None])[0] - m_mj).max() <= ROUNDOFF * np.abs(m_mj).max()
        if k == 0:  # θ = 0: the slides carry the whole mass the joint moves
            mass = carried_mass(name)
            assert np.allclose(m_mj[np.ix_(xy, xy)], mass * np.eye(2), rtol=0.0, atol=ROUNDOFF * mass)
    e_mj = loaded.mujoco.kinetic_energy(qpos, qvel).rigid
    e_drake = drake.kinetic_energy(qpos, qvel).rigid
    assert np.all(e_mj > 0) and np.abs(e_drake - e_mj).max() <= ROUNDOFF * e_mj.max()


def test_three_engines_agree_on_a_planar_robot(tmp_path) -> None:
    path = write_planar(tmp_path, "turned planar base, tilted continuous child")
    check = koenig_check.compare(path, n_poses=6, formulas=["exact"], engines=("mujoco", "pinocchio", "drake"))
    assert check.ok, check.reason()
    assert check.agreements[0].rigid_max_rel <= ROUNDOFF
