"""Pinocchio's load errors reach the user whole, on one line, naming the file, with what to do for known limitations.

(MuJoCo's compile errors: ``tests/engines/mujoco/test_mujoco_load_errors.py``.)
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.api import compare, make_poses
from koenig_check.engines import ModelLoadError, load_model
from koenig_check.engines.pinocchio.loader import parser_reason
from koenig_check.findings import Kind

MODELS = Path(__file__).resolve().parents[1] / "models"


@pytest.mark.parametrize(
    ("name", "reason", "hint"),
    [
        ("hfield.xml", "hfields are not supported yet", "--pinocchio-model"),
        ("include_worldbody.xml", "No such node (body)", "include_arm.xml"),
    ],
)
def test_pinocchio_parse_error_gives_the_whole_reason_on_one_line(name: str, reason: str, hint: str) -> None:
    path = MODELS / name
    with pytest.raises(ModelLoadError) as info:
        load_model(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg and reason in msg and hint in msg
    assert "From file" not in msg and ".cpp" not in msg
    check = compare(path, n_poses=2)  # the batch route: same reason
    assert not check.ok and reason in check.reason()


def test_parser_reason_keeps_every_line_of_reason_and_drops_source_locations() -> None:
    exc = ValueError(
        "From file: /project/src/parsers/mjcf/mjcf-graph.cpp\nin function: void f()\nat line: 726\nmessage:\n"
        "first reason\nsecond reason\n"
    )
    assert parser_reason(exc, ["Error: urdfdom says this", "Warning: not this"]) == (
        "first reason; second reason; urdfdom says this"
    )


def test_parser_reason_puts_urdfdom_skipped_link_elements_last_and_folds_repeats() -> None:
    output = [
        "Error:   Could not parse collision element for Link [a]",
        "Error:   Could not parse collision element for Link [b]",
        "Error:   Could not parse visual element for Link [b]",
        "Error:   Joint [j] has no known type [spherical]",
        "Error:   joint xml is not initialized correctly",
    ]
    assert parser_reason(ValueError("not a valid URDF model."), output) == (
        "not a valid URDF model.; Joint [j] has no known type [spherical]; joint xml is not initialized correctly; "
        "Could not parse collision element for Link [a] (and 1 more); Could not parse visual element for Link [b]"
    )


def test_pinocchio_refusal_names_the_element_it_stopped_at_not_those_it_skipped() -> None:
    """humanoid.urdf of pybullet_data: eight capsule collisions urdfdom skips, then a spherical joint it refuses."""
    import mujoco

    path = MODELS / "spherical_capsules.urdf"
    model = mujoco.MjModel.from_xml_path(str(path))  # MuJoCo reads the file: the refusal is Pinocchio's alone
    assert list(model.jnt_type) == [mujoco.mjtJoint.mjJNT_BALL, mujoco.mjtJoint.mjJNT_HINGE]
    with pytest.raises(ModelLoadError) as info:
        load_model(path)
    msg = str(info.value)
    stopped, skipped = (
        "Joint [shoulder] has no known type [spherical]",
        "collision element for Link [base] (and 2 more)",
    )
    assert "\n" not in msg and str(path) in msg and stopped in msg and skipped in msg
    assert msg.index(stopped) < msg.index(skipped) and "Link [upper]" not in msg
    check = compare(path, n_poses=2)  # the one-line reason of the batch keeps the element it stopped at
    assert not check.ok and stopped in check.reason()


#: A joint whose default class is defined in an included file (Pinocchio's MJCF parser ignores <include>).
CLASS_IN_INCLUDE = """<mujoco model="class_in_include">
  <include file="classes.xml"/>
  <worldbody>
    <body name="arm">
      <joint name="shoulder" type="hinge" axis="0 1 0" class="soft"/>
      <geom type="sphere" size="0.1" pos="0 0 0.3" mass="1"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_a_class_pinocchio_cannot_find_is_its_refusal_naming_the_class_and_the_element(tmp_path: Path) -> None:
    """Pinocchio raises IndexError ('unordered_map::at'): a refusal naming the file, not a bare C++ message."""
    import mujoco
    import pinocchio as pin

    (tmp_path / "classes.xml").write_text(
        '<mujocoinclude><default><default class="soft"><joint damping="2"/></default></default></mujocoinclude>'
    )
    path = tmp_path / "class_in_include.xml"
    path.write_text(CLASS_IN_INCLUDE)
    assert mujoco.MjModel.from_xml_path(str(path)).dof_damping[0] == 2.0  # MuJoCo reads the class
    with pytest.raises(IndexError, match="unordered_map::at"):  # Pinocchio's own reason, as it gives it
        pin.buildModelFromMJCF(str(path))
    with pytest.raises(ModelLoadError) as info:
        load_model(path)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{path}: Pinocchio cannot parse the file: unordered_map::at")
    assert "class 'soft' of joint shoulder: not in the file's own <default>" in msg
    check = compare(path, n_poses=2)
    assert not check.ok and "class 'soft' of joint shoulder" in check.reason()


