"""A URDF ``planar`` joint: MuJoCo's three joints paired with Pinocchio's one ``JointModelPlanar``.

MuJoCo 4.0 reads ``<joint name="slider" type="planar">`` as slides ``slider_TX``, ``slider_TY`` and hinge
``slider_RZ`` on the child body; Pinocchio 4.1 as one planar joint, ``q = (x, y, cos θ, sin θ)`` and ``v`` with
the linear part in the joint's own (turned) frame.  The independent route is each engine's own mass matrix
(``mj_fullM`` and ``crba``) related by the velocity map written out here by hand, ``M_mj = Jᵀ M_pin J`` with
``J = diag(Rz(θ)ᵀ, 1, ...)``, and a hand computation: at θ = 0 the x, y block is the mass the joint carries
times the identity.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest
from planar_urdfs import MODELS, carried_mass, write_planar

import koenig_check
from koenig_check.engines import JointMismatch, load_model, random_states
from koenig_check.findings import Kind
from koenig_check.roundoff import ROUNDOFF


def _pin_state(mj: mujoco.MjModel, pm: pin.Model, qpos: np.ndarray, qvel: np.ndarray) -> tuple:
    """Pinocchio's (q, v) and J (v = J q̇) written out by hand from the joint names."""
    q, J = np.zeros(pm.nq), np.zeros((pm.nv, mj.nv))
    for i in range(1, pm.njoints):
        joint, name = pm.joints[i], pm.names[i]
        iq, iv = joint.idx_q, joint.idx_v
        if joint.shortname() == "JointModelPlanar":
            x, y, th = (qpos[mj.joint(name + s).qposadr[0]] for s in ("_TX", "_TY", "_RZ"))
            dofs = [mj.joint(name + s).dofadr[0] for s in ("_TX", "_TY", "_RZ")]
            c, s = np.cos(th), np.sin(th)
            q[iq : iq + 4] = x, y, c, s
            J[iv : iv + 2, dofs[:2]] = np.array([[c, s], [-s, c]])  # Rz(θ)ᵀ: local frame
            J[iv + 2, dofs[2]] = 1.0
        else:
            angle = qpos[mj.joint(name).qposadr[0]]
            q[iq : iq + joint.nq] = [np.cos(angle), np.sin(angle)] if joint.nq == 2 else [angle]
            J[iv, mj.joint(name).dofadr[0]] = 1.0
    return q, J @ qvel, J


@pytest.fixture(scope="module", params=sorted(MODELS))
def model(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Path]:
    return request.param, write_planar(tmp_path_factory.mktemp("planar"), request.param)


def test_mujoco_reads_a_planar_joint_as_two_slides_and_a_hinge_about_the_body_axes(model) -> None:
    _, path = model
    mj = mujoco.MjModel.from_xml_path(str(path))
    parts = [mj.joint(f"slider_{s}") for s in ("TX", "TY", "RZ")]
    assert [int(j.type[0]) for j in parts] == [mujoco.mjtJoint.mjJNT_SLIDE] * 2 + [mujoco.mjtJoint.mjJNT_HINGE]
    assert np.array_equal(np.array([j.axis for j in parts]), np.eye(3))
    assert pin.buildModelFromUrdf(str(path)).joints[pin.buildModelFromUrdf(str(path)).getJointId("slider")].nq == 4


def test_each_engines_mass_matrix_agrees_through_the_velocity_map_and_by_hand(model) -> None:
    name, path = model
    loaded = load_model(path)
    mj, pm = loaded.mujoco.model, loaded.pinocchio.model
    data, pdata = mujoco.MjData(mj), pm.createData()
    qpos, qvel = random_states(mj, 6, seed=3)
    qpos[0, mj.joint("slider_RZ").qposadr[0]] = 0.0  # θ = 0: the hand computation below
    xy = [mj.joint("slider_TX").dofadr[0], mj.joint("slider_TY").dofadr[0]]
    for k in range(qpos.shape[0]):
        q, v, J = _pin_state(mj, pm, qpos[k], qvel[k])
        data.qpos[:] = qpos[k]
        mujoco.mj_forward(mj, data)
        m_mj = np.zeros((mj.nv, mj.nv))
        mujoco.mj_fullM(mj, data, m_mj)
        m_pin = pin.crba(pm, pdata, q)
        m_pin = np.triu(m_pin) + np.triu(m_pin, 1).T
        assert np.abs(J.T @ m_pin @ J - m_mj).max() <= ROUNDOFF * np.abs(m_mj).max()
        # the code under test: the same q, v and map, and the same matrix carried back
        q_map, v_map = loaded.state_map.to_pinocchio(qpos[k], qvel[k])
        assert np.allclose(q_map, q, rtol=0.0, atol=1e-15) and np.allclose(v_map, v, rtol=0.0, atol=1e-14)
        T = loaded.state_map.velocity_matrix(qpos[k][None])[0]
        assert np.allclose(T, J, rtol=0.0, atol=1e-15)
        m_can = loaded.pinocchio.mass_matrix(qpos[k][None])[0]
        assert np.abs(m_can - m_mj).max() <= ROUNDOFF * np.abs(m_mj).max()
        if k == 0:  # θ = 0: the slides carry the whole mass the joint moves, uncoupled
            mass = carried_mass(name)
            assert np.allclose(m_mj[np.ix_(xy, xy)], mass * np.eye(2), rtol=0.0, atol=ROUNDOFF * mass)
            assert np.allclose(J.T @ m_pin @ J, m_mj, rtol=0.0, atol=ROUNDOFF * mass)


