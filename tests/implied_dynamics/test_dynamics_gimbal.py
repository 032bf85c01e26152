"""The paper's gimbal by hand: M(q) and Q* in closed form against all three routes and both engines.

Hinge ``outer_z`` (angle ψ) about the world z axis carries the outer frame; hinge ``inner_x`` (angle θ)
about the outer frame's x axis, at a point of the z axis, carries the asymmetric inner body.  With
``R_inner = Rz(ψ) Rx(θ)`` the inner body's angular velocity in its own axes is

    ω_b = (θ̇, ψ̇ sin θ, ψ̇ cos θ) = A(θ) (ψ̇, θ̇),   A = [[0, 1], [sin θ, 0], [cos θ, 0]].

Both hinge anchors sit on the z axis, fixed in the world, so each body rotates about a fixed point O
and ``T = ½ J1_zz ψ̇² + ½ ω_bᵀ J2 ω_b`` with ``J = I_C + m (|c|² 1 − c cᵀ)`` the inertia about the
anchor (parallel-axis theorem; ``c`` the COM in the body's axes).  Hence

    M_ψψ = J1_zz + s² J2_yy + 2 s c J2_yz + c² J2_zz,   M_ψθ = s J2_xy + c J2_xz,   M_θθ = J2_xx,

and, M depending on θ only, Lagrange's equations give ``τ = M q̈ + Ṁ q̇ − ∂T/∂q``:

    τ_ψ = M_ψψ ψ̈ + M_ψθ θ̈ + M_ψψ' θ̇ ψ̇ + M_ψθ' θ̇²
    τ_θ = M_ψθ ψ̈ + M_θθ θ̈ − ½ M_ψψ' ψ̇²
    M_ψψ' = 2 s c (J2_yy − J2_zz) + 2 (c² − s²) J2_yz,   M_ψθ' = c J2_xy − s J2_xz,

with ``Q* = −τ``.  The numbers are models/gimbal.xml's, typed here (MJCF ``fullinertia`` is
``Ixx Iyy Izz Ixy Ixz Iyz``).
"""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.implied_dynamics.analysis import ENGINES, dynamics_of_pair

M1, C1 = 0.6, np.array([0.03, -0.02, 0.05])
I1 = np.array([[0.004195, 0.000544, 0.000258], [0.000544, 0.005923, -0.000485], [0.000258, -0.000485, 0.007882]])
M2, C2 = 2.0, np.array([0.07, 0.05, -0.04])
I2 = np.array([[0.019401, -0.006439, -0.001736], [-0.006439, 0.020517, -0.005249], [-0.001736, -0.005249, 0.028082]])


def about_anchor(m: float, c: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    return inertia + m * (c @ c * np.eye(3) - np.outer(c, c))


J1, J2 = about_anchor(M1, C1, I1), about_anchor(M2, C2, I2)


def hand_mass_matrix(theta: float) -> np.ndarray:
    s, c = np.sin(theta), np.cos(theta)
    m_pp = J1[2, 2] + s * s * J2[1, 1] + 2 * s * c * J2[1, 2] + c * c * J2[2, 2]
    m_pt = s * J2[0, 1] + c * J2[0, 2]
    return np.array([[m_pp, m_pt], [m_pt, J2[0, 0]]])


def hand_inertia_forces(theta: float, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
    s, c = np.sin(theta), np.cos(theta)
    (pd, td), (pdd, tdd) = qvel, qacc
    M = hand_mass_matrix(theta)
    d_pp = 2 * s * c * (J2[1, 1] - J2[2, 2]) + 2 * (c * c - s * s) * J2[1, 2]
    d_pt = c * J2[0, 1] - s * J2[0, 2]
    tau_psi = M[0, 0] * pdd + M[0, 1] * tdd + d_pp * td * pd + d_pt * td * td
    tau_theta = M[0, 1] * pdd + M[1, 1] * tdd - 0.5 * d_pp * pd * pd
    return -np.array([tau_psi, tau_theta])


# (ψ, θ), (ψ̇, θ̇), (ψ̈, θ̈)
STATES = [
    ((0.0, 0.0), (1.0, 0.0), (0.0, 0.0)),  # Q*_θ = J2_yz ψ̇²: the centrifugal product of inertia alone
    ((0.7, 0.9), (1.3, -0.8), (0.4, 1.1)),
    ((-2.2, 1.4), (-0.6, 2.0), (-1.5, 0.3)),
    ((2.9, -2.5), (2.5, 1.7), (0.9, -2.0)),
]


@pytest.mark.parametrize("fmt", ["xml", "urdf"])
def test_hand_derived_gimbal_matches_every_route_and_both_engines(load_pair, fmt):
    pair = load_pair(f"gimbal.{fmt}")
    assert pair.mujoco.dof_segments() == ("outer_z", "inner_x")
    qpos, qvel, qacc = (np.array([s[k] for s in STATES], dtype=float) for k in range(3))
    M_hand = np.array([hand_mass_matrix(q[1]) for q in qpos])
    Q_hand = np.array([hand_inertia_forces(q[1], v, a) for q, v, a in zip(qpos, qvel, qacc, strict=True)])
    result = dynamics_of_pair(pair, qpos, qvel, qacc, formulas=["exact"])
    candidates = {route: (r.M, r.Q) for (_, route), r in result.routes.items()}
    candidates |= {f"engine {e}": (result.engine_mass[e], result.engine_forces[e]) for e in ENGINES}
    assert len(candidates) == 6
    for name, (M, Q) in candidates.items():
        m_err = np.linalg.norm(M - M_hand, axis=(1, 2)) / np.linalg.norm(M_hand, axis=(1, 2))
        q_err = np.linalg.norm(Q - Q_hand, axis=1) / np.linalg.norm(Q_hand, axis=1)
        assert m_err.max() < 1e-9, (name, m_err)
        assert q_err.max() < 1e-6, (name, q_err)
