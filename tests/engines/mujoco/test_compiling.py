"""Compiling a spec MuJoCo refuses: a fused inertia it rejects is named, and ``--repair-inertia`` loads it.

The pendulum below is built like Drake's ``examples/pendulum/Pendulum.urdf``: a moving link and a link welded
to it are both point masses on one line, so the inertia MuJoCo's ``fusestatic`` makes of the two has a zero
principal moment, which it refuses without naming a body.  By hand: 1 kg at 0.5 m from the hinge, so the
mass matrix is m l² = 0.25 kg m² at every angle.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.api import compare
from koenig_check.engines import InertiaError, load_model
from koenig_check.findings import Kind

PENDULUM = """<robot name="point_pendulum">
  <link name="base"/>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.5"/><mass value="0.5"/>
      <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
  </link>
  <link name="arm_com">
    <inertial><mass value="0.5"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
  </link>
  <joint name="theta" type="continuous">
    <parent link="base"/><child link="arm"/><axis xyz="0 1 0"/>
  </joint>
  <joint name="arm_weld" type="fixed">
    <parent link="arm"/><child link="arm_com"/><origin xyz="0 0 -0.5"/>
  </joint>
</robot>
"""
HAND_M = 1.0 * 0.5**2  # kg m²
ANGLES = np.array([0.0, 0.7, -2.1])


@pytest.fixture
def pendulum(tmp_path: Path) -> Path:
    path = tmp_path / "point_pendulum.urdf"
    path.write_text(PENDULUM)
    return path


def test_mujoco_itself_refuses_the_fused_inertia_without_naming_a_body(pendulum: Path) -> None:
    with pytest.raises(ValueError, match="fusing static body inertias") as info:
        mujoco.MjModel.from_xml_path(str(pendulum))
    assert "Element name" not in str(info.value)


def test_the_refusal_names_the_links_fused_and_the_option(pendulum: Path) -> None:
    with pytest.raises(InertiaError) as info:
        load_model(pendulum)
    message = str(info.value)
    assert "\n" not in message and str(pendulum) in message and "--repair-inertia" in message
    assert "'arm_com' into 'arm'" in message and "positive eigenvalues" in message and "link ''" not in message


def test_repair_loads_it_with_static_links_kept_apart_and_the_hand_mass_matrix(pendulum: Path) -> None:
    pair = load_model(pendulum, repair_inertia=True)
    kept = [f for f in pair.findings if f.kind is Kind.LOAD and f.element == "compiler fusestatic"]
    assert len(kept) == 1 and list(kept[0].values["fusions"]) == ["arm_com into arm"]
    assert [f.element for f in pair.findings if f.kind is Kind.REPAIR] == ["link arm"]
    qpos = np.stack([np.cos(ANGLES), np.sin(ANGLES)], axis=1) if pair.mujoco.model.nq == 2 else ANGLES[:, None]
    for engine in pair.engines.values():
        np.testing.assert_allclose(engine.mass_matrix(qpos)[:, 0, 0], HAND_M, rtol=1e-12)
    check = compare(pendulum, repair_inertia=True, n_poses=3, formulas=["exact"])
    assert not check.failures and check.agreements[0].rigid_max_rel <= 1e-12
