"""``--floating`` on a file whose root already moves, or that has no single root: one line saying which."""

from __future__ import annotations

from pathlib import Path

import pytest
from common import dm_control_root

from koenig_check.engines import load_model
from koenig_check.engines.errors import NotFloatableError

SUITE = dm_control_root() / "suite"
#: dm_control models whose top-level body already has joints, with them (read from the files by hand).
ROOT_JOINTS = {
    "hopper": ("torso", "rootx, rootz, rooty"),
    "walker": ("torso", "rootz, rootx, rooty"),
    "cheetah": ("torso", "rootx, rootz, rooty"),
    "acrobot": ("upper_arm", "shoulder"),
    "pendulum": ("pole", "hinge"),
    "swimmer": ("head", "rootx, rooty, rootz"),
    "reacher": ("arm", "shoulder"),
    "point_mass": ("pointmass", "root_x, root_y"),
}


@pytest.mark.parametrize("name", list(ROOT_JOINTS))
def test_root_with_joints_is_named_with_them(name: str) -> None:
    body, joints = ROOT_JOINTS[name]
    with pytest.raises(NotFloatableError) as info:
        load_model(SUITE / f"{name}.xml", floating=True)
    assert info.value.top_level == (body,)
    message = str(info.value)
    assert "\n" not in message and f"{name}.xml" in message and "--floating" in message
    assert f"top-level body '{body}' already has joints ({joints}): it moves without --floating" in message
    assert "exactly one" not in message and "found [" not in message


def test_several_top_level_bodies_are_counted(tmp_path: Path) -> None:
    body = '<body name="{0}"><geom size="0.1" mass="1"/></body>'
    path = tmp_path / "two.xml"
    path.write_text(f"<mujoco><worldbody>{body.format('a')}{body.format('b')}</worldbody></mujoco>")
    with pytest.raises(NotFloatableError, match=r"--floating.*the file has 2: 'a', 'b'") as info:
        load_model(path, floating=True)
    assert info.value.top_level == ("a", "b")


def test_no_top_level_body_is_said(tmp_path: Path) -> None:
    """A file of defaults only (dm_control's drosophila_defaults.xml): nothing to float."""
    path = tmp_path / "defaults.xml"
    path.write_text('<mujoco><default><geom size="0.1"/></default><worldbody/></mujoco>')
    with pytest.raises(NotFloatableError, match=r"--floating.*the file has none") as info:
        load_model(path, floating=True)
    assert info.value.top_level == ()
