"""The canonical <-> Pinocchio state map: round trips for every joint type, kinematic agreement, mismatches."""

from __future__ import annotations

import mujoco
import numpy as np
import pinocchio as pin
import pytest
from all_joints import ALL_JOINTS_MJCF
from engine_helpers import RTOL, rel_err

from koenig_check.engines import JointMismatch, load_model, random_states
from koenig_check.findings import Kind

# fixed base URDF with revolute (aligned and tilted), continuous (aligned and tilted), prismatic
URDF_JOINTS = """
<robot name="urdf_joints">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="rev" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 0.5" rpy="0.1 0.2 0.3"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="l1"><inertial><origin xyz="0.1 0 0" rpy="0.3 0 0"/><mass value="2"/>
    <inertia ixx="0.1" iyy="0.2" izz="0.25" ixy="0.01" ixz="0" iyz="0"/></inertial></link>
  <joint name="cont" type="continuous"><parent link="l1"/><child link="l2"/><origin xyz="0 0.3 0"/>
    <axis xyz="1 0 0"/></joint>
  <link name="l2"><inertial><origin xyz="0 0 0.1"/><mass value="1"/>
    <inertia ixx="0.1" iyy="0.12" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="cont_tilted" type="continuous"><parent link="l2"/><child link="l3"/><origin xyz="0 0.3 0"/>
    <axis xyz="0.6 0 0.8"/></joint>
  <link name="l3"><inertial><origin xyz="0 0.05 0.1"/><mass value="1.2"/>
    <inertia ixx="0.1" iyy="0.12" izz="0.13" ixy="0" ixz="0.01" iyz="0"/></inertial></link>
  <joint name="pris" type="prismatic"><parent link="l3"/><child link="l4"/><origin xyz="0 0.3 0"/><axis xyz="1 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <link name="l4"><inertial><mass value="1"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="rev_tilted" type="revolute"><parent link="l4"/><child link="l5"/><origin xyz="0.2 0 0" rpy="0 0.5 0"/>
    <axis xyz="0 0.6 0.8"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="l5"><inertial><origin xyz="0.05 0 0"/><mass value="0.4"/>
    <inertia ixx="0.01" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial></link>
</robot>
"""


@pytest.fixture(scope="module")
def mjcf_pair(tmp_path_factory):
    path = tmp_path_factory.mktemp("state_map") / "all_joints.xml"
    path.write_text(ALL_JOINTS_MJCF)
    return load_model(path)


@pytest.fixture(scope="module")
def urdf_pair(tmp_path_factory):
    path = tmp_path_factory.mktemp("state_map") / "urdf_joints.urdf"
    path.write_text(URDF_JOINTS)
    return load_model(path, floating=True)


def _pairs(request, which):
    return request.getfixturevalue(which)


def test_every_joint_type_is_mapped(mjcf_pair, urdf_pair):
    kinds = {(p.kind, p.pin_kind, p.pin_sub >= 0) for pr in (mjcf_pair, urdf_pair) for p in pr.state_map.pairs}
    assert ("free", "free", False) in kinds
    assert ("ball", "ball", False) in kinds
    assert ("hinge", "revolute", False) in kinds
    assert ("hinge", "unbounded", False) in kinds
    assert ("slide", "prismatic", False) in kinds
    assert ("hinge", "revolute", True) in kinds and ("slide", "prismatic", True) in kinds
    # the composite's segment is named after the body's last joint in both engines
    assert "c_tilted" in mjcf_pair.mujoco.segment_names and "c_tilted" in mjcf_pair.pinocchio.segment_names
    assert "c_hinge" not in mjcf_pair.mujoco.segment_names


@pytest.mark.parametrize("which", ["mjcf_pair", "urdf_pair"])
def test_round_trip_canonical_to_pinocchio_and_back(request, which):
    pair = _pairs(request, which)
    qpos, qvel = random_states(pair.mujoco.model, 50, seed=1)
    sm = pair.state_map
    q, v = sm.to_pinocchio(qpos, qvel)
    assert q.shape == (50, pair.pinocchio.model.nq) and v.shape == (50, pair.pinocchio.model.nv)
    back_q, back_v = sm.from_pinocchio(q, v)
    assert np.abs(back_q - qpos).max() < 1e-12
    assert np.abs(back_v - qvel).max() < 1e-12
    # single states come back single
    q1, _ = sm.to_pinocchio(qpos[0], qvel[0])
    assert q1.shape == (pair.pinocchio.model.nq,) and np.allclose(q1, q[0])


