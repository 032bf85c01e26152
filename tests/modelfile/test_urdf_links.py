"""A URDF whose joints name links it never declares (Drake's implicit ``world``): the joint and link are named.

Drake's ``examples/acrobot/Acrobot.urdf`` welds ``base_link`` to a ``world`` link it does not declare; MuJoCo and
Pinocchio both refuse that file (checked here on each engine directly), and load it once the link is declared.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.modelfile.urdf_links import links_without_inertial, planar_joints, undeclared_links

LINK = '<link name="{0}"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>' + (
    "</inertial></link>"
)
JOINT = '<joint name="{0}" type="{1}"><parent link="{2}"/><child link="{3}"/><axis xyz="0 1 0"/></joint>'


def _urdf(tmp_path: Path, links: list[str], joints: list[tuple[str, str, str, str]]) -> Path:
    body = "".join(LINK.format(n) if n != "world" else '<link name="world"/>' for n in links)
    body += "".join(JOINT.format(*j) for j in joints)
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r">{body}</robot>')
    return path


WELDED = [("base_weld", "fixed", "world", "base"), ("shoulder", "continuous", "base", "upper")]
CASES = {
    "world not declared": (["base", "upper"], WELDED, "joint 'base_weld': parent link 'world' not declared"),
    "child not declared": (["base"], [("shoulder", "continuous", "base", "upper")], "child link 'upper'"),
    "world declared": (["world", "base", "upper"], WELDED, ""),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_undeclared_links_are_named_with_their_joint(tmp_path: Path, case: str) -> None:
    links, joints, expected = CASES[case]
    path = _urdf(tmp_path, links, joints)
    found = undeclared_links(path)
    assert (expected in found) if expected else found == ""
    assert ('add <link name="world"/>' in found) is (case == "world not declared")
    if expected:  # both engines refuse such a file themselves
        with pytest.raises(ValueError, match="parent or child missing"):
            mujoco.MjSpec.from_file(str(path))
        with pytest.raises(ValueError):
            pin.buildModelFromUrdf(str(path))


def test_the_refusal_line_names_the_joint_and_what_to_add(tmp_path: Path) -> None:
    links, joints, _ = CASES["world not declared"]
    path = _urdf(tmp_path, links, joints)
    check = koenig_check.compare(path, n_poses=2, formulas=["exact"])
    line = check.failure_lines["robot.urdf"]
    assert "\n" not in line and "root cause: joint 'base_weld': parent link 'world' not declared" in line
    assert 'add <link name="world"/>' in line and "URDF joint parent or child missing" in check.failures[0][1]
    declared = _urdf(tmp_path, ["world", *links], joints)
    assert koenig_check.compare(declared, n_poses=2, formulas=["exact"]).ok


def test_a_planar_joint_is_named_with_the_three_joints_mujoco_makes(tmp_path: Path) -> None:
    joints = [("slider", "planar", "base", "upper"), ("elbow", "continuous", "upper", "lower")]
    path = _urdf(tmp_path, ["base", "upper", "lower"], joints)
    assert planar_joints(path) == ["slider"]
    mj = mujoco.MjModel.from_xml_path(str(path))  # each engine's own reading
    assert [mj.joint(k).name for k in range(mj.njnt)] == ["slider_TX", "slider_TY", "slider_RZ", "elbow"]
    assert pin.buildModelFromUrdf(str(path)).joints[1].shortname() == "JointModelPlanar"
    check = koenig_check.compare(path, n_poses=2, formulas=["exact"])
    line = check.failure_lines["robot.urdf"]
    assert "root cause: joint slider: URDF planar joint" in line
    assert "MuJoCo's import makes it three joints (slider_TX, slider_TY, slider_RZ)" in check.failures[0][1]


def test_links_without_inertial_in_file_order(tmp_path: Path) -> None:
    """``world`` (declared bare) and ``tool`` have no <inertial>; ``base`` and ``upper`` have one."""
    path = _urdf(tmp_path, ["world", "base", "upper"], WELDED)
    path.write_text(path.read_text().replace("</robot>", '<link name="tool"/></robot>'))
    assert links_without_inertial(path) == ["world", "tool"]
    assert links_without_inertial(tmp_path / "missing.urdf") == []
