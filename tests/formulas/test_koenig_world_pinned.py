"""koenig_world pinned on a two-axis rotation of the gimbal, computed by hand from the model file.

At q = (outer_z, inner_x) = (π/2, π/2) the inner body's axes are permuted onto the world axes
(body x → world y, body y → world z, body z → world x), so the current-pose axial moments about
world axes are the body diagonal permuted, and they differ from the initial-pose ones.  One-axis
tests cannot tell the two apart; this one can.
"""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.demo import builtin_models
from koenig_check.engines import load_model
from koenig_check.formulas import FORMULAS

# From models/gimbal.xml (fullinertia order: ixx iyy izz ixy ixz iyz).
M_OUTER, COM_OUTER, IZZ_OUTER = 0.6, (0.03, -0.02, 0.05), 0.007882
M_INNER, COM_INNER = 2.0, (0.07, 0.05, -0.04)
IXX_INNER, IYY_INNER, IZZ_INNER = 0.019401, 0.020517, 0.028082
INNER_ANCHOR_Z = 0.12  # inner_x's anchor above outer_z's, on its axis
A_DOT, B_DOT = 1.5, -2.0


def hand_value(current_moments: bool = True) -> float:
    """koenig_world at q = (π/2, π/2), q̇ = (A_DOT, B_DOT), term by term."""
    # Outer frame: R_z(π/2) maps (x, y, z) to (−y, x, z); ω_outer = (0, 0, A_DOT).
    cx, cy, cz = COM_OUTER
    r_outer = (-cy, cx, cz)  # COM from the outer_z axis point, world
    v_outer = (-A_DOT * r_outer[1], A_DOT * r_outer[0], 0.0)  # ẑ × r
    t_outer = 0.5 * M_OUTER * sum(v * v for v in v_outer) + 0.5 * A_DOT**2 * IZZ_OUTER
    # Inner body: R_x(π/2) maps (x, y, z) to (x, −z, y), then R_z(π/2).
    px, py, pz = COM_INNER
    local = (px, -pz, py)  # COM from inner_x's anchor, outer axes
    from_anchor = (-local[1], local[0], local[2])  # world
    from_axis_z = (from_anchor[0], from_anchor[1], from_anchor[2] + INNER_ANCHOR_Z)
    # ω_inner = A_DOT ẑ + B_DOT R_z(π/2) x̂ = (0, B_DOT, A_DOT)
    v_z = (-A_DOT * from_axis_z[1], A_DOT * from_axis_z[0], 0.0)  # A_DOT ẑ × r
    v_x = (B_DOT * from_anchor[2], 0.0, -B_DOT * from_anchor[0])  # B_DOT ŷ × r
    v_inner = [a + b for a, b in zip(v_z, v_x, strict=True)]
    if current_moments:  # world (x, y, z) diagonal = body (zz, xx, yy)
        j_y, j_z = IXX_INNER, IYY_INNER
    else:  # the initial pose: body axes along the world's
        j_y, j_z = IYY_INNER, IZZ_INNER
    t_inner = 0.5 * M_INNER * sum(v * v for v in v_inner) + 0.5 * (B_DOT**2 * j_y + A_DOT**2 * j_z)
    return t_outer + t_inner


@pytest.mark.parametrize("fmt", ["mjcf", "urdf"])
@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_koenig_world_on_a_two_axis_gimbal_pose_matches_hand_value(fmt: str, engine: str) -> None:
    pair = load_model(next(p for p in builtin_models() if p.name == f"gimbal.{fmt.replace('mjcf', 'xml')}"))
    qpos = np.array([[np.pi / 2, np.pi / 2]])
    qvel = np.array([[A_DOT, B_DOT]])
    states = getattr(pair, engine).segment_states(qpos, qvel)
    value = float(FORMULAS["koenig_world"](states).sum())
    np.testing.assert_allclose(value, hand_value(), rtol=1e-12)
    # the pin is sharp: the initial-pose moments give another number, and exact yet another
    assert abs(hand_value(False) - hand_value()) > 1e-3 * hand_value()
    assert abs(float(FORMULAS["exact"](states).sum()) - value) > 1e-3 * value