@pytest.mark.parametrize("which", ["mjcf_pair", "urdf_pair"])
def test_round_trip_pinocchio_to_canonical_and_back(request, which):
    pair = _pairs(request, which)
    model = pair.pinocchio.model
    rng = np.random.default_rng(2)
    lo = np.where(np.isfinite(model.lowerPositionLimit), model.lowerPositionLimit, -1.0).clip(-3, 3)
    hi = np.where(np.isfinite(model.upperPositionLimit), model.upperPositionLimit, 1.0).clip(-3, 3)
    q = np.array([pin.randomConfiguration(model, lo, hi) for _ in range(20)])
    v = rng.normal(size=(20, model.nv))
    qpos, qvel = pair.state_map.from_pinocchio(q, v)
    q2, v2 = pair.state_map.to_pinocchio(qpos, qvel)
    assert np.abs(q2 - q).max() < 1e-12 and np.abs(v2 - v).max() < 1e-12


def test_continuous_joint_is_cos_sin_and_wraps(urdf_pair):
    pairs = {p.name: p for p in urdf_pair.state_map.pairs}
    cont = pairs["cont"]
    assert cont.pin_kind == "unbounded"
    qpos, _ = random_states(urdf_pair.mujoco.model, 5, seed=3)
    qpos[:, cont.qadr] = [0.5, 3.0, -3.0, 4.0, -7.0]
    q = urdf_pair.state_map.to_pinocchio(qpos)
    assert np.allclose(q[:, cont.pin_qadr], np.cos(qpos[:, cont.qadr]))
    assert np.allclose(q[:, cont.pin_qadr + 1], np.sin(qpos[:, cont.qadr]))
    back = urdf_pair.state_map.from_pinocchio(q)
    wrapped = np.angle(np.exp(1j * qpos[:, cont.qadr]))
    assert np.allclose(back[:, cont.qadr], wrapped, atol=1e-12)


def test_quaternion_order(mjcf_pair):
    pairs = {p.name: p for p in mjcf_pair.state_map.pairs}
    qpos = np.array(mjcf_pair.mujoco.model.qpos0, dtype=float)
    w, x, y, z = 0.5, 0.5, -0.5, 0.5
    qpos[pairs["ball1"].qadr : pairs["ball1"].qadr + 4] = [w, x, y, z]
    qpos[pairs["root"].qadr + 3 : pairs["root"].qadr + 7] = [w, x, y, z]
    q = mjcf_pair.state_map.to_pinocchio(qpos)
    assert np.allclose(q[pairs["ball1"].pin_qadr : pairs["ball1"].pin_qadr + 4], [x, y, z, w])
    assert np.allclose(q[pairs["root"].pin_qadr + 3 : pairs["root"].pin_qadr + 7], [x, y, z, w])


@pytest.mark.parametrize("which", ["mjcf_pair", "urdf_pair"])
def test_engines_put_every_segment_in_the_same_place(request, which):
    """Same rotation, COM, angular and COM velocity in both engines: quaternions, free frames, refs, composites."""
    pair = _pairs(request, which)
    qpos, qvel = random_states(pair.mujoco.model, 20, seed=4)
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=list(sm.names))
    for field in ("rotation", "com", "omega", "v_com", "pole", "v_pole"):
        assert rel_err(getattr(sp, field), getattr(sm, field)) < RTOL, field
    assert rel_err(sp.mass, sm.mass) < RTOL and rel_err(sp.inertia_world(), sm.inertia_world()) < RTOL


def test_composite_hinge_ref_is_compensated(mjcf_pair):
    """Pinocchio 4.1 ignores ``ref`` of a hinge inside a composite joint; the map offsets it (and says so)."""
    pairs = {p.name: p for p in mjcf_pair.state_map.pairs}
    assert pairs["c_hinge"].q_offset == pytest.approx(0.2)
    assert pairs["c_slide"].q_offset == 0.0 and pairs["hinge1"].q_offset == 0.0 and pairs["slide1"].q_offset == 0.0
    assert any(
        f.kind is Kind.IGNORED_CONSTRUCT and f.element == "joint c_hinge" and f.values["ref"] == pytest.approx(0.2)
        for f in mjcf_pair.findings
    )
    # at qpos0 the body sits where the file put it, in MuJoCo: c_hinge reads 0.2 there
    assert mjcf_pair.mujoco.model.qpos0[pairs["c_hinge"].qadr] == pytest.approx(0.2)


