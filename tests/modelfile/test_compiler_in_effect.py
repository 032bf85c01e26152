"""A compiler option is reported only when MuJoCo changes the masses with it; a body's note only when it has geoms.

The independent route is MuJoCo itself: the file compiled with the option and with the option removed.  An option
written ``0`` (``settotalmass="0"``, ``boundmass="0"``: MuJoCo's own defaults, "off") changes no mass, so no record
and no note may say that MuJoCo rescales or raises anything.  A body without ``<inertial>`` and without geoms
takes no inertia from geoms: no note may say it does.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.modelfile.compiler import compiler_findings, compiler_options

BODIES = """
  <worldbody>
    <body name="arm">
      <joint name="shoulder" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.04"/>
      <body name="bracket" pos="0.3 0 0">
        <body name="hand" pos="0.05 0 0">
          <joint name="wrist" type="hinge" axis="0 0 1"/>
          <inertial pos="0.05 0 0" mass="0.1" diaginertia="0.001 0.002 0.0025"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def _write(tmp_path: Path, compiler: str) -> Path:
    path = tmp_path / "model.xml"
    path.write_text(f'<mujoco model="m">\n  <compiler {compiler}/>' + BODIES)
    return path


def _masses(path: Path) -> np.ndarray:
    return np.array(mujoco.MjModel.from_xml_path(str(path)).body_mass)


@pytest.mark.parametrize(
    "written", ['settotalmass="0"', 'settotalmass="-1"', 'boundmass="0"', 'boundinertia="0"', 'balanceinertia="false"']
)
def test_an_option_written_off_is_not_in_effect(tmp_path: Path, written: str) -> None:
    path = _write(tmp_path, written)
    without = tmp_path / "without.xml"
    without.write_text('<mujoco model="m">' + BODIES)
    assert np.array_equal(_masses(path), _masses(without))  # MuJoCo: the option changes nothing
    assert compiler_options(path) == []
    assert not [line for line in compiler_findings(path) if line.startswith("compiler ")]


@pytest.mark.parametrize(("written", "total"), [('settotalmass="3"', 3.0), ('boundmass="0.5"', None)])
def test_an_option_in_effect_is_one_record(tmp_path: Path, written: str, total: float | None) -> None:
    path = _write(tmp_path, written)
    without = tmp_path / "without.xml"
    without.write_text('<mujoco model="m">' + BODIES)
    assert not np.array_equal(_masses(path), _masses(without))  # MuJoCo: the option changes the masses
    if total is not None:
        assert _masses(path).sum() == pytest.approx(total)
    (record,) = compiler_options(path)
    assert record.element == "compiler " + written.split("=")[0]


def test_a_body_without_inertial_and_without_geoms_gets_no_note(tmp_path: Path) -> None:
    path = _write(tmp_path, 'angle="radian"')
    notes = [line for line in compiler_findings(path) if "has no <inertial>" in line]
    assert notes == [
        "body 'arm' has no <inertial>: its inertia comes from geoms of type ['capsule']; a parser that "
        "ignores a geom type (e.g. mesh) gets a different inertia"
    ]
    model = mujoco.MjModel.from_xml_path(str(path))
    assert model.body_mass[model.body("bracket").id] == 0.0  # MuJoCo: the geomless body has no mass of its own