def test_inverse_dynamics_agree_through_the_acceleration_map(model) -> None:
    """RNEA of Pinocchio at ``a = d/dt v`` against MuJoCo's ``mj_inverse`` (gravity off): the ``θ̇ ẑ × v`` term."""
    _, path = model
    loaded = load_model(path)
    qpos, qvel = random_states(loaded.mujoco.model, 5, seed=8)
    qacc = np.random.default_rng(8).normal(size=qvel.shape)
    tau_mj = loaded.mujoco.inverse_dynamics(qpos, qvel, qacc)
    tau_pin = loaded.pinocchio.inverse_dynamics(qpos, qvel, qacc)
    assert np.abs(tau_pin - tau_mj).max() <= 1e-10 * np.abs(tau_mj).max()


def test_the_state_map_round_trips_planar_coordinates(model) -> None:
    _, path = model
    loaded = load_model(path)
    qpos, qvel = random_states(loaded.mujoco.model, 7, seed=5)
    th = loaded.mujoco.model.joint("slider_RZ").qposadr[0]
    qpos[:, th] = np.angle(np.exp(1j * qpos[:, th]))  # the map returns θ in (−π, π]
    back, back_vel = loaded.state_map.from_pinocchio(*loaded.state_map.to_pinocchio(qpos, qvel))
    pin_dofs, can_dofs = loaded.state_map.velocity_permutation  # every dof paired once (armature compared there)
    assert sorted(pin_dofs) == sorted(can_dofs) == list(range(loaded.mujoco.model.nv))
    assert np.allclose(back, qpos, rtol=0.0, atol=1e-14) and np.allclose(back_vel, qvel, rtol=0.0, atol=1e-14)


def test_compare_agrees_pose_by_pose_and_notes_how_the_engines_read_the_joint(model) -> None:
    _, path = model
    check = koenig_check.compare(path, n_poses=8, formulas=["exact"])
    assert check.ok, check.reason()
    assert check.agreements[0].rigid_max_rel <= ROUNDOFF
    loaded = load_model(path)
    qpos, qvel = random_states(loaded.mujoco.model, 8, seed=11)
    e_mj = loaded.mujoco.kinetic_energy(qpos, qvel).rigid
    e_pin = loaded.pinocchio.kinetic_energy(qpos, qvel).rigid
    assert np.all(e_mj > 0) and np.abs(e_pin - e_mj).max() <= ROUNDOFF * e_mj.max()
    notes = [f for f in loaded.findings if f.element == "joint slider"]
    assert [(f.kind, f.root_cause, f.affects_energy) for f in notes] == [(Kind.LOAD, False, False)]
    assert notes[0].values["mujoco"] == ("slider_TX", "slider_TY", "slider_RZ")
    assert not [f for f in check.comparisons[0].findings if f.root_cause]


@pytest.mark.parametrize("axis", ["0 1 0", "1 0 0", "0 0 -1"])
def test_a_planar_joint_about_another_axis_is_not_paired_and_the_cause_says_why(tmp_path: Path, axis: str) -> None:
    """MuJoCo honours the URDF axis (the plane's normal), Pinocchio 4.1 reads every planar joint about z."""
    path = write_planar(tmp_path, "planar base, revolute child", axis=axis)
    mj = mujoco.MjModel.from_xml_path(str(path))
    normal = np.array([float(a) for a in axis.split()])
    assert np.allclose(mj.joint("slider_RZ").axis, normal)  # MuJoCo's reading of the axis
    with pytest.raises(JointMismatch) as refused:
        load_model(path)
    assert [c.cause for c in refused.value.causes] == ["pinocchio.urdf.planar-axis"]
    check = koenig_check.compare(path, n_poses=2, formulas=["exact"])
    assert not check.ok
    line = check.failure_lines["robot.urdf"]
    assert "root cause: joint slider: URDF planar joint" in line and "Pinocchio" in line and "about z" in line