def test_velocity_matrix_is_orthogonal_and_maps_free_linear_velocity_to_local(mjcf_pair):
    qpos, qvel = random_states(mjcf_pair.mujoco.model, 10, seed=5)
    T = mjcf_pair.state_map.velocity_matrix(qpos)
    eye = np.eye(T.shape[-1])
    assert np.abs(np.swapaxes(T, -1, -2) @ T - eye).max() < 1e-12
    _, v = mjcf_pair.state_map.to_pinocchio(qpos, qvel)
    assert np.abs(np.einsum("pij,pj->pi", T, qvel) - v).max() < 1e-12
    root = next(p for p in mjcf_pair.state_map.pairs if p.kind == "free")
    data = mujoco.MjData(mjcf_pair.mujoco.model)
    data.qpos[:] = qpos[0]
    mujoco.mj_kinematics(mjcf_pair.mujoco.model, data)
    R = data.xmat[mujoco.mj_name2id(mjcf_pair.mujoco.model, mujoco.mjtObj.mjOBJ_BODY, "base")].reshape(3, 3)
    assert np.allclose(v[0, root.pin_vadr : root.pin_vadr + 3], R.T @ qvel[0, root.vadr : root.vadr + 3])
    assert np.allclose(v[0, root.pin_vadr + 3 : root.pin_vadr + 6], qvel[0, root.vadr + 3 : root.vadr + 6])


def test_acceleration_map_is_the_derivative_of_the_velocity_map(mjcf_pair):
    model = mjcf_pair.mujoco.model
    qpos, qvel = random_states(model, 3, seed=6)
    qacc = np.random.default_rng(6).normal(size=qvel.shape)
    a = mjcf_pair.state_map.acceleration_to_pinocchio(qpos, qvel, qacc)
    h = 1e-6
    fd = np.empty_like(a)
    for p in range(3):
        vs = []
        for sign in (-1.0, 1.0):
            q = qpos[p].copy()
            mujoco.mj_integratePos(model, q, qvel[p] + sign * 0.5 * h * qacc[p], sign * h)
            vs.append(mjcf_pair.state_map.to_pinocchio(q, qvel[p] + sign * h * qacc[p])[1])
        fd[p] = (vs[1] - vs[0]) / (2 * h)
    assert np.abs(fd - a).max() < 1e-6 * max(np.abs(a).max(), 1.0)


def test_joints_missing_in_pinocchio_raise_joint_mismatch(tmp_path):
    """Pinocchio 4.1's MJCF parser reads only the first body under <worldbody>."""
    path = tmp_path / "two_trees.xml"
    path.write_text(
        """<mujoco><worldbody>
        <body name="a"><joint name="ja" axis="0 1 0"/><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body>
        <body name="c" pos="1 0 0"><joint name="jc" type="slide" axis="0 0 1"/>
          <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
          <body name="d"><joint name="jd" axis="1 0 0"/>
            <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></body>
        </worldbody></mujoco>"""
    )
    with pytest.raises(JointMismatch) as info:
        load_model(path)
    assert info.value.only_in_mujoco == ["jc", "jd"]
    assert info.value.only_in_pinocchio == []
    assert str(path) in str(info.value) and "\n" not in str(info.value)


def test_renamed_joint_is_reported_on_both_sides(tmp_path):
    urdf = tmp_path / "a.urdf"
    urdf.write_text(URDF_JOINTS)
    other = tmp_path / "b.urdf"
    other.write_text(URDF_JOINTS.replace('name="pris"', 'name="prismatic_renamed"'))
    with pytest.raises(JointMismatch) as info:
        load_model(urdf, pinocchio_source=other)
    assert info.value.only_in_mujoco == ["pris"]
    assert info.value.only_in_pinocchio == ["prismatic_renamed"]


@pytest.mark.parametrize("free", ['<joint type="free"/>', "<freejoint/>"])
def test_unnamed_free_joint_pairs_however_the_file_writes_it(tmp_path, free):
    # Pinocchio names these "torso_free" and "torsoJoint_0"; both pair with MuJoCo's one free joint
    # (dm_control's drosophila_fused.xml writes the first form).
    path = tmp_path / "unnamed_free.xml"
    path.write_text(
        f"""<mujoco><worldbody><body name="torso" pos="0 0 1">{free}
        <geom type="box" size="0.1 0.2 0.3" mass="2"/>
        <body name="arm" pos="0.2 0 0"><joint name="elbow" axis="0 1 0"/><geom type="capsule" size="0.02 0.1"/></body>
        </body></worldbody></mujoco>"""
    )
    pair = load_model(path)
    assert [p.kind for p in pair.state_map.pairs] == ["free", "hinge"]
    qpos, qvel = random_states(pair.mujoco.model, 5, seed=2)
    mj, pn = pair.mujoco.kinetic_energy(qpos, qvel), pair.pinocchio.kinetic_energy(qpos, qvel)
    # independent route: ½ q̇ᵀ M q̇ with MuJoCo's own mass matrix
    quad = 0.5 * np.einsum("pi,pij,pj->p", qvel, pair.mujoco.mass_matrix(qpos), qvel)
    np.testing.assert_allclose(mj.rigid, quad, rtol=1e-12)
    np.testing.assert_allclose(pn.rigid, quad, rtol=1e-12)