def test_floating_keyframes_pinocchio_refuses_are_dropped_for_pinocchio_and_said(tmp_path: Path) -> None:
    path = MODELS / "keyframe_floating.xml"
    with pytest.raises(ModelLoadError, match="Keyframe size does not match model size"):
        import pinocchio as pin

        from koenig_check.engines.pinocchio.loader import _build
        from koenig_check.sources.catalogue import resolve_model

        try:  # the limitation itself, straight from Pinocchio
            pin.buildModelFromMJCFAndRootJoint(str(path), pin.JointModelFreeFlyer(), "root_joint")
        except ValueError as exc:
            raise ModelLoadError(str(exc)) from exc
        _build(resolve_model(path), str(path), pin.JointModelFreeFlyer(), "root_joint", [])
    before = sorted(p.name for p in MODELS.iterdir())
    pair = load_model(path, floating=True)
    assert sorted(p.name for p in MODELS.iterdir()) == before  # the keyframe-free copy is gone
    (found,) = [f for f in pair.findings if f.kind is Kind.LOAD and f.element == "keyframe"]
    assert found.engine == "pinocchio" and not found.affects_energy and "without the file's keyframes" in found.summary
    assert pair.mujoco.model.nkey == 1  # MuJoCo keeps its keyframe
    keys = make_poses(pair.mujoco.model, "keyframes")
    assert keys.ids == ("key:bent",) and np.isclose(keys.qpos[0, -1], 0.4)
    check = compare(path, floating=True, n_poses=4)
    assert check.ok, check.reason()


#: A URDF whose root link is MuJoCo's world body, with two joints below it: --floating has no one link to free.
WORLD_TWO_BELOW = """<robot name="two_below">
  <link name="world"/>
  <link name="a"><inertial><mass value="1"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="b"><inertial><mass value="2"/>
    <inertia ixx="0.2" iyy="0.2" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hold" type="fixed"><parent link="world"/><child link="a"/></joint>
  <joint name="swing" type="revolute"><parent link="world"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_pinocchio_refuses_to_float_a_world_link_holding_several_joints_naming_them(tmp_path: Path) -> None:
    """Compare reaches MuJoCo's refusal of such a file first; Pinocchio's loader says its own reason on its own."""
    from koenig_check.engines.pinocchio.loader import load_pinocchio
    from koenig_check.sources.catalogue import resolve_model

    path = tmp_path / "two_below.urdf"
    path.write_text(WORLD_TWO_BELOW, encoding="utf-8")
    source = resolve_model(path)
    with pytest.raises(ModelLoadError) as info:
        load_pinocchio(source, root_joint="root")
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith(f"{path}: link 'world'")
    assert msg.endswith("joints below 'world': hold (fixed), swing (revolute)")
    model, _ = load_pinocchio(source)  # fixed base: the file is read as written
    assert [model.names[j] for j in range(1, model.njoints)] == ["swing"]
