"""The paper's recipe on the gimbal: wrong dynamics once both joints move, right when only one moves.

The recipe (eq. 38 with the axial moments of the initial pose, eq. 29, and centrifugal moments
rotated by eq. 36) gives the exact energy for a rotation about one world axis from the initial pose.
Its implied M and Q* then coincide with the engines' for the moving joint (M_jj and Q*_j: the
energy is right on the one-joint submanifold, and so are its derivatives along it), while at general
poses M and Q* are off by far more than 1e-3.
"""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.implied_dynamics.analysis import ENGINES, dynamics_of_pair

RECIPES = ["alyushin_paper:rotvec", "alyushin_paper:euler_xyz"]

# (ψ, θ), (ψ̇, θ̇), (ψ̈, θ̈): both joints away from the reference and moving
GENERAL = [
    ((0.7, 0.9), (1.3, -0.8), (0.4, 1.1)),
    ((-2.2, 1.4), (-0.6, 2.0), (-1.5, 0.3)),
    ((1.6, -0.7), (0.9, 1.2), (1.0, -0.8)),
]
# one joint moves, the other rests at its reference (0): (state, index of the moving joint)
ONE_JOINT = [
    (((0.8, 0.0), (1.3, 0.0), (0.7, 0.0)), 0),
    (((-2.1, 0.0), (0.4, 0.0), (-1.5, 0.0)), 0),
    (((0.0, 0.9), (0.0, 1.1), (0.0, -0.6)), 1),
    (((0.0, -1.4), (0.0, -0.8), (0.0, 0.9)), 1),
]


def _run(pair, states, formula):
    qpos, qvel, qacc = (np.array([s[k] for s in states], dtype=float) for k in range(3))
    return dynamics_of_pair(pair, qpos, qvel, qacc, formulas=[formula])


@pytest.mark.parametrize("formula", RECIPES)
def test_recipe_dynamics_differ_from_engines_at_general_poses(load_pair, formula):
    pair = load_pair("gimbal.xml")
    result = _run(pair, GENERAL, formula)
    for route in ("lagrange@mujoco", "lagrange@pinocchio"):
        r = result.routes[(formula, route)]
        for engine in ENGINES:
            M_ref, Q_ref = result.engine_mass[engine], result.engine_forces[engine]
            m_err = np.linalg.norm(r.M - M_ref, axis=(1, 2)) / np.linalg.norm(M_ref, axis=(1, 2))
            q_err = np.linalg.norm(r.Q - Q_ref, axis=1) / np.linalg.norm(Q_ref, axis=1)
            assert (m_err > 1e-3).all(), (route, engine, m_err)
            assert (q_err > 1e-3).all(), (route, engine, q_err)
    assert result.ok  # the recipe's disagreement is a finding, not a failure of the check


@pytest.mark.parametrize("formula", RECIPES)
@pytest.mark.parametrize(("state", "joint"), ONE_JOINT)
def test_recipe_dynamics_coincide_when_only_one_joint_moves(load_pair, formula, state, joint):
    pair = load_pair("gimbal.xml")
    result = _run(pair, [state], formula)
    for route in ("lagrange@mujoco", "lagrange@pinocchio"):
        r = result.routes[(formula, route)]
        for engine in ENGINES:
            M_ref, Q_ref = result.engine_mass[engine][0], result.engine_forces[engine][0]
            assert abs(r.M[0, joint, joint] - M_ref[joint, joint]) < 1e-9 * abs(M_ref[joint, joint])
            assert abs(r.Q[0, joint] - Q_ref[joint]) < 1e-6 * abs(Q_ref[joint])
            # ... and not beyond that submanifold: the coupling entry is wrong
            assert abs(r.M[0, 0, 1] - M_ref[0, 1]) > 1e-3 * np.linalg.norm(M_ref)
