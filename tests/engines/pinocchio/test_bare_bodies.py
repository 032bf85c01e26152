"""A ``<body>`` without any attribute is named as the root cause: Pinocchio's MJCF parser skips it.

The old verdict named only symptoms ("body a (joint j1): mass differs; body c (joint j2): anchor differs"), or
for a refusal nothing ("joints only in MuJoCo (BisBisJoint_0)").  The masses are read from each engine's own
model; the same file with ``pos="0 0 0"`` on the body (MuJoCo reads both alike) is the control.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.engines.parser_traps import file_causes

BALL = '<geom type="sphere" size="0.1" mass="1" pos="0.1 0.2 0.3"/>'
#: A bare body holding a 5 kg geom inside body a, with body c (joint j2) below it.
INSIDE = f"""<mujoco><worldbody>
  <body name="a" pos="0 0 1"><joint name="j1" type="hinge" axis="0 1 0"/>{BALL}
    <body{{attr}}><geom type="sphere" size="0.1" mass="5" pos="0.5 0 0"/>
      <body name="c" pos="0 0 1"><joint name="j2" type="hinge" axis="1 0 0"/>{BALL}</body>
    </body>
  </body>
</worldbody></mujoco>"""
#: A bare top-level body with a hinge, and an unnamed body with a hinge below it.
TOP = f"""<mujoco><worldbody>
  <body{{attr}}><joint type="hinge" axis="0 1 0"/>{BALL}
    <body pos="0 0 1"><joint type="hinge" axis="1 0 0"/>{BALL}</body>
  </body>
</worldbody></mujoco>"""


@pytest.mark.parametrize("attr", ["", ' pos="0 0 0"'])
def test_a_bare_body_weighs_nothing_in_pinocchio_and_is_the_named_cause(tmp_path: Path, attr: str) -> None:
    path = tmp_path / "inside.xml"
    path.write_text(INSIDE.format(attr=attr))
    model = mujoco.MjModel.from_xml_path(str(path))
    pmodel = pin.buildModelFromMJCF(str(path))
    assert sum(model.body_mass) == pytest.approx(7.0)  # MuJoCo: a, the bare body, c
    assert sum(i.mass for i in pmodel.inertias) == pytest.approx(2.0 if not attr else 7.0)  # Pinocchio: a, c
    causes = [c for c in file_causes(path, model) if c.cause == "pinocchio.mjcf.bare-body"]
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    if attr:
        assert causes == [] and check.ok, check.reason()
        return
    (cause,) = causes
    assert cause.element == "body without attributes in body a" and cause.engine == "pinocchio"
    assert cause.affects_energy and cause.values["geoms"] == 1
    assert cause.segments == ("j1", "j2") and cause.values["joints"] == ()  # c hangs from the world, j2 is not lost
    assert not check.ok and "root cause: body without attributes in body a" in check.reason()


@pytest.mark.parametrize("attr", ["", ' pos="0 0 0"'])
def test_a_bare_top_level_body_is_named_when_the_joints_do_not_pair(tmp_path: Path, attr: str) -> None:
    path = tmp_path / "top.xml"
    path.write_text(TOP.format(attr=attr))
    pmodel = pin.buildModelFromMJCF(str(path))
    assert pmodel.nq == (1 if not attr else 2)  # Pinocchio loses the bare body's hinge
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    if attr:
        assert check.ok, check.reason()
        return
    assert not check.ok and "root cause: body without attributes in worldbody" in check.reason()


def test_a_bare_leaf_body_with_a_geom_only_changes_the_energy(tmp_path: Path) -> None:
    path = tmp_path / "leaf.xml"
    path.write_text(
        INSIDE.format(attr="").replace(
            f'<body name="c" pos="0 0 1"><joint name="j2" type="hinge" axis="1 0 0"/>{BALL}</body>', ""
        )
    )
    model = mujoco.MjModel.from_xml_path(str(path))
    assert model.njnt == 1 and sum(model.body_mass) == pytest.approx(6.0)
    assert sum(i.mass for i in pin.buildModelFromMJCF(str(path)).inertias) == pytest.approx(1.0)
    (cause,) = [c for c in file_causes(path, model) if c.cause == "pinocchio.mjcf.bare-body"]
    assert cause.affects_energy and cause.segments == ("j1",) and cause.values["joints"] == ()
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert not check.ok and "root cause: body without attributes in body a" in check.reason()


#: dm_control's model_with_ball_joints.xml: a bare top-level body without joints, welded to the world.
STATIC = f"""<mujoco><worldbody>
  <body><geom type="sphere" size="0.1" mass="5"/>
    <body name="b" pos="0 0 1"><joint name="j" type="hinge" axis="1 0 0"/>{BALL}</body>
  </body>
</worldbody></mujoco>"""


def test_a_bare_body_welded_to_the_world_changes_no_energy(tmp_path: Path) -> None:
    path = tmp_path / "static.xml"
    path.write_text(STATIC)
    (cause,) = [c for c in file_causes(path) if c.cause == "pinocchio.mjcf.bare-body"]
    assert not cause.affects_energy and cause.values["joints"] == ()  # b moves alike, its joint is there
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert check.ok, check.reason()
