"""What loading says about the engines' masses and poses: refused only when no engine has a moving mass, the
repair named when MuJoCo's masses are only its minimum ones, a centre of mass the engines place apart noted.

MuJoCo reads one file, Pinocchio another (``pinocchio_model``), so that the engines are given different robots on
purpose; expected values come from the engines' own models.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.engines import load_model
from koenig_check.engines.errors import NoMassError
from koenig_check.findings import Kind

_ARM = """<mujoco model="one">
  <worldbody>
    <body name="arm">
      <joint name="hinge" type="hinge" axis="0 0 1"/>
      <inertial pos="{x} 0 0" mass="{mass}" diaginertia="{moments}"/>
    </body>
  </worldbody>
</mujoco>
"""


def _arm(path: Path, x: float = 0.1, mass: float = 2.0, moments: str = "0.01 0.02 0.03") -> Path:
    path.write_text(_ARM.format(x=x, mass=mass, moments=moments))
    return path


def test_mass_in_one_engine_only_is_a_disagreement_not_a_refusal(tmp_path: Path) -> None:
    """MuJoCo's arm has 2 kg, Pinocchio's none: there is energy to compare, and the engines disagree."""
    heavy, massless = _arm(tmp_path / "heavy.xml"), _arm(tmp_path / "massless.xml", mass=0.0, moments="0 0 0")
    loaded = load_model(heavy, pinocchio_model=str(massless))
    assert float(loaded.mujoco.model.body_mass[1]) == 2.0 and loaded.pinocchio.model.inertias[1].mass == 0.0
    check = koenig_check.compare([heavy], pinocchio_model=str(massless), n_poses=3)
    assert not check.failures, check.failures
    (parity,) = check.agreements
    assert not parity.agrees and parity.rigid_max_rel == pytest.approx(1.0)  # |T_mj - 0| / T_mj


def test_a_refusal_after_a_repair_says_the_masses_are_the_repairs_minimum() -> None:
    path = Path(__file__).parent / "models" / "massless.urdf"
    with pytest.raises(NoMassError) as err:
        load_model(path, repair_inertia=True)
    assert "minimum masses of --repair-inertia" in str(err.value)


def test_a_centre_of_mass_the_engines_place_apart_is_a_pose_finding(tmp_path: Path) -> None:
    """Same orientation, centre of mass 0.1 m vs 0.3 m along x: the segment poses differ at qpos0."""
    loaded = load_model(_arm(tmp_path / "a.xml"), pinocchio_model=str(_arm(tmp_path / "b.xml", x=0.3)))
    gap = np.linalg.norm(loaded.mujoco.model.body_ipos[1] - loaded.pinocchio.model.inertias[1].lever)
    assert gap == pytest.approx(0.2)
    (frame,) = [f for f in loaded.findings if f.kind is Kind.FRAME]
    assert frame.segments == ("hinge",)  # the segment is named by the joint that moves it
    assert frame.values["max COM distance (m)"] == pytest.approx(0.2)
