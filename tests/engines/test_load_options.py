"""Every load option is accepted, from one definition, by every command and function that loads a model."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest

from koenig_check.cli import build_parser, main
from koenig_check.engines.load_options import LoadOptions

MODELS = Path(__file__).resolve().parents[2] / "models"
#: Sub-commands that load a model file.
LOADING_COMMANDS = ("compare", "parity")


def _subparser(command: str):
    parser = build_parser()
    action = next(a for a in parser._subparsers._group_actions if a.dest == "command")
    return action.choices[command]


def _option_dests(command: str) -> set[str]:
    sub = _subparser(command)
    return {a.dest for a in sub._actions if a.option_strings and a.dest != "help"}


@pytest.mark.parametrize("command", LOADING_COMMANDS)
def test_every_loading_command_has_exactly_the_load_options(command: str) -> None:
    group = next(g for g in _subparser(command)._action_groups if g.title == "how the model is loaded")
    assert {a.dest for a in group._group_actions} == set(LoadOptions.names())
    assert set(LoadOptions.names()) <= _option_dests(command)


@pytest.mark.parametrize("command", LOADING_COMMANDS)
def test_every_load_option_reaches_load_model_from_the_command_line(command: str, monkeypatch) -> None:
    import koenig_check.engines as engines

    seen: list[LoadOptions] = []

    def fake_load_model(path, options=None, **kwargs):
        seen.append(options)
        raise engines.ModelLoadError("stop here")

    monkeypatch.setattr(engines, "load_model", fake_load_model)
    twin = str(MODELS / "gimbal.urdf")
    argv = [command, str(MODELS / "gimbal.xml"), "--floating", "--balance-inertia", "--pinocchio-model", twin]
    argv += [flag for flag in _extra_flags() if flag not in argv]
    main(argv)
    assert seen and seen[0].floating and seen[0].balance_inertia and seen[0].pinocchio_model == twin
    for name in LoadOptions.names():
        if name not in ("allow_coupled", "pinocchio_model") and isinstance(getattr(LoadOptions(), name), bool):
            assert getattr(seen[0], name) is True, name


def _extra_flags() -> list[str]:
    return [
        "--" + n.replace("_", "-")
        for n in LoadOptions.names()
        if n not in ("allow_coupled", "pinocchio_model") and isinstance(getattr(LoadOptions(), n), bool)
    ]


def test_api_and_testing_helper_accept_every_load_option(monkeypatch) -> None:
    import koenig_check.engines as engines
    from koenig_check import api
    from koenig_check.testing import assert_energy_parity

    seen: list[LoadOptions] = []

    def fake_load_model(path, options=None, **kwargs):
        seen.append(options)
        raise engines.ModelLoadError("stop here")

    monkeypatch.setattr(engines, "load_model", fake_load_model)
    every = {n: True for n in LoadOptions.names() if isinstance(getattr(LoadOptions(), n), bool)}
    every.pop("allow_coupled")
    every["pinocchio_model"] = str(MODELS / "gimbal.urdf")
    expected = LoadOptions(**every)
    api.compare(MODELS / "gimbal.xml", **every)
    with pytest.raises(engines.ModelLoadError):
        api.compare_model(MODELS / "gimbal.xml", **every)
    with pytest.raises(AssertionError, match="stop here"):  # a load failure is the test's failure, one line
        assert_energy_parity(MODELS / "gimbal.xml", **every)
    assert seen == [expected] * 3
    for function in (api.compare_model, assert_energy_parity):
        assert "load_options" in inspect.signature(function).parameters


def test_unknown_load_option_is_refused() -> None:
    from koenig_check import api

    with pytest.raises(TypeError, match="unknown option"):
        api.compare_model(MODELS / "gimbal.xml", floting=True)


def test_allow_coupled_on_the_command_line_is_a_noted_no_op(capsys) -> None:
    status = main(["parity", str(MODELS / "gimbal.xml"), "--allow-coupled"])
    err = capsys.readouterr().err
    assert status == 0 and "--allow-coupled" in err and "deprecated" in err
