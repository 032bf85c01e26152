"""What MuJoCo includes (armature), and the importer quirks the MuJoCo adapter relies on or reports.

These tests pin down engine behaviour of MuJoCo 4.0; one failing after an upgrade means a finding in the
report has changed.  (Pinocchio's counterparts: ``tests/engines/pinocchio/test_pinocchio_behaviour.py``.)
"""

from __future__ import annotations

import re

import mujoco
import numpy as np
import pytest
from engine_helpers import RTOL, rel_err

from koenig_check.engines import load_model, random_states
from koenig_check.findings import Kind


@pytest.fixture(scope="module")
def armature_chain():
    return load_model("armature_chain.xml")


def test_mujoco_energy_and_mass_matrix_include_armature(armature_chain):
    mj = armature_chain.mujoco
    qpos, qvel = random_states(mj.model, 10, seed=1)
    parts = mj.kinetic_energy(qpos, qvel)
    assert np.all(parts.armature > 0)
    assert rel_err(parts.reported, parts.rigid + parts.armature) < RTOL
    M = mj.mass_matrix(qpos)
    rigid = mujoco.MjModel.__copy__(mj.model)
    rigid.dof_armature[:] = 0
    data = mujoco.MjData(rigid)
    data.qpos[:] = qpos[0]
    mujoco.mj_forward(rigid, data)
    M0 = np.zeros_like(M[0])
    mujoco.mj_fullM(rigid, data, M0)
    assert np.allclose(np.diag(M[0] - M0), mj.model.dof_armature, rtol=1e-12, atol=0)
    facts = [f for f in armature_chain.findings if f.kind is Kind.SELF_CONSISTENCY and f.engine == "mujoco"]
    assert any(f.summary == "its kinetic energy includes the armature term" for f in facts)
    assert not any(f.affects_energy for f in facts)


def test_mujoco_rne_excludes_armature_but_inverse_includes_it(armature_chain):
    model = mujoco.MjModel.__copy__(armature_chain.mujoco.model)
    model.opt.gravity[:] = 0
    data = mujoco.MjData(model)
    qpos, qvel = random_states(model, 1, seed=2)
    qacc = np.random.default_rng(2).normal(size=model.nv)
    data.qpos[:], data.qvel[:], data.qacc[:] = qpos[0], qvel[0], qacc
    mujoco.mj_inverse(model, data)
    rne = np.zeros(model.nv)
    mujoco.mj_rne(model, data, 1, rne)
    assert np.allclose(data.qfrc_inverse - rne, model.dof_armature * qacc, rtol=1e-9, atol=1e-12)


def test_mujoco_urdf_importer_discards_visuals_and_fuses_static_links(tmp_path):
    path = tmp_path / "visual.urdf"
    path.write_text(
        '<robot name="v"><link name="base"/><joint name="j" type="revolute"><parent link="base"/>'
        '<child link="l"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<link name="l"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/>'
        '</inertial><visual><geometry><mesh filename="package://nowhere/visual_only.dae"/></geometry></visual></link>'
        '<joint name="f" type="fixed"><parent link="l"/><child link="tip"/><origin xyz="0.1 0 0"/></joint>'
        '<link name="tip"><inertial><mass value="0.5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" '
        'iyz="0"/></inertial></link></robot>'
    )
    pair = load_model(path)
    assert pair.mujoco.model.nmesh == 0 and not any("inertia-only" in n for n in pair.notes)
    assert any("fused" in n and re.search(r"\btip\b", n) for n in pair.notes)
    assert pair.mujoco.model.nbody == 2  # world and l: base and tip were fused
    states = pair.mujoco.segment_states(*random_states(pair.mujoco.model, 1))
    assert states.mass[0] == pytest.approx(1.5)
