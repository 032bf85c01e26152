"""An engine the user names checks every model, or the model fails with that engine's own reason."""

from __future__ import annotations

import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.diagnosis.reason import REASON_WIDTH
from koenig_check.engines.registry import installed
from koenig_check.findings import Kind
from koenig_check.testing import assert_energy_parity

ALL = ("mujoco", "pinocchio", "drake")
needs_drake = pytest.mark.skipif(not installed("drake"), reason="Drake (the optional extra [drake]) is not installed")
#: Drake 1.51 refuses talos_reduced.urdf (a fixed joint that mimics a revolute one); MuJoCo and Pinocchio load it.
REFUSED_BY_DRAKE = "talos"
DRAKE_REASON = "which has 0 DOF cannot mimic joint 'gripper_left_joint'"


@needs_drake
def test_api_fails_a_model_drake_was_asked_for_and_cannot_check() -> None:
    check = koenig_check.compare(REFUSED_BY_DRAKE, n_poses=1, formulas=["exact"], engines=ALL)
    assert all(p.agrees for p in check.agreements)  # MuJoCo and Pinocchio agree: the failure is the unmade check
    assert not check.ok
    unable = [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
    assert [f.engine for f in unable] == ["drake"] and DRAKE_REASON in unable[0].summary  # Drake's reason, whole
    # the one-line reason says so first and fits its line (the verdict table's row holds Drake's reason whole)
    reason = check.reason()
    assert reason.startswith("talos: Drake asked for (--engines) but it could not check the model: Drake cannot")
    assert len(reason) <= REASON_WIDTH


@needs_drake
def test_cli_row_and_exit_status_say_the_asked_engine_did_not_check(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["compare", REFUSED_BY_DRAKE, "--poses", "1", "--formulas", "exact", "--engines", "mujoco,pinocchio,drake"]
    assert main(argv) == 1
    out, err = capsys.readouterr()
    row = " ".join(out.split("\n\n")[0].split())  # the model's row, its wrapped lines joined
    assert "Drake asked for (--engines) but it could not check the model" in row and DRAKE_REASON in row
    line, *rest = err.splitlines()  # one message: a line within 200 characters saying which engine could not check,
    assert line.startswith("koenig-check: talos: Drake asked for (--engines)") and len(line) <= 200
    assert all(x.startswith("    ") for x in rest) and DRAKE_REASON in " ".join(" ".join(rest).split())  # then Drake's


@needs_drake
def test_helper_fails_with_drakes_reason() -> None:
    with pytest.raises(AssertionError, match=r"Drake asked for \(--engines\) but it could not check the model:\s"):
        assert_energy_parity(REFUSED_BY_DRAKE, n_poses=1, engines=ALL)


@needs_drake
def test_drake_consulted_by_default_only_where_the_engines_disagree() -> None:
    check = koenig_check.compare(REFUSED_BY_DRAKE, n_poses=1, formulas=["exact"])
    assert check.ok  # MuJoCo and Pinocchio agree: Drake is not needed, and its refusal is no failure
    assert not [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]


@needs_drake
def test_dynamics_fails_when_the_asked_engine_cannot_check() -> None:
    result = koenig_check.dynamics(REFUSED_BY_DRAKE, n_poses=1, formulas=["exact"], engines=ALL)
    assert not result.ok and DRAKE_REASON in result.reason()


@pytest.mark.parametrize(
    ("engines", "left"),
    [
        (None, ()),  # the default names no engine: nothing to say on each run
        (("all",), ()),  # every installed engine asked for (one that does not read a format is said on the model)
        (("mujoco", "pinocchio"), ("drake", "idyntree", "newton", "pybullet")),
        (("mujoco", "pinocchio", "newton"), ("drake", "idyntree", "pybullet")),
    ],
)
def test_the_engines_not_named_are_said_once_for_the_run(engines, left) -> None:
    from koenig_check.diagnosis.policy import not_named

    assert not_named(engines) == tuple(e for e in left if installed(e))


def test_an_engine_not_named_gets_no_note_on_the_model() -> None:
    check = koenig_check.compare("gimbal.urdf", n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio"))
    assert not [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_NOT_USED]
    assert check.not_named == tuple(e for e in ("drake", "idyntree", "newton", "pybullet") if installed(e))
