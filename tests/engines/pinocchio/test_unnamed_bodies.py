"""Unnamed joints of unnamed bodies are paired with Pinocchio's: it names such a body after its parent + "Bis".

pybullet_data's mjcf/capsule.xml, cylinder.xml and hello_mjcf.xml (one unnamed body with ``<joint type="free"/>``)
were refused, "joints only in MuJoCo (body1_free); joints only in Pinocchio (BisJoint_0)", though both engines
load them.  The agreement is checked on the engines' own mass matrices (:mod:`independent_energy`) and the
names against Pinocchio's own model.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from independent_energy import engines_agree
from koenig_check.engines import load_model
from koenig_check.engines.canonical import mujoco_joint_names

BALL = '<geom type="sphere" size="0.1" mass="1" pos="0.1 0.2 0.3"/>'
#: Bodies without names, and the joint names Pinocchio's MJCF parser gives (read from Pinocchio below).
CASES = {
    "joint type=free": (f'<body pos="0 0 1"><joint type="free"/>{BALL}</body>', ["BisJoint_0"]),
    "freejoint": (f'<body pos="0 0 1"><freejoint/>{BALL}</body>', ["Bis_free"]),
    "chain, two joints in one body": (
        f'<body pos="0 0 0.5"><joint type="hinge" axis="0 1 0"/>{BALL}<body pos="0 0 1">'
        f'<joint type="hinge" axis="1 0 0"/><joint type="slide" axis="0 0 1"/>{BALL}</body></body>',
        ["BisJoint_0", "Composite_BisBisJoint_0"],
    ),
    "unnamed in named": (
        f'<body name="arm"><joint type="hinge" axis="0 1 0"/>{BALL}<body pos="0 0 1"><joint type="hinge"/>{BALL}'
        "</body></body>",
        ["armJoint_0", "armBisJoint_0"],
    ),
}


def _written(tmp_path: Path, construct: str) -> Path:
    path = tmp_path / "unnamed.xml"
    path.write_text(f"<mujoco><worldbody>{CASES[construct][0]}</worldbody></mujoco>")
    return path


@pytest.mark.parametrize("construct", list(CASES))
def test_unnamed_bodies_are_paired_and_agree(tmp_path: Path, construct: str) -> None:
    path = _written(tmp_path, construct)
    model = pin.buildModelFromMJCF(str(path))
    assert list(model.names)[1:] == CASES[construct][1]  # Pinocchio's own names
    canonical = mujoco_joint_names(mujoco.MjModel.from_xml_path(str(path)))
    composite = [n[len("Composite_") :] for n in CASES[construct][1] if n.startswith("Composite_")]
    assert set(composite) <= set(canonical)  # a composite is known by its first joint
    pair = load_model(path)
    assert engines_agree(pair)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert check.ok, check.reason()
