"""`koenig-check dynamics --engines ...`: an engine the user names checks the model, or the run says so and exits 1.

talos is a model Drake 1.51 cannot load (a joint of 0 dof with a mimic); MuJoCo and Pinocchio agree on it.  Named
with ``--engines mujoco,pinocchio,drake``, Drake's check is not made: the command exits 1 with Drake's own reason
(the exit status reads the checks left unmade as well as the failed comparisons).
"""

from __future__ import annotations

import pytest

from koenig_check.cli import main

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed")

ARGS = ["--poses", "1", "--formulas", "exact"]
DRAKE_REASON = "which has 0 DOF cannot mimic joint"


@pytest.mark.parametrize(
    ("model", "engines", "status"),
    [
        ("talos", "mujoco,pinocchio,drake", 1),
        ("talos", "mujoco,pinocchio", 0),
        ("gimbal.xml", "mujoco,pinocchio,drake", 0),
    ],
)
def test_exit_status_says_whether_every_named_engine_checked(
    model: str, engines: str, status: int, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["dynamics", model, "--engines", engines, *ARGS]) == status
    out, err = capsys.readouterr()
    if status:  # one line (cut to its width) saying which engine did not check; Drake's reason whole above it
        line, *rest = err.splitlines()  # one message: its first line, then the rest indented
        assert line.startswith(f"koenig-check: {model}: ") and "Drake asked for (--engines)" in line
        assert all(x.startswith("    ") for x in rest) and len(line) <= 200
        assert "Drake cannot load the file" in err and DRAKE_REASON in " ".join(out.split())
    else:
        assert err == ""
