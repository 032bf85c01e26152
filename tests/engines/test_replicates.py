"""``<replicate>``: the copies MuJoCo makes and Pinocchio's MJCF parser does not read are named as the root cause.

The engines' own readings are checked first (MuJoCo's joints ``j20``, ``j21``, ``j22``; Pinocchio's none of them,
or its refusal when the only root body is replicated); the portable MJCF export loads the same robot in both.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.engines import load_model
from koenig_check.exceptions import KoenigCheckError
from koenig_check.findings import Kind

ARM = (
    '<body name="a"><joint name="j1" axis="0 1 0"/><geom type="box" size="0.1 0.2 0.3" pos="0.3 0 0"/>'
    '<replicate count="3" offset="0.5 0 0"><body name="b" pos="0 0 -1"><joint name="j2" axis="1 0 0"/>'
    '<geom type="box" size="0.1 0.2 0.3" pos="0 0.2 -0.5"/></body></replicate></body>'
)
ROOT = (
    '<replicate count="2" offset="1 0 0" sep="_"><body name="b"><joint name="j2" axis="1 0 0"/>'
    '<geom type="box" size="0.1 0.2 0.3" pos="0 0.2 -0.5"/></body></replicate>'
)
#: (worldbody, the replicate's element, the joints MuJoCo makes of it, Pinocchio's joints or None: refused)
CASES = {
    "in a body": (ARM, "replicate #1 in body a", ("j20", "j21", "j22"), ["universe", "j1"]),
    "at the root": (ROOT, "replicate #1 in worldbody", ("j2_0", "j2_1"), None),
}


@pytest.mark.parametrize("where", sorted(CASES))
def test_the_replicate_is_named_with_the_joints_mujoco_makes(tmp_path: Path, where: str) -> None:
    world, element, joints, pinocchio_joints = CASES[where]
    path = tmp_path / "replicated.xml"
    path.write_text(f"<mujoco><worldbody>{world}</worldbody></mujoco>")
    mj = mujoco.MjModel.from_xml_path(str(path))
    assert set(joints) <= {mj.joint(k).name for k in range(mj.njnt)}
    if pinocchio_joints is None:
        with pytest.raises(RuntimeError, match="No such node"):
            pin.buildModelFromMJCF(str(path))
    else:
        assert list(pin.buildModelFromMJCF(str(path)).names) == pinocchio_joints
    with pytest.raises(KoenigCheckError) as info:
        load_model(path)
    (cause,) = [c for c in info.value.causes if c.cause == "pinocchio.mjcf.replicate"]
    assert (cause.kind, cause.engine, cause.element) == (Kind.IGNORED_CONSTRUCT, "pinocchio", element)
    assert cause.values["joints"] == joints and cause.segments == joints and cause.affects_energy
    line = koenig_check.compare(path, n_poses=2, formulas=["exact"]).failure_lines[path.name]
    assert f"root cause: {element}: <replicate> not read by Pinocchio's MJCF parser" in line
    portable = tmp_path / "portable.xml"  # what the hint offers: the copies written out
    assert koenig_check.export(path, to="mjcf", out=portable).equivalent
    assert koenig_check.compare(portable, n_poses=2, formulas=["exact"]).ok
