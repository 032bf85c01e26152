"""``koenig-check parity``: its exit status with an engine the user named (0: the same robot, 1: not, or unchecked)."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.engines.registry import installed

needs_drake = pytest.mark.skipif(not installed("drake"), reason="Drake (the optional extra [drake]) is not installed")
ALL = "mujoco,pinocchio,drake"
CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"
#: Drake 1.51's own reason for refusing talos_reduced.urdf, which MuJoCo and Pinocchio load alike.
DRAKE_REASON = "Joint 'gripper_left_inner_double_joint' which has 0 DOF cannot mimic joint 'gripper_left_joint'"


@needs_drake
def test_parity_fails_when_the_engine_asked_for_cannot_check(capsys: pytest.CaptureFixture[str]) -> None:
    """MuJoCo and Pinocchio import talos alike, but the check asked for (with Drake) was not made: exit 1."""
    assert main(["parity", "talos"]) == 0
    capsys.readouterr()
    assert main(["parity", "talos", "--engines", ALL]) == 1
    out, err = capsys.readouterr()
    assert "verdict: no import difference" in out  # the two engines' table is clean: the failure is Drake's
    assert len(err.splitlines()) == 1 and "Drake asked for (--engines) but it could not check the model" in err
    assert len(err.rstrip("\n")) <= 200
    assert " ".join(out.split()).count(DRAKE_REASON) == 1  # Drake's reason whole, once, in its part (folded)


@needs_drake
def test_parity_with_drake_passes_a_root_pose_pinocchio_drops(capsys: pytest.CaptureFixture[str]) -> None:
    """posed_root.xml: Pinocchio drops the pose of a jointless root body, a constant world transform (no import
    difference, tests/diagnosis/test_import_parity.py); asking for Drake too must not turn it into a departure.
    Gravity sees it: both runs exit 1 on the gravity verdict alone, naming the catalogued cause."""
    path = str(CAUSES / "posed_root.xml")
    assert main(["parity", path]) == 1  # gravity sees the dropped pose (issue 27): the only disagreement
    assert main(["parity", path, "--engines", ALL]) == 1
    out, err = capsys.readouterr()
    assert "departs" not in out  # no kinetic departure, with or without Drake
    lines = err.splitlines()
    assert len(lines) == 2 and all("gravity differs" in x and "[pinocchio.mjcf.welded-root-pose]" in x for x in lines)


TESTS = Path(__file__).resolve().parents[1]
#: Files on which ``parity`` and ``compare`` with Drake named must reach the same verdict, and its exit status:
#: Drake's MJCF parser drops a multi-joint body's pos / ignores armature (ENGINE_UNABLE in both: exit 1); Drake
#: reads a URDF rotor inertia MuJoCo has no armature for (a departure in motion only: the mass, COM and inertia
#: at qpos0 agree; exit 1); and a file all three engines read alike (exit 0).
SAME_VERDICT = {
    "class_joint_pos_explicit.xml": (TESTS / "models" / "causes" / "class_joint_pos_explicit.xml", 1),
    "hinge_armature.xml": (TESTS / "engines" / "models" / "hinge_armature.xml", 1),
    "rotor_inertia.urdf": (TESTS / "models" / "tiebreak" / "rotor_inertia.urdf", 1),
    "hinge_ref.xml": (TESTS / "models" / "tiebreak" / "hinge_ref.xml", 0),
}


def _verdicts(findings: list) -> set[tuple[str, str, str]]:
    from koenig_check.findings import Kind

    lead = (Kind.VERDICT, Kind.ENGINE_UNABLE)
    return {(f.kind.value, f.engine, f.element) for f in findings if f.kind in lead}


@needs_drake
@pytest.mark.parametrize("name", list(SAME_VERDICT))
def test_parity_and_compare_reach_the_same_verdict_with_drake_named(
    name: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """The same file and engines: the same exit status and the same one-line reason in both commands."""
    path, expected = SAME_VERDICT[name]
    assert main(["parity", str(path), "--engines", ALL]) == expected
    parity_out, parity_err = capsys.readouterr()
    assert main(["compare", str(path), "--engines", ALL, "--quiet"]) == expected
    _, compare_err = capsys.readouterr()
    assert parity_err == compare_err  # one line each (the reason), or nothing for a model all three agree on
    if expected == 0:
        assert "departs" not in parity_out and parity_err == ""


@needs_drake
@pytest.mark.parametrize("name", list(SAME_VERDICT))
def test_parity_verdicts_are_compare_verdicts(name: str) -> None:
    """The verdicts as data: what ``parity`` finds on its default states is what ``compare`` finds on its poses."""
    from koenig_check.api import compare_model
    from koenig_check.cli.parity import parity_diagnosis
    from koenig_check.engines import load_model
    from koenig_check.engines.load_options import LoadOptions

    path, _ = SAME_VERDICT[name]
    options = LoadOptions(engines=("mujoco", "pinocchio", "drake"))
    model = load_model(str(path), options)
    model.attach("drake")
    diagnosis = parity_diagnosis(model, rtol=1e-9)
    compared = compare_model(str(path), load_options=options)
    assert _verdicts(diagnosis.findings) == _verdicts(compared.findings)


@needs_drake
def test_parity_shows_a_departure_only_the_motion_shows(capsys: pytest.CaptureFixture[str]) -> None:
    """rotor_inertia.urdf: Drake reads the rotor inertia (4.5 kg m² reflected on joint spin) that MuJoCo and
    Pinocchio have no armature for. At qpos0 the mass properties agree; on the states, Drake's armature energy
    departs: the third engine's part names it, and the reason too."""
    path, _ = SAME_VERDICT["rotor_inertia.urdf"]
    assert main(["parity", str(path), "--engines", ALL, "--poses", "3", "--seed", "7"]) == 1
    out, err = capsys.readouterr()
    third = out.split("The third engine (Drake)")[1]
    assert "three engines: drake: armature energy: Drake departs (MuJoCo and Pinocchio agree)" in third
    assert "actuators of joints spin" in third
    assert err.startswith("koenig-check: rotor_inertia.urdf: Drake departs")


def test_parity_refuses_a_negative_seed_before_any_work(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_:
        main(["parity", "no_such_file.xml", "--seed", "-1"])
    assert exit_.value.code == 2
    assert "--seed must be >= 0" in capsys.readouterr().err
