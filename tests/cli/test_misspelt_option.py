"""A misspelt option gets the sub-command's usage and the closest option, exit 2."""

from __future__ import annotations

import pytest

from koenig_check.cli.main import main


@pytest.mark.parametrize(
    ("argv", "closest"),
    [
        (["compare", "x.xml", "--floting"], "--floating"),
        (["parity", "x.xml", "--rtl", "1e-6"], "--rtol"),
        (["dynamics", "x.xml", "--repair-inertias"], "--repair-inertia"),
        (["export", "x.xml", "--to", "urdf", "--out", "y.urdf", "--sede", "3"], "--seed"),
        (["compare", "x.xml", "--report", "rep"], "--out"),  # by spelling --records, which means something else
        (["compare", "x.xml", "--report-dir", "rep"], "--out"),
    ],
)
def test_closest_option(argv, closest, capsys):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(f"usage: koenig-check {argv[0]} [options]"), err
    assert "unrecognized argument" in err and f"did you mean {closest}?" in err


def test_no_suggestion_for_nothing_close(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["compare", "x.xml", "--zzzzzz"])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert "unrecognized argument --zzzzzz" in err and "did you mean" not in err


@pytest.mark.parametrize(("word", "closest"), [("compar", "compare"), ("parit", "parity"), ("dynamic", "dynamics")])
def test_closest_command(word, closest, capsys):
    with pytest.raises(SystemExit) as stop:
        main([word, "ur5"])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert f"invalid choice: '{word}'; did you mean '{closest}'?" in err and len(err.splitlines()) == 2


def test_no_command_suggestion_for_nothing_close(capsys):
    with pytest.raises(SystemExit):
        main(["zzzz", "ur5"])
    assert "did you mean" not in capsys.readouterr().err


@pytest.mark.parametrize(("engines", "whole"), [("drake", "mujoco,pinocchio,drake"), ("pinocchio", "mujoco,pinocchio")])
def test_engines_without_the_required_ones_says_what_to_write(engines, whole, capsys):
    with pytest.raises(SystemExit) as stop:
        main(["compare", "ur5", "--engines", engines])
    assert stop.value.code == 2
    assert f"write '{whole}'" in capsys.readouterr().err
