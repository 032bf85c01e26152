"""Drake adapter against MuJoCo and Pinocchio: energy, mass matrix, inverse dynamics and segment states to 1e-12."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import LoadedModel, load_model, random_states

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed: its tests are skipped")

from koenig_check.engines.drake.adapter import DrakeEngine
from koenig_check.engines.drake.building import load_drake_engine

RTOL = 1e-12
#: The repository: the test models below are named from it (their ids), and found from this file, wherever pytest runs.
ROOT = Path(__file__).resolve().parents[3]
#: (model, floating): project models in both formats and example-robot-data robots, fixed and floating.
DRAKE_CASES = [
    ("gimbal.xml", False),
    ("gimbal.urdf", False),
    ("gimbal.urdf", True),
    ("double_pendulum.xml", False),
    ("double_pendulum.urdf", True),
    ("serial7.xml", False),
    ("serial7.urdf", False),
    ("free_body.xml", False),
    ("free_body.urdf", True),
    ("armature_chain.urdf", False),
    ("tests/engines/models/ball_armature.xml", False),
    ("tests/models/tiebreak/hinge_ref.xml", False),
    ("tests/models/tiebreak/rotor_inertia.urdf", False),
    ("ur5", False),
    ("ur5", True),
    ("solo12", True),
    ("panda", False),
    ("panda", True),
]


@cache
def _load(model: str, floating: bool) -> tuple[LoadedModel, DrakeEngine]:
    pair = load_model(str(ROOT / model) if model.startswith("tests/") else model, floating=floating, check=False)
    return pair, load_drake_engine(pair.source, pair.mujoco.model)


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    """Largest difference relative to the largest entry of the reference (per quantity, not per entry)."""
    return float(np.abs(np.asarray(a) - np.asarray(b)).max() / max(np.abs(b).max(), 1e-300))


@pytest.fixture(params=DRAKE_CASES, ids=[f"{m}{'-floating' if f else ''}" for m, f in DRAKE_CASES])
def loaded(request: pytest.FixtureRequest) -> tuple[LoadedModel, DrakeEngine, np.ndarray, np.ndarray]:
    pair, drake = _load(*request.param)
    qpos, qvel = random_states(pair.mujoco.model, 6, seed=3)
    return pair, drake, qpos, qvel


def test_energy_agrees_with_both_engines(loaded) -> None:
    pair, drake, qpos, qvel = loaded
    ed = drake.kinetic_energy(qpos, qvel)
    for other in pair.engines.values():
        assert _rel(ed.rigid, other.kinetic_energy(qpos, qvel).rigid) < RTOL, other.engine


def test_mass_matrix_and_inverse_dynamics_agree(loaded) -> None:
    pair, drake, qpos, qvel = loaded
    arm_mj = np.asarray(pair.mujoco.model.dof_armature)
    arm_dk = drake.armature_per_dof()
    qacc = np.random.default_rng(1).normal(size=qvel.shape)
    M_mj = pair.mujoco.mass_matrix(qpos) - np.diag(arm_mj)
    M_dk = drake.mass_matrix(qpos) - np.diag(arm_dk)
    assert _rel(M_dk, M_mj) < RTOL
    tau_mj = pair.mujoco.inverse_dynamics(qpos, qvel, qacc) - arm_mj * qacc
    tau_dk = drake.inverse_dynamics(qpos, qvel, qacc) - arm_dk * qacc
    assert _rel(tau_dk, tau_mj) < RTOL


def test_segment_states_agree(loaded) -> None:
    pair, drake, qpos, qvel = loaded
    sd = drake.segment_states(qpos, qvel)
    for other in pair.engines.values():
        so = other.segment_states(qpos, qvel)
        assert sorted(sd.names) == sorted(so.names), other.engine
        so = so.select(segments=list(sd.names))
        length = max(float(np.abs(so.com).max()), 1.0)
        speed = max(float(np.abs(so.v_com).max()), float(np.abs(so.omega).max()), 1.0)
        assert _rel(sd.mass, so.mass) < RTOL
        assert _rel(sd.inertia_body, so.inertia_body) < RTOL
        assert np.abs(sd.rotation - so.rotation).max() < RTOL
        for a, b, scale in [
            (sd.com, so.com, length),
            (sd.v_com, so.v_com, speed),
            (sd.omega, so.omega, speed),
        ]:
            assert np.abs(a - b).max() < RTOL * scale, other.engine
        if other.engine == "mujoco":  # the reference configuration is MuJoCo's qpos0 (Pinocchio's is its neutral)
            assert np.abs(sd.com_ref - so.com_ref).max() < RTOL * length
            assert np.abs(sd.rotation_ref - so.rotation_ref).max() < RTOL
            assert np.abs(sd.pole - so.pole).max() < RTOL * length
            assert np.abs(sd.v_pole - so.v_pole).max() < RTOL * speed


def test_point_velocities_from_jacobians_match_segment_velocities(loaded) -> None:
    pair, drake, qpos, qvel = loaded
    points = np.zeros((len(drake.segment_names), 2, 3))
    points[:, 1] = [0.1, -0.2, 0.3]
    pv = drake.point_velocities(qpos, qvel, points)
    pm = pair.mujoco.point_velocities(
        qpos, qvel, points[[pair.mujoco.segment_names.index(n) for n in drake.segment_names]]
    )
    scale = max(float(np.abs(pm).max()), 1.0)
    assert np.abs(pv - pm).max() < RTOL * scale


def test_ball_joint_is_rpy_with_parent_frame_velocity() -> None:
    pair, drake = _load("tests/engines/models/ball_armature.xml", False)
    assert list(drake.dofs_by_kind()) == ["ball_rpy"]
    qpos, qvel = random_states(pair.mujoco.model, 4, seed=9)
    # independent route: ½ ωᵀ I ω with the file's inertia (COM at the joint) in the body frame
    I_body = np.diag([0.1, 0.2, 0.25])
    expected = 0.5 * np.einsum("pi,ij,pj->p", qvel, I_body, qvel)
    assert np.allclose(drake.kinetic_energy(qpos, qvel).rigid, expected, rtol=RTOL, atol=0)


def test_reflected_inertia_is_reported_apart_from_the_rigid_energy() -> None:
    pair, drake = _load("tests/models/tiebreak/rotor_inertia.urdf", False)
    qpos, qvel = random_states(pair.mujoco.model, 4, seed=2)
    parts = drake.kinetic_energy(qpos, qvel)
    reflected = 0.5 * 3.0**2  # rotor inertia × gear ratio², by hand from the file
    assert np.allclose(parts.armature, 0.5 * reflected * qvel[:, 0] ** 2, rtol=RTOL, atol=0)
    assert np.allclose(parts.reported, parts.rigid + parts.armature, rtol=RTOL, atol=0)
    assert _rel(parts.rigid, pair.pinocchio.kinetic_energy(qpos, qvel).rigid) < RTOL
