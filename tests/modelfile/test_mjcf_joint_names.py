"""A ``<joint>`` in a default class, an equality or a tendon is not a joint an ``<include>`` brings in.

Metaworld's files include ``*_dependencies.xml`` fragments that hold only default classes (``<default><joint
damping=.../></default>``); their ``<joint>`` was counted as a joint named "?", so the include of classes read as
losing joint "?", changed the energy and came first: the one-line reason said "2 root causes not shown" instead
of naming the include that loses the arm.  Expected joints from MuJoCo's own compiled model of the file.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import koenig_check
from koenig_check.causes import cause
from koenig_check.engines.parser_traps import file_causes
from koenig_check.modelfile.mjcf import includes, read_mjcf

MAIN = """<mujoco model="includes">
  <include file="classes.xml"/>
  <worldbody>
    <body name="base">
      <joint name="shoulder" type="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0 0 0.5" size="0.05" mass="2"/>
      <include file="{fragment}"/>
    </body>
  </worldbody>
  <include file="links.xml"/>
</mujoco>
"""
#: Default classes only: what Metaworld's *_dependencies.xml files hold.
CLASSES = """<mujocoinclude>
  <default><default class="soft"><joint damping="2" limited="false"/><geom contype="1"/></default></default>
</mujocoinclude>
"""
#: Sections that name joints without making any.
LINKS = """<mujocoinclude>
  <equality><joint joint1="shoulder" joint2="elbow" polycoef="0 1 0 0 0"/></equality>
  <tendon><fixed name="coupled"><joint joint="shoulder" coef="1"/><joint joint="elbow" coef="-1"/></fixed></tendon>
</mujocoinclude>
"""
FRAGMENTS = {
    # a body with its hinge
    "forearm.xml": '<mujocoinclude><body name="forearm" pos="0 0 0.5"><joint name="elbow" type="hinge" axis="0 1 0"/>'
    '<geom type="sphere" size="0.1" mass="1"/></body></mujocoinclude>',
    # a joint at the fragment's top level, included inside body base: a joint of that body, and a second one
    "bare_joint.xml": '<mujocoinclude><joint name="elbow" type="slide" axis="1 0 0"/>'
    '<body name="tip" pos="0 0 0.5"><joint name="wrist" type="hinge"/><geom type="sphere" size="0.1" mass="1"/>'
    "</body></mujocoinclude>",
}


def _written(tmp_path: Path, fragment: str) -> Path:
    (tmp_path / "classes.xml").write_text(CLASSES)
    (tmp_path / "links.xml").write_text(LINKS)
    (tmp_path / fragment).write_text(FRAGMENTS[fragment])
    path = tmp_path / "main.xml"
    path.write_text(MAIN.format(fragment=fragment))
    return path


@pytest.mark.parametrize("fragment", list(FRAGMENTS))
def test_included_joints_are_the_joints_mujoco_builds(tmp_path: Path, fragment: str) -> None:
    path = _written(tmp_path, fragment)
    model = mujoco.MjModel.from_xml_path(str(path))
    built = {model.joint(j).name for j in range(model.njnt)} - {"shoulder"}  # the main file's own joint
    found = {inc.file: inc for inc in includes(read_mjcf(path), tmp_path)}
    assert found["classes.xml"].joints == () and found["classes.xml"].defaults
    assert found["links.xml"].joints == ()
    assert set(found[fragment].joints) == built and len(built) == len(found[fragment].joints)


@pytest.mark.parametrize("fragment", list(FRAGMENTS))
def test_an_include_of_classes_loses_no_joint_and_the_one_line_names_the_include_that_does(
    tmp_path: Path, fragment: str
) -> None:
    path = _written(tmp_path, fragment)
    causes = {c.element: c for c in file_causes(path, mujoco.MjModel.from_xml_path(str(path)))}
    classes = causes["include classes.xml"]
    assert not classes.affects_energy and classes.segments == () and classes.values["joints"] == ()
    assert causes[f"include {fragment}"].affects_energy and "include links.xml" not in causes  # nothing kinematic
    reason = koenig_check.compare(path, n_poses=2, formulas=["exact"]).reason()
    assert causes[f"include {fragment}"].cause == classes.cause == "pinocchio.mjcf.include"
    assert f"root cause: include {fragment}: {cause('pinocchio.mjcf.include').brief}" in reason
    assert "?" not in reason and "not shown" not in reason
