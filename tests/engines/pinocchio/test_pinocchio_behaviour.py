"""What Pinocchio includes (armature, rotor inertia), and the parser quirks the Pinocchio adapter relies on or reports.

These tests pin down engine behaviour of Pinocchio 4.1; one failing after an upgrade means a finding in the
report has changed.  (MuJoCo's counterparts: ``tests/engines/mujoco/test_mujoco_behaviour.py``.)
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest
from engine_helpers import RTOL, rel_err

from koenig_check.engines import load_model, random_states
from koenig_check.findings import Kind


@pytest.fixture(scope="module")
def armature_chain():
    return load_model("armature_chain.xml")


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
