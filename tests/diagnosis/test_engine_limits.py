"""Drake departing through a known limit of its MJCF parser: the check not made when named, no verdict when consulted.

The model is a body with two hinges placed off the body frame: Drake 1.51's MJCF parser drops the body's pos for
the first one (Drake turns it about another point), while MuJoCo and Pinocchio read the file alike.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.diagnosis.diagnose import diagnose
from koenig_check.engines import load_model
from koenig_check.findings import Kind
from koenig_check.run.poses import random_pose_range

pytest.importorskip("pydrake")

MODEL = Path(__file__).resolve().parents[1] / "models" / "parser_limits" / "joints_with_pos_in_one_body.xml"
NAMED = ["mujoco", "pinocchio", "drake"]


def test_mujoco_and_pinocchio_agree_and_drake_gets_another_robot() -> None:
    """The premise, from the engines' own energies: Drake's energy differs, MuJoCo's and Pinocchio's do not."""
    model = load_model(MODEL, engines=NAMED)
    model.attach("drake")
    poses = random_pose_range(model.mujoco.model, 0, 8, 0, 1.0)
    energy = {name: e.kinetic_energy(poses.qpos, poses.qvel).rigid for name, e in model.engines.items()}
    np.testing.assert_allclose(energy["pinocchio"], energy["mujoco"], rtol=1e-12)
    assert np.max(np.abs(energy["drake"] - energy["mujoco"]) / energy["mujoco"]) > 1e-3


def test_drake_named_fails_the_model_saying_it_could_not_check_it() -> None:
    check = koenig_check.compare(MODEL, n_poses=8, engines=NAMED)
    findings = check.comparisons[0].findings
    assert not check.ok and not [f for f in findings if f.kind is Kind.VERDICT]
    (unable,) = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.engine == "drake" and unable.segments == ("arm_x",)
    assert unable.summary.startswith("Drake cannot check this model: its MJCF parser drops the pos of multi-joint")
    (reason,) = check.reasons()
    assert "Drake cannot check this model" in reason and "departs" not in reason and "root cause" not in reason


def test_drake_consulted_as_tie_breaker_never_fails_an_agreeing_model() -> None:
    model = load_model(MODEL)
    poses = random_pose_range(model.mujoco.model, 0, 8, 0, 1.0)
    diagnosis = diagnose(model, disagree=True, qpos=poses.qpos, qvel=poses.qvel)  # Drake consulted
    assert "drake" in diagnosis.engines
    assert not [f for f in diagnosis.findings if f.kind in (Kind.VERDICT, Kind.ENGINE_UNABLE)]
    assert koenig_check.compare(MODEL, n_poses=8).ok


#: Files of the corpus Drake 1.51's MJCF parser reads as another robot, with what it does not read.
LIMITED = [
    (MODEL, "drops the pos of multi-joint bodies (joints: arm_x)"),
    (
        MODEL.parents[1] / "causes" / "class_joint_pos_explicit.xml",
        "drops the pos of multi-joint bodies (joints: vertebra_1_extend)",
    ),
    (MODEL.parents[2] / "engines" / "models" / "hinge_armature.xml", "ignores armature (joints: spin)"),
]


@pytest.mark.parametrize(("path", "limit"), LIMITED, ids=lambda x: getattr(x, "name", "limit"))
def test_a_parser_limit_is_said_exactly_when_drake_is_named(path: Path, limit: str) -> None:
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=NAMED)
    assert not check.ok
    (reason,) = check.reasons()
    assert reason == (
        f"{path.name}: Drake cannot check this model: its MJCF parser {limit}; "
        "without Drake: --engines mujoco,pinocchio"
    )
    assert len(f"koenig-check: {reason}") <= 200


def test_drake_reading_more_than_the_others_still_departs() -> None:
    """A URDF's rotor inertia, which Drake reads and MuJoCo's armature does not match, is not a parser limit."""
    path = MODEL.parents[1] / "tiebreak" / "rotor_inertia.urdf"
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=NAMED)
    assert check.reason().startswith("rotor_inertia.urdf: Drake departs")


def test_an_anchor_of_a_one_joint_body_is_no_parser_limit() -> None:
    """Only joints of a body with several joints are misplaced by the parser; elsewhere an anchor is a departure."""
    from koenig_check.diagnosis.engine_limits import parser_limit
    from koenig_check.findings import Finding

    def anchor(joint: str) -> Finding:
        return Finding(Kind.ANCHOR, "drake", f"joint {joint}", "Drake turns the joint about another point", {})

    several = load_model(MODEL).mujoco.model
    assert parser_limit(anchor("arm_y"), several) is not None
    assert parser_limit(anchor("base_z"), several) is None  # the only joint of its body


def test_parity_with_drake_named_fails_the_same_way_and_shows_drake_after_the_table(
    capsys: pytest.CaptureFixture[str],
) -> None:
    from koenig_check.cli import main

    assert main(["parity", str(MODEL), "--engines", "mujoco,pinocchio,drake"]) == 1
    out, err = capsys.readouterr()
    assert err.startswith(f"koenig-check: {MODEL.name}: Drake cannot check this model: its MJCF parser")
    assert out.startswith("Import parity of ")  # the title first; Drake's part (its parser's words) under it
    assert out.index("The third engine (Drake)") < out.index("drake: joint arm_x: Drake turns the joint")
