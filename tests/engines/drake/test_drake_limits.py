"""Drake's parser limits on a user's robot: an inertia Drake replaced abstains Drake only where it moves.

pybullet_data's kuka_iiwa/model.urdf writes its base link (welded to the world) with mass 0 and a rotational inertia:
Drake's URDF parser builds it with 1 kg and another inertia, which changes no M (measured on the kuka: Drake's
``CalcMassMatrix`` equals Pinocchio's ``crba`` to 7e-16).  The same link fixed to a moving arm changes M.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check
from koenig_check.causes import cause, fixture_path
from koenig_check.findings import Kind

pytest.importorskip("pydrake")

ENGINES = ("mujoco", "pinocchio", "drake")
WELDED = """<robot name="welded_massless_base">
  <link name="base"><inertial><mass value="0"/>
    <inertia ixx="0.05" iyy="0.06" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0.2 0 0"/><mass value="2"/>
    <inertia ixx="0.01" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="swing" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def _drake_unable(path: Path) -> tuple[bool, list[str]]:
    check = koenig_check.compare(str(path), n_poses=3, formulas=["exact"], engines=ENGINES)
    (comparison,) = check.comparisons
    unable = any(f.engine == "drake" and f.kind is Kind.ENGINE_UNABLE for f in comparison.findings)
    return unable, [f.cause for f in comparison.findings if f.engine == "drake" and f.cause]


def test_an_inertia_replaced_on_a_link_welded_to_the_world_leaves_drake_checking(tmp_path: Path) -> None:
    path = tmp_path / "welded.urdf"
    path.write_text(WELDED)
    unable, causes = _drake_unable(path)
    assert causes == ["drake.urdf.replaced-inertia"]  # still said
    assert not unable


def test_an_inertia_replaced_on_a_moving_link_abstains_drake() -> None:
    unable, causes = _drake_unable(fixture_path(cause("drake.urdf.replaced-inertia")))
    assert "drake.urdf.replaced-inertia" in causes and unable
