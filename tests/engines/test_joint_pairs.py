"""MuJoCo's joints paired by name with an engine's (PyBullet's and iDynTree's way), and the one message of a
pairing that fails (theirs, Drake's and Newton's)."""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.joint_pairs import EngineJoint, dofs_by_kind, mismatch_message, pair_by_name, per_dof

MODEL = """<mujoco><worldbody>
  <body name="root"><freejoint name="float"/><geom size="0.1"/>
    <body name="b1"><joint name="j1" type="hinge"/><geom size="0.1"/>
      <body name="b2"><joint name="j2" type="slide"/><geom size="0.1"/>
        <body name="b3"><joint name="j3" type="hinge"/><geom size="0.1"/></body>
      </body>
    </body>
  </body>
</worldbody></mujoco>"""


def _model() -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(MODEL)


def test_joints_pair_by_name_the_free_root_with_the_base() -> None:
    m = _model()
    joints = {"j3": EngineJoint("hinge", "revolute", 3, 0), "j2": EngineJoint("slide", "prismatic", 2, 1)}
    joints["j1"] = EngineJoint("hinge", "revolute", 1, 2)
    pairing = pair_by_name(m, joints, "someengine", lambda j: 0)
    assert pairing.failure("f.urdf", "Some") is None
    assert [(p.name, p.kind, p.link, p.dof) for p in pairing.pairs] == [
        ("float", "free", 0, -1),
        ("j1", "hinge", 1, 2),
        ("j2", "slide", 2, 1),
        ("j3", "hinge", 3, 0),
    ]
    assert [(p.qadr, p.vadr) for p in pairing.pairs] == [(0, 0), (7, 6), (8, 7), (9, 8)]


def test_what_does_not_pair_is_said_in_one_message() -> None:
    m = _model()
    joints = {"j1": EngineJoint("slide", "prismatic", 1, 0), "j3": EngineJoint("hinge", "revolute", 3, 1)}
    joints["extra"] = EngineJoint("hinge", "revolute", 4, 2)
    pairing = pair_by_name(m, joints, "someengine", lambda j: None)  # no floating base: the free joint by name
    assert pairing.only_mujoco == ["float", "j2"] and pairing.only_engine == ["extra"]
    assert pairing.mismatch == ["j1: mujoco hinge vs someengine prismatic"]
    assert pairing.failure("f.urdf", "Some") == (
        "f.urdf: joints do not match between MuJoCo and Some (only in MuJoCo: float, j2; only in Some: extra; "
        "incompatible types: j1: mujoco hinge vs someengine prismatic)"
    )


def test_an_extra_part_alone_fails_the_pairing() -> None:
    assert mismatch_message("f", "Some", [], [], []) is None
    said = mismatch_message("f", "Some", [], [], [], "Some has 3 dofs, MuJoCo 2")
    assert said == "f: joints do not match between MuJoCo and Some (Some has 3 dofs, MuJoCo 2)"


def test_dofs_by_kind_and_per_dof_cover_each_joints_canonical_dofs() -> None:
    m = _model()
    joints = {"j1": EngineJoint("hinge", "revolute", 1, 0), "j2": EngineJoint("slide", "prismatic", 2, 1)}
    joints["j3"] = EngineJoint("hinge", "revolute", 3, 2)
    pairs = pair_by_name(m, joints, "someengine", lambda j: 0).pairs
    words = {"free": "floating", "hinge": "revolute", "slide": "prismatic"}
    groups = dofs_by_kind(pairs, lambda p: words[p.kind])
    assert {k: list(v) for k, v in groups.items()} == {
        "floating": [0, 1, 2, 3, 4, 5],
        "revolute": [6, 8],
        "prismatic": [7],
    }
    values = per_dof(pairs, m.nv, lambda p: 10.0 + p.dof)
    assert np.array_equal(values, [0, 0, 0, 0, 0, 0, 10.0, 11.0, 12.0])
