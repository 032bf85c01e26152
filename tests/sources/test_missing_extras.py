"""A source whose package is not installed: one line saying what to install, before any work."""

from __future__ import annotations

import sys

import pytest

from koenig_check import compare
from koenig_check.cli import main
from koenig_check.sources import ModelSourceError
from koenig_check.sources.catalogue import resolve_model

#: model as typed -> (the module that is missing, the extra that installs it)
SOURCES = {
    "menagerie:unitree_g1": ("mujoco_menagerie", "menagerie"),
    "rd:ur5e_description": ("robot_descriptions", "descriptions"),
    "robot.urdf.xacro": ("xacrodoc", "xacro"),
}


@pytest.fixture(params=sorted(SOURCES))
def missing(request, monkeypatch, tmp_path):
    """One source's package made unimportable (``sys.modules[name] = None``)."""
    model = request.param
    module, extra = SOURCES[model]
    for name in [m for m in sys.modules if m == module or m.startswith(f"{module}.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, module, None)
    if model.endswith(".xacro"):
        (tmp_path / model).write_text("<robot name='r'/>")
        monkeypatch.chdir(tmp_path)
    return model, extra


def test_resolver_says_what_to_install(missing):
    model, extra = missing
    with pytest.raises(ModelSourceError) as info:
        resolve_model(model)
    assert str(info.value).startswith(f"{model}: needs ")
    assert f"pip install 'koenig-check[{extra}]'" in str(info.value)
    assert "\n" not in str(info.value)


def test_api_refuses_before_any_model(missing):
    model, extra = missing
    started = []
    with pytest.raises(ModelSourceError, match=rf"koenig-check\[{extra}\]"):
        compare(["gimbal", model], n_poses=2, progress=started.append)
    assert started == []


@pytest.mark.parametrize("command", ["compare", "parity", "dynamics"])
def test_cli_exits_2(missing, command, capsys):
    model, extra = missing
    with pytest.raises(SystemExit) as info:
        main([command, model])
    assert info.value.code == 2
    assert f"pip install 'koenig-check[{extra}]'" in capsys.readouterr().err


def test_models_menagerie_without_the_extra(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "mujoco_menagerie", None)
    with pytest.raises(SystemExit) as info:
        main(["models", "--menagerie"])
    assert info.value.code == 2
    assert "pip install 'koenig-check[menagerie]'" in capsys.readouterr().err
