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
    difference, tests/diagnosis/test_import_parity.py); asking for Drake too must not turn it into a departure."""
    path = str(CAUSES / "posed_root.xml")
    assert main(["parity", path]) == 0
    assert main(["parity", path, "--engines", ALL]) == 0
    out, err = capsys.readouterr()
    assert "departs" not in out and err == ""
