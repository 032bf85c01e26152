"""Newton's D6 joint of a body with several MJCF joints: each MuJoCo joint paired with the dof on its own axis.

brax's prismaversal_2dof_joint.xml writes a hinge before a slide in one body.  Newton 1.8 makes them one D6 joint
whose linear axes come first (``joint_axis``: the slide's, then the hinge's): pairing the joints in the file's order
fed the hinge's angle to the slide ("Newton departs" by 0.77 of the energy, with no cause).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

from koenig_check.engines.newton.loader import build
from koenig_check.engines.newton.state_map import match_joints

BODY = """<mujoco model="hinge_then_slide">
  <compiler inertiafromgeom="false"/>
  <worldbody>
    <body name="carriage">
      <joint name="{first}" type="{first_type}" axis="{first_axis}" range="-1.5 1.5"/>
      <joint name="{second}" type="{second_type}" axis="{second_axis}" range="-1.5 1.5"/>
      <inertial pos="0.3 0 0" mass="2" diaginertia="0.01 0.02 0.02"/>
    </body>
  </worldbody>
</mujoco>
"""
SWING = ("swing", "hinge", "0 1 0")
REACH = ("reach", "slide", "1 0 0")


@pytest.mark.parametrize("order", [(SWING, REACH), (REACH, SWING)], ids=["hinge-first", "slide-first"])
def test_each_joint_gets_the_d6_dof_on_its_axis(tmp_path: Path, order) -> None:
    (first, first_type, first_axis), (second, second_type, second_axis) = order
    path = tmp_path / "body.xml"
    path.write_text(BODY.format(**locals()))
    mj_model = mujoco.MjModel.from_xml_path(str(path))
    model, _ = build(path, "mjcf", floating=False)
    axes = model.joint_axis.numpy()  # Newton's own: one row per dof
    for pair in match_joints(mj_model, model, str(path), mjcf=True):
        k = mj_model.joint(pair.name).id
        assert np.allclose(axes[pair.nv], mj_model.jnt_axis[k]), pair.name
