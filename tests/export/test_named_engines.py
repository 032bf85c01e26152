"""An engine the user names in an export proof is compared, or the proof says it was not, and fails.

hfield.xml is a model Pinocchio 4.1 cannot parse (a height field).  By default a proof compares every engine that
loads both files, and an engine that cannot is listed as not compared; an engine named with ``--engines``
(``engines=``) is a check the user asked for: when it cannot compare the files, the proof is not made, and
``koenig-check export`` exits 1 saying which engine and why (it exited 0, "equivalent", without it).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.export.proof import prove

HFIELD = Path(__file__).resolve().parents[1] / "engines" / "models" / "hfield.xml"
PINOCCHIO_REASON = "hfields are not supported yet"


@pytest.mark.parametrize(
    ("engines", "status"),
    [(None, 0), ("mujoco,pinocchio", 1), ("pinocchio,mujoco", 1)],
)
def test_check_only_fails_when_a_named_engine_cannot_compare(
    engines: str | None, status: int, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(HFIELD.parent)  # the files named relative to the folder: lines must name them so
    argv = ["export", "--check-only", HFIELD.name, HFIELD.name, "--poses", "2"]
    assert main(argv + (["--engines", engines] if engines else [])) == status
    out = " ".join(capsys.readouterr().out.split())  # folded lines joined
    if status:
        assert "not equivalent" in out
        assert "Pinocchio asked for (--engines) but not compared: cannot load the export" in out
        assert out.count(PINOCCHIO_REASON) == 1  # said once, under "not equivalent", not also as "not compared"
        assert str(HFIELD.parent) not in out  # the file as the user named it, not resolved
    else:
        assert "equivalent: max relative difference 0" in out


def test_the_proof_names_the_engine_asked_for_and_not_compared() -> None:
    named = prove(HFIELD, HFIELD, poses=2, engines=("mujoco", "pinocchio"))
    assert not named.equivalent
    (line,) = named.unmade()
    assert line.startswith("Pinocchio asked for (--engines) but not compared: ") and PINOCCHIO_REASON in line
    assert named.reasons()[0] == line
    default = prove(HFIELD, HFIELD, poses=2, engines=None)
    assert default.equivalent and default.unmade() == []
    assert any(s.startswith("pinocchio: ") and PINOCCHIO_REASON in s for s in default.skipped())
