"""A body whose explicit inertial MuJoCo's compiler rescaled (settotalmass): the finding blames the engine that departs.

The file asks for 2 kg in all; MuJoCo gives the body 2 kg (as the file asks), Pinocchio the inertial's 1 kg as if
the option were absent.  The catalogue declares MuJoCo's reading "as written" and Pinocchio's "differently": the
loader's finding names Pinocchio, the engine of the cause's id, never the one that applies the option.
"""

from __future__ import annotations

from pathlib import Path

import pinocchio as pin
import pytest

from koenig_check.engines import load_model
from koenig_check.engines.catalogue import cause

MODEL = """<mujoco model="rescaled">
  <compiler settotalmass="2"/>
  <worldbody>
    <body name="b"><joint name="j" type="hinge" axis="0 1 0"/>
      <inertial pos="0 0 0.1" mass="1" diaginertia="0.1 0.2 0.3"/></body>
  </worldbody>
</mujoco>
"""


def test_the_rescaled_body_is_blamed_on_the_engine_that_ignores_the_option(tmp_path: Path) -> None:
    path = tmp_path / "rescaled.xml"
    path.write_text(MODEL)
    model = load_model(path)
    assert float(model.mujoco.model.body_mass.sum()) == pytest.approx(2.0, rel=1e-12)  # the option, as written
    as_read = pin.buildModelFromMJCF(str(path))  # Pinocchio's own reading: the inertial's mass
    assert sum(y.mass for y in as_read.inertias) == pytest.approx(1.0, rel=1e-12)
    declared = cause("pinocchio.mjcf.settotalmass")
    assert (declared.reading("mujoco").reads, declared.reading("pinocchio").reads) == ("as written", "differently")
    found = [f for f in model.findings if f.cause == declared.id]
    assert [(f.engine, f.element, f.root_cause) for f in found] == [("pinocchio", "body b", True)]
    assert found[0].values["mass in the file"] == pytest.approx(1.0) and found[0].values[
        "mass compiled"
    ] == pytest.approx(2.0)
