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
        return Finding(
            Kind.ANCHOR, "drake", f"joint {joint}", "Drake turns the joint about another point", {}, tag="joint"
        )

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


def _rigid_energies(path: Path | str, n: int = 8) -> dict[str, np.ndarray]:
    """Each engine's own rigid-body energy on the same random states (Drake attached)."""
    model = load_model(path, engines=NAMED)
    model.attach("drake")
    poses = random_pose_range(model.mujoco.model, 0, n, 0, 1.0)
    return {name: e.kinetic_energy(poses.qpos, poses.qvel).rigid for name, e in model.engines.items()}


def test_slides_before_a_hinge_are_read_alike_and_drake_checks_the_model() -> None:
    """dm_control's cheetah in small: Drake puts the torso's pos on its hinge, after two slides; translations
    commute, so its robot is the file's (its energies equal MuJoCo's and Pinocchio's): no parser limit."""
    path = MODEL.parent / "slides_then_hinge.xml"
    energy = _rigid_energies(path)
    for name in ("pinocchio", "drake"):
        np.testing.assert_allclose(energy[name], energy["mujoco"], rtol=1e-12)
    check = koenig_check.compare(path, n_poses=8, engines=NAMED)
    findings = check.comparisons[0].findings
    assert not [f for f in findings if f.kind in (Kind.ENGINE_UNABLE, Kind.ANCHOR, Kind.VERDICT)]
    assert check.ok, check.reasons()


def _bolt() -> Path:
    from koenig_check.sources.catalogue import resolve_model

    try:
        return resolve_model("bolt").path
    except Exception as err:  # example-robot-data comes with Pinocchio; skip where it does not
        pytest.skip(f"bolt (example-robot-data) not found: {err}")


def test_bolt_massless_feet_drake_replaces_make_it_unable_not_a_voter() -> None:
    """bolt's FL_FOOT and FR_FOOT: mass 0 and a rotational inertia.  Drake's URDF parser cannot re-express that
    about a COM and builds a 1 kg link instead: another robot, so Drake casts no vote ("all three engines differ,
    Drake departs" before); named, it could not check the model; the pair's cause (fusestatic) is the reason."""
    import xml.etree.ElementTree as ET

    path = _bolt()
    written = {
        link.get("name"): float(link.find("inertial/mass").get("value"))
        for link in ET.parse(path).getroot().findall("link")
        if link.find("inertial/mass") is not None
    }
    assert written["FL_FOOT"] == written["FR_FOOT"] == 0.0
    children = {j.find("child").get("link") for j in ET.parse(path).getroot().findall("joint")}
    moving = sum(m for link, m in written.items() if link in children)  # the root link is welded: it does not move
    model = load_model(path, engines=NAMED)
    model.attach("drake")
    q0, zero = np.asarray(model.mujoco.model.qpos0)[None], np.zeros((1, model.mujoco.nv))
    mass = {n: float(np.sum(e.segment_states(q0, zero).mass)) for n, e in model.engines.items()}
    assert mass["pinocchio"] == pytest.approx(moving, rel=1e-12)  # the file's masses
    assert mass["drake"] - mass["pinocchio"] == pytest.approx(2.0, rel=1e-9)  # 1 kg per massless foot
    for engines in (None, NAMED):
        check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=engines)
        findings = check.comparisons[0].findings
        assert not [f for f in findings if f.kind is Kind.VERDICT] and not check.ok
        reason = check.reason()
        # one root cause, on both massless feet: MuJoCo's fusestatic (Drake's replaced inertias are no cause)
        assert reason.startswith(f"{path.name}: root cause: links FL_FOOT, FR_FOOT: fusestatic dropped the rotational")
        assert "more root cause" not in reason
        assert "departs" not in reason and "engines differ" not in reason
        unable = [f.summary for f in findings if f.kind is Kind.ENGINE_UNABLE]
        assert unable == (
            []
            if engines is None
            else [
                "Drake cannot check this model: its URDF parser replaces inertias it judges unphysical "
                "(links: FL_FOOT, FR_FOOT)"
            ]
        )


#: Files on which Drake's parser does not read what the model uses while MuJoCo and Pinocchio disagree: Drake's
#: reading makes no majority (no verdict), whether it is consulted or named.
LIMITED_AND_DISAGREEING = [
    ("frame_geom.xml", MODEL.parents[1] / "causes" / "frame_geom.xml", {}),
    ("unbalanced_inertia.urdf", MODEL.parents[1] / "tiebreak" / "unbalanced_inertia.urdf", {"repair_inertia": True}),
]


@pytest.mark.parametrize("engines", [None, NAMED], ids=["consulted", "named"])
@pytest.mark.parametrize(
    ("name", "path", "options"), LIMITED_AND_DISAGREEING, ids=[c[0] for c in LIMITED_AND_DISAGREEING]
)
def test_an_engine_that_cannot_check_a_model_makes_no_verdict(name, path, options, engines) -> None:
    model = load_model(path, engines=NAMED, **options)
    model.attach("drake")
    poses = random_pose_range(model.mujoco.model, 0, 4, 0, 1.0)
    diagnosis = diagnose(model, qpos=poses.qpos, qvel=poses.qvel)
    limited = [f for f in diagnosis.findings if f.engine == "drake" and f.kind is not Kind.ENGINE_UNABLE]
    assert limited and not diagnosis.verdicts  # Drake read it (its findings) and did not vote
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=engines, **options)
    findings = check.comparisons[0].findings
    assert not [f for f in findings if f.kind is Kind.VERDICT] and not check.ok
    assert [f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE] == ([] if engines is None else ["drake"])
    assert "departs" not in check.reason() and "engines differ" not in check.reason()
