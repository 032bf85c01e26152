"""Newton's mass matrix of a planar 2-link arm against the textbook formula, computed here by hand.

Two hinges about z; link i has mass m_i, its COM at c_i along the link from its joint, central inertia I_i about
z; the links are l1 apart.  With θ2 the elbow angle (Lagrange, planar arm):

    M11 = I1 + m1 c1² + I2 + m2 (l1² + c2² + 2 l1 c2 cos θ2)
    M12 = I2 + m2 (c2² + l1 c2 cos θ2)
    M22 = I2 + m2 c2²
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

from koenig_check.engines.newton import PRECISION
from koenig_check.engines.newton.departures import mass_matrices
from koenig_check.engines.newton.loader import build

M1, M2, C1, C2, L1, I1, I2 = 1.3, 0.7, 0.21, 0.17, 0.45, 0.011, 0.006

ARM = f"""<?xml version="1.0"?>
<robot name="arm2">
  <link name="base"/>
  <link name="upper"><inertial><origin xyz="{C1} 0 0"/><mass value="{M1}"/>
    <inertia ixx="0.002" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="{I1}"/></inertial></link>
  <link name="fore"><inertial><origin xyz="{C2} 0 0"/><mass value="{M2}"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.005" iyz="0" izz="{I2}"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/><origin xyz="{L1} 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def _by_hand(theta2: np.ndarray) -> np.ndarray:
    c = np.cos(theta2)
    m11 = I1 + M1 * C1**2 + I2 + M2 * (L1**2 + C2**2 + 2 * L1 * C2 * c)
    m12 = I2 + M2 * (C2**2 + L1 * C2 * c)
    m22 = np.full_like(c, I2 + M2 * C2**2)
    return np.stack([np.stack([m11, m12], -1), np.stack([m12, m22], -1)], -2)


def test_two_link_arm_mass_matrix_by_hand(tmp_path: Path) -> None:
    path = tmp_path / "arm2.urdf"
    path.write_text(ARM)
    model, _ = build(path, "urdf", False)
    q = np.column_stack([np.linspace(-2.0, 2.0, 7), np.linspace(-2.5, 2.5, 7)])
    M = mass_matrices(model, q)
    expected = _by_hand(q[:, 1])
    assert np.abs(M - expected).max() <= PRECISION * np.abs(expected).max()
    assert np.abs(M - expected).max() > 0  # float32: not the same numbers, the same matrix within its round-off
