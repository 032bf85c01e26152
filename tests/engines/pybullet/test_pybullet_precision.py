"""PyBullet's declared precision (3e-6: it diagonalizes every inertia) is part of every verdict: its round-off is
never called a departure, and a difference above it always is."""

from __future__ import annotations

import numpy as np
import pytest

import koenig_check
from koenig_check.diagnosis.three_way import _departing
from koenig_check.findings import Kind

pytest.importorskip("pybullet")


@pytest.mark.parametrize(("offset", "departs"), [(2e-6, False), (5e-6, True)])
def test_round_off_below_the_precision_is_agreement(offset: float, departs: bool) -> None:
    values = {e: np.array([2.0]) for e in ("mujoco", "pinocchio", "idyntree")}
    values["pybullet"] = np.array([2.0 * (1 + offset)])
    assert _departing(values, 1e-9) == (("pybullet",) if departs else None)


def test_an_engine_of_finer_precision_departs_by_the_same_round_off() -> None:
    values = {e: np.array([2.0]) for e in ("mujoco", "pinocchio", "pybullet")}
    values["idyntree"] = np.array([2.0 * (1 + 2e-6)])  # iDynTree declares 1e-12
    assert _departing(values, 1e-9) == ("idyntree",)


def test_pandas_diagonalized_inertias_are_no_departure() -> None:
    """panda's link1 inertia comes back from PyBullet's principal axes 1e-9 off (measured): within its precision."""
    check = koenig_check.compare("panda", n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio", "pybullet"))
    assert check.ok and not [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]


#: example-robot-data's tiago wheel: two principal moments 9e-8 apart, products of inertia 4e-8.
WHEEL = {"ixx": 0.00499743171, "ixy": 4.464e-08, "ixz": -2.245e-08, "iyy": 0.00499741733, "iyz": -1.64e-09}
WHEELS = """<robot name="wheels">
  <link name="world"/>
  <link name="wheel"><inertial><origin xyz="0.1 0 0"/><mass value="1.8"/>
    <inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="0.00839239692"/></inertial></link>
  <joint name="spin" type="continuous"><parent link="world"/><child link="wheel"/><axis xyz="0 1 0"/></joint>
</robot>
"""


def test_a_wheels_nearly_equal_moments_come_back_within_the_precision(tmp_path) -> None:
    """PyBullet's own inertia of tiago's wheel (getDynamicsInfo) is 1.2e-6 off the file's: round-off, no departure."""
    import pybullet

    path = tmp_path / "wheels.urdf"
    path.write_text(WHEELS.format(**WHEEL))
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(path), flags=pybullet.URDF_USE_INERTIA_FROM_FILE, physicsClientId=client)
        info = pybullet.getDynamicsInfo(body, 0, physicsClientId=client)
        axes = np.array(pybullet.getMatrixFromQuaternion(info[4], physicsClientId=client)).reshape(3, 3)
    finally:
        pybullet.disconnect(client)
    i = WHEEL
    written = np.array(
        [[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]], [i["ixz"], i["iyz"], 0.00839239692]]
    )
    off = np.abs(axes @ np.diag(info[2]) @ axes.T - written).max()
    assert 1e-7 * 0.00839239692 < off <= 1e-6 * np.trace(written)  # beyond the old 1e-7, within Bullet's threshold
    check = koenig_check.compare(str(path), n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio", "pybullet"))
    assert not [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]
