"""The coordinate counts of MuJoCo's joint types (``canonical.joint_sizes``) against MuJoCo's own addresses."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from all_joints import ALL_JOINTS_MJCF

from koenig_check.engines.canonical import joint_sizes


def _model(model_file: str) -> mujoco.MjModel:
    if model_file == "all_joints":
        return mujoco.MjModel.from_xml_string(ALL_JOINTS_MJCF)
    dm_control = pytest.importorskip("dm_control")
    return mujoco.MjModel.from_xml_path(str(Path(dm_control.__file__).parent / "suite" / model_file))


@pytest.mark.parametrize("model_file", ["all_joints", "humanoid.xml", "swimmer.xml"])
def test_joint_sizes_are_mujocos_address_steps(model_file: str) -> None:  # all_joints: free, ball, hinge, slide
    """Each joint's sizes are the steps of MuJoCo's qpos and dof addresses to the next joint (or the end)."""
    model = _model(model_file)
    q_steps = np.diff([*model.jnt_qposadr, model.nq])
    v_steps = np.diff([*model.jnt_dofadr, model.nv])
    assert [joint_sizes(t) for t in model.jnt_type] == list(zip(q_steps.tolist(), v_steps.tolist(), strict=True))
