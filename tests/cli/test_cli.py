from __future__ import annotations

import subprocess
import sys

import pytest

from koenig_check.cli import main


def test_selfcheck_prints_every_formula(capsys: pytest.CaptureFixture[str]) -> None:
    from koenig_check.formulas import FORMULAS

    assert main(["selfcheck"]) == 0
    out = capsys.readouterr().out
    for name in FORMULAS:
        assert name in out


def test_console_script_help_has_an_example() -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "selfcheck", "--help"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 0
    assert "example:\n  koenig-check selfcheck" in proc.stdout


def test_no_command_prints_help_and_fails(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 2
    assert "COMMAND" in capsys.readouterr().out
