"""MJCF model composition: ``<attach>`` of a ``<model>`` asset, which Pinocchio's MJCF parser does not read (issue 28,
item 2; MuJoCo's own ``test/xml/testdata/parent.xml``).  A disagreement with its root cause, not an error."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.causes import cause, fixture_path
from koenig_check.cli import main
from koenig_check.engines.parser_traps import file_causes

FIXTURE = fixture_path(cause("pinocchio.mjcf.attach"))


def test_the_engines_read_the_fixture_differently() -> None:
    """MuJoCo builds the attached arm and its hinge; Pinocchio the slide alone (each engine's own model)."""
    mj = mujoco.MjModel.from_xml_path(str(FIXTURE))
    assert [mj.joint(j).name for j in range(mj.njnt)] == ["slide", "other_hinge"]
    assert mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_BODY, "other_arm") > 0
    pm = pin.buildModelFromMJCF(str(FIXTURE))
    assert pm.nv == 1 and list(pm.names)[1:] == ["slide"]


def test_the_cause_names_the_model_and_the_bodies() -> None:
    mj = mujoco.MjModel.from_xml_path(str(FIXTURE))
    (found,) = [f for f in file_causes(FIXTURE, mj) if f.cause == "pinocchio.mjcf.attach"]
    assert found.element == "attach child (bodies other_arm)" and found.engine == "pinocchio"
    assert found.values["bodies"] == ("other_arm",) and found.values["joints"] == ("other_hinge",)
    assert found.values["in"] == "body base" and found.values["file"] == "attach_child.xml"
    assert found.root_cause and found.affects_energy and found.segments == ("other_hinge",)
    assert "other_arm" in found.summary


def test_no_attach_no_cause(tmp_path: Path) -> None:
    """The control: the composed model written out by MuJoCo (no <attach>) has no such cause."""
    spec = mujoco.MjSpec.from_file(str(FIXTURE))
    spec.compile()
    written = tmp_path / "composed.xml"
    written.write_text(spec.to_xml())
    mj = mujoco.MjModel.from_xml_path(str(written))
    assert not [f for f in file_causes(written, mj) if f.cause == "pinocchio.mjcf.attach"]


def test_compare_says_disagree_with_the_root_cause(capsys: pytest.CaptureFixture[str]) -> None:
    check = koenig_check.compare(FIXTURE, n_poses=2)
    assert not check.ok and check.disagrees("attach.xml")
    assert {f.cause for f in check.failure_causes["attach.xml"]} == {"pinocchio.mjcf.attach"}
    reason = check.reason()
    assert "<attach> not read by Pinocchio's MJCF parser" in reason and "other_arm" in reason
    assert main(["compare", str(FIXTURE), "--poses", "2"]) == 1
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("attach.xml"))
    assert row.split()[1] == "DISAGREE"


def test_parity_prints_its_report_not_an_error(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["parity", str(FIXTURE)]) == 1
    captured = capsys.readouterr()
    assert captured.out.startswith("Import parity of") and "root causes:" in captured.out
    assert "attach child" in captured.out and "joints only in MuJoCo: other_hinge" in captured.out
    assert "koenig-check: error:" not in captured.err
    first = captured.err.splitlines()[0]
    assert first.startswith("koenig-check: attach.xml: ") and "<attach>" in first and len(first) <= 200


CHILD = """<mujoco model="child"><worldbody>
  <body name="body1"><freejoint/><geom type="sphere" size="0.1"/>
    <body name="body2" pos="0 0 1"><joint type="hinge"/><geom type="sphere" size="0.1"/></body>
  </body></worldbody></mujoco>"""
PARENT = """<mujoco model="parent"><asset><model name="other" file="child.xml"/></asset><worldbody>
  <body name="base"><joint name="slide" type="slide"/><geom type="box" size="0.1 0.1 0.1"/></body>
  <frame name="f" pos="1 0 0"><attach model="other" body="body1" prefix="other2"/></frame>
</worldbody></mujoco>"""


def test_an_attach_in_a_frame_with_unnamed_joints_names_what_the_engines_lack(tmp_path: Path) -> None:
    """As MuJoCo's parent.xml: free bodies attached in a frame; the cause's joints are those the pairing misses."""
    from koenig_check.engines import load_model
    from koenig_check.exceptions import JointMismatch

    (tmp_path / "child.xml").write_text(CHILD)
    path = tmp_path / "parent.xml"
    path.write_text(PARENT)
    with pytest.raises(JointMismatch) as info:
        load_model(path)
    (found,) = [f for f in info.value.causes if f.cause == "pinocchio.mjcf.attach"]
    assert found.values["in"] == "frame f" and found.values["bodies"] == ("other2body1", "other2body2")
    assert list(found.values["joints"]) == info.value.only_in_mujoco == ["other2body1_free", "other2body2Joint_0"]
