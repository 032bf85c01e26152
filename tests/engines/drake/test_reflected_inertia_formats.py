"""drake.urdf.reflected-inertia is URDF's: in MJCF, Drake reads a driven joint's armature as written.

Drake's MJCF parser takes a motor-driven joint's ``armature`` as the motor's rotor inertia with gear ratio 1
(whatever the motor's ``gear``), so its reflected inertia is the armature MuJoCo and Pinocchio add: no MJCF file
shows the URDF cause (MuJoCo's schema refuses ``drake:`` attributes).  Measured against the hand value.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.causes import cause

pytest.importorskip("pydrake")

#: One box arm (0.6 x 0.1 x 0.1 m, 1 kg, centre 0.3 m from the axis) on a hinge with armature 0.01, driven by a
#: motor of gear 10 (and a second of gear 3): about z, M = (0.6² + 0.1²)/12 + 0.3² + 0.01.
MJCF = """<mujoco model="driven_armature">
  <worldbody>
    <body name="arm"><joint name="spin" type="hinge" axis="0 0 1" armature="0.01"/>
      <geom type="box" size="0.3 0.05 0.05" pos="0.3 0 0" mass="1"/></body>
  </worldbody>
  <actuator><motor name="m" joint="spin" gear="10"/>{second}</actuator>
</mujoco>
"""
BY_HAND = (0.6**2 + 0.1**2) / 12 + 0.3**2 + 0.01


def test_the_cause_is_declared_for_urdf_only() -> None:
    assert cause("drake.urdf.reflected-inertia").formats == ("urdf",)


@pytest.mark.parametrize("second", ["", '<motor name="m2" joint="spin" gear="3"/>'], ids=["one motor", "two"])
def test_drake_reads_a_driven_joint_armature_in_mjcf_as_written(tmp_path: Path, second: str) -> None:
    from koenig_check.engines.drake.causes import measure as drake
    from koenig_check.engines.mujoco.causes import measure as mujoco

    path = tmp_path / "driven_armature.xml"
    path.write_text(MJCF.format(second=second))
    d, m = drake(path), mujoco(path)
    assert d.mass_matrix[("spin", "spin")] == pytest.approx(BY_HAND, rel=1e-12)  # not 0.01 × 10² reflected
    assert m.mass_matrix[("spin", "spin")] == pytest.approx(BY_HAND, rel=1e-12)
    assert d.armature == {"spin": pytest.approx(0.01, rel=1e-12)}
