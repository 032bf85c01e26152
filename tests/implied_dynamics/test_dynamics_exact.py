"""exact: polarization/Lagrange, Kane with MuJoCo and Kane with Pinocchio against both engines' M and Q*."""

from __future__ import annotations

import numpy as np
import pytest
from dynamics_helpers import states_with_accelerations

from koenig_check.implied_dynamics.analysis import ENGINES, dynamics_of_pair

M_RTOL, Q_RTOL = 1e-9, 1e-6
ROUTES = ("lagrange@mujoco", "lagrange@pinocchio", "kane@mujoco", "kane@pinocchio")

# (model, floating): every project model in both formats, fixed and floating bases, example-robot-data
# robots (ur5 fixed and floating, solo12 and the g1 humanoid floating), and a model with a ball joint
# and a three-joint body.
CASES = [
    ("gimbal.xml", False),
    ("gimbal.urdf", False),
    ("serial7.xml", False),
    ("serial7.urdf", False),
    ("serial7.urdf", True),
    ("double_pendulum.xml", False),
    ("double_pendulum.urdf", False),
    ("armature_chain.xml", False),
    ("armature_chain.urdf", False),
    ("free_body.xml", False),
    ("free_body.urdf", True),
    ("ur5", False),
    ("ur5", True),
    ("solo12", True),
    ("g1_29dof_rev_1_0", True),
    ("mixed_joints", False),
]


@pytest.fixture(params=CASES, ids=[f"{m}{'-floating' if f else ''}" for m, f in CASES])
def pair(request, load_pair, mixed_joints_file):
    model, floating = request.param
    return load_pair(mixed_joints_file if model == "mixed_joints" else model, floating)


def test_three_routes_agree_with_both_engines(pair):
    qpos, qvel, qacc = states_with_accelerations(pair, 3)
    result = dynamics_of_pair(pair, qpos, qvel, qacc, formulas=["exact"])
    assert not result.refusals
    assert {route for _, route in result.routes} == set(ROUTES)
    for route in ROUTES:
        r = result.routes[("exact", route)]
        for engine in ENGINES:
            M_ref, Q_ref = result.engine_mass[engine], result.engine_forces[engine]
            m_err = np.linalg.norm(r.M - M_ref, axis=(1, 2)) / np.linalg.norm(M_ref, axis=(1, 2))
            q_err = np.linalg.norm(r.Q - Q_ref, axis=1) / np.linalg.norm(Q_ref, axis=1)
            assert m_err.max() < M_RTOL, (route, engine, m_err)
            assert q_err.max() < Q_RTOL, (route, engine, q_err)
    assert result.ok, result.reason()


def test_mixed_joints_model_has_ball_and_multi_joint_body(load_pair, mixed_joints_file):
    # the joint kinds the case list claims to cover
    pair = load_pair(mixed_joints_file)
    kinds = set(pair.mujoco.dofs_by_kind())
    assert {"free", "ball", "hinge", "slide"} <= kinds
    assert any("in composite" in k for k in pair.pinocchio.dofs_by_kind())
