"""Joints whose defaults come through a class without ``<joint>`` (Drake's catalogued cause), read from the file."""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check.causes
from koenig_check.modelfile.joint_classes import inherited_through_jointless_class

FIXTURES = Path(koenig_check.causes.__file__).parent / "fixtures"

BODY = '<worldbody><body name="b"{cc}><joint name="j"{jc}/><geom size=".1" mass="1"/></body></worldbody>'


def test_the_fixture_names_both_joints() -> None:
    assert inherited_through_jointless_class(FIXTURES / "class_joint_inherited.xml") == ("shoulder", "elbow")


@pytest.mark.parametrize(
    ("defaults", "cc", "jc", "expected"),
    [
        ('<joint axis="0 1 0"/><default class="a"><geom size=".2"/></default>', ' childclass="a"', "", ("j",)),
        ('<joint axis="0 1 0"/><default class="a"><geom size=".2"/></default>', "", ' class="a"', ("j",)),
        ('<joint axis="0 1 0"/><default class="a"><joint damping="1"/></default>', ' childclass="a"', "", ()),
        ('<joint axis="0 1 0"/>', "", "", ()),  # the main class's own <joint>
        ('<default class="a"><geom size=".2"/></default>', ' childclass="a"', "", ()),  # nothing to inherit
    ],
)
def test_inherited_only_through_a_class_without_joint(
    tmp_path: Path, defaults: str, cc: str, jc: str, expected: tuple[str, ...]
) -> None:
    path = tmp_path / "m.xml"
    path.write_text(f'<mujoco model="m"><default>{defaults}</default>{BODY.format(cc=cc, jc=jc)}</mujoco>')
    assert inherited_through_jointless_class(path) == expected


def test_a_urdf_has_none(tmp_path: Path) -> None:
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="a"/></robot>')
    assert inherited_through_jointless_class(path) == ()
