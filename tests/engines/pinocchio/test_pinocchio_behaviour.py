"""What each engine includes (armature), and the importer/parser quirks the adapters rely on or report.

These tests pin down engine behaviour of MuJoCo 4.0 and Pinocchio 4.1; one failing after an upgrade
means a finding in the report has changed.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pinocchio as pin
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


def test_pinocchio_energy_misses_armature_of_unaligned_revolute_joints(armature_chain):
    pn = armature_chain.pinocchio
    kinds = pn.dofs_by_kind()
    assert set(kinds) == {"JointModelRZ", "JointModelRY", "JointModelRevoluteUnaligned"}
    qpos, qvel = random_states(armature_chain.mujoco.model, 5, seed=3)
    for kind, dofs in kinds.items():
        v = np.zeros_like(qvel)
        v[:, dofs] = qvel[:, dofs]
        parts = pn.kinetic_energy(qpos, v)
        expected = parts.rigid if kind == "JointModelRevoluteUnaligned" else parts.total
        assert rel_err(parts.reported, expected) < RTOL, kind
        # crba has the armature for every joint kind
        half_vmv = 0.5 * np.einsum("pi,pij,pj->p", v, pn.mass_matrix(qpos), v)
        assert rel_err(half_vmv, parts.total) < RTOL, kind
    assert any(
        f.kind is Kind.SELF_CONSISTENCY
        and f.engine == "pinocchio"
        and f.affects_energy
        and "kinetic energy != ½ q̇ᵀ M q̇" in f.summary
        and f.values["joint kinds"] == ["JointModelRevoluteUnaligned"]
        for f in armature_chain.findings
    )


def test_pinocchio_rotor_inertia_fields_are_unused():
    model = pin.buildModelFromUrdf(str(load_model("ur5").source.path))
    data = model.createData()
    q, v = pin.neutral(model), np.ones(model.nv)
    M0, E0 = pin.crba(model, data, q).copy(), pin.computeKineticEnergy(model, data, q, v)
    model.rotorInertia[:] = 0.5
    model.rotorGearRatio[:] = 3.0
    data = model.createData()
    assert np.array_equal(pin.crba(model, data, q), M0) and pin.computeKineticEnergy(model, data, q, v) == E0


def test_pinocchio_mjcf_parser_ignores_the_pose_of_a_welded_first_body(tmp_path):
    path = tmp_path / "welded_first.xml"
    path.write_text(
        """<mujoco><compiler angle="radian"/><worldbody>
        <body name="base" pos="0.5 0.2 1" euler="0.3 0.2 0.1">
          <inertial pos="0 0.1 0" mass="3" diaginertia="0.1 0.2 0.25"/>
          <body name="a" pos="0 0 0.3"><joint name="ja" axis="0 1 0"/>
            <inertial pos="0 0.1 0" mass="1" diaginertia="0.1 0.2 0.25"/></body>
        </body></worldbody></mujoco>"""
    )
    pair = load_model(path)
    qpos, qvel = random_states(pair.mujoco.model, 5, seed=4)
    sm, sp = pair.mujoco.segment_states(qpos, qvel), pair.pinocchio.segment_states(qpos, qvel)
    assert np.allclose(sp.pole[:, 0], [0.0, 0.0, 0.3])  # the base's pose is dropped
    assert not np.allclose(sm.pole, sp.pole) and not np.allclose(sm.rotation, sp.rotation)
    # a constant rigid displacement of the whole model: energies still agree
    e_mj, e_pin = pair.mujoco.kinetic_energy(qpos, qvel).rigid, pair.pinocchio.kinetic_energy(qpos, qvel).rigid
    assert rel_err(e_pin, e_mj) < RTOL
    assert any("segment poses differ" in n for n in pair.notes)


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
    assert any("fused" in n and "'tip'" in n for n in pair.notes)
    assert pair.mujoco.model.nbody == 2  # world and l: base and tip were fused
    states = pair.mujoco.segment_states(*random_states(pair.mujoco.model, 1))
    assert states.mass[0] == pytest.approx(1.5)
