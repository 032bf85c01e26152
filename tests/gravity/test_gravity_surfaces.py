"""The gravity verdict where users read it: compare's exit status, the report files, dynamics, the test helper."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import koenig_check
import koenig_check.causes
from koenig_check.cli import main
from koenig_check.implied_dynamics.gravity_terms import NO_COUNTERPART
from koenig_check.testing import assert_energy_parity
from koenig_check.testing.failure_text import verdict_lines

FIXTURES = Path(koenig_check.causes.__file__).parent / "fixtures"
MOON = FIXTURES / "option_gravity_moon.xml"
SAME = FIXTURES / "option_gravity_default.xml"
CAUSE = "pinocchio.mjcf.option-gravity"


def test_compare_exits_1_on_gravity_alone_and_names_the_cause(tmp_path: Path, capsys) -> None:
    assert main(["compare", str(SAME), "--poses", "4", "--quiet"]) == 0
    capsys.readouterr()
    out = tmp_path / "out"
    assert main(["compare", str(MOON), "--poses", "4", "--out", str(out)]) == 1
    printed, err = capsys.readouterr()
    assert err.count("\n") == 1 and f"[{CAUSE}]" in err  # one line, the cause by id
    assert "Gravity:" in printed and "DIFFER" in printed
    record = json.loads((out / "records.json").read_text())["gravity"]["option_gravity_moon.xml"]
    assert record["agrees"] is False and record["vectors"]["pinocchio"] == [0.0, 0.0, -9.81]
    assert [f["cause"] for f in record["findings"] if f["root_cause"]] == [CAUSE]
    assert f"[{CAUSE}]" in (out / "summary.md").read_text() and f"[{CAUSE}]" in (out / "report.html").read_text()


def test_api_and_plugin_text() -> None:
    check = koenig_check.compare(MOON, n_poses=3, formulas=["exact"])
    assert all(p.agrees for p in check.agreements) and not check.ok  # kinetic energy agrees, gravity does not
    lines = verdict_lines(check)
    assert any(CAUSE in line for line in lines)


def test_assert_energy_parity_fails_on_gravity_unless_told_not_to() -> None:
    with pytest.raises(AssertionError, match=CAUSE):
        assert_energy_parity(MOON, n_poses=3)
    assert_energy_parity(MOON, n_poses=3, gravity=False)  # the kinetic energy alone agrees
    assert_energy_parity(SAME, n_poses=3)


def test_dynamics_reports_gravity_beside_the_formulas() -> None:
    result = koenig_check.dynamics(MOON, n_poses=2, formulas=["exact"])
    assert not result.ok and CAUSE in result.reason()
    assert result.full_inverse_dynamics[0].relative > 0.1  # τ + g(q) of Pinocchio is another robot's
    same = koenig_check.dynamics(SAME, n_poses=2, formulas=["exact"])
    assert same.ok and same.full_inverse_dynamics[0].relative < 1e-12
    from koenig_check.implied_dynamics.markdown import to_markdown

    assert NO_COUNTERPART in to_markdown(same)
