"""The API functions name every option in their signatures, from one definition (LoadOptions), and a misspelt
keyword names the closest one."""

from __future__ import annotations

import inspect
import warnings

import pytest

import koenig_check
from koenig_check.api import RUN_OPTIONS, compare_model
from koenig_check.arguments import ArgumentTypeError, keywords_of
from koenig_check.engines.load_options import LoadOptions
from koenig_check.testing import assert_energy_parity

LOAD = set(LoadOptions.names())


def keywords(func) -> set[str]:
    params = inspect.signature(func).parameters.values()
    assert not any(p.kind is p.VAR_KEYWORD for p in params), f"{func.__name__} hides options in **kwargs"
    return {p.name for p in params if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)}


def test_compare_names_every_option():
    per_model = keywords_of(compare_model) - {"model", "label", "on_chunk"}
    assert keywords(koenig_check.compare) == {"models", "progress", "debug"} | per_model | LOAD
    assert set(RUN_OPTIONS) == per_model - {"rtol", "load_options"}


def test_dynamics_names_every_option():
    run = {"model", "n_poses", "seed", "formulas", "m_rtol", "q_rtol", "velocity_scale", "rtol", "load_options"}
    assert keywords(koenig_check.dynamics) == run | LOAD
    assert "repair_inertia" in koenig_check.dynamics.__doc__


def test_assert_energy_parity_names_every_option():
    run = {"model", "n_poses", "seed", "velocity_scale", "rtol", "include_armature", "load_options", "gravity"}
    assert keywords(assert_energy_parity) == run | LOAD


NON_DEFAULT = {
    "floating": True,
    "balance_inertia": True,
    "repair_inertia": True,
    "pinocchio_model": "models/double_pendulum.urdf",
    "engines": ("mujoco", "pinocchio", "drake"),
    "xacro_args": {"length": "0.7"},
}


class LoadReachedError(Exception):
    pass


@pytest.fixture
def captured(monkeypatch):
    seen: list[LoadOptions] = []

    def fake_load(model, options):
        seen.append(options)
        raise LoadReachedError

    monkeypatch.setattr("koenig_check.engines.load_model", fake_load)
    monkeypatch.setattr("koenig_check.implied_dynamics.analysis.load_model", fake_load)
    monkeypatch.setattr("koenig_check.engines.registry.check_engines", lambda engines: None)
    monkeypatch.setattr("koenig_check.api.check_engines", lambda engines: None)
    return seen


CALLS = {
    "compare": lambda **kw: koenig_check.compare("double_pendulum", debug=True, **kw),
    "dynamics": lambda **kw: koenig_check.dynamics("double_pendulum", **kw),
    "assert_energy_parity": lambda **kw: assert_energy_parity("double_pendulum", **kw),
}


@pytest.mark.parametrize("name", sorted(NON_DEFAULT))
@pytest.mark.parametrize("call", sorted(CALLS))
def test_each_load_keyword_reaches_the_load(captured, call, name):
    with pytest.raises(LoadReachedError):
        CALLS[call](**{name: NON_DEFAULT[name]})
    assert getattr(captured[-1], name) == getattr(LoadOptions(**{name: NON_DEFAULT[name]}), name)


@pytest.mark.parametrize("call", sorted(CALLS))
def test_allow_coupled_is_accepted_deprecated(captured, call):
    with warnings.catch_warnings(record=True) as caught, pytest.raises(LoadReachedError):
        warnings.simplefilter("always")
        CALLS[call](allow_coupled=True)
    assert any(issubclass(w.category, DeprecationWarning) for w in caught)
    assert captured[-1].allow_coupled is False


@pytest.mark.parametrize(
    ("call", "typo", "closest"),
    [
        ("compare", "n_pose", "n_poses"),
        ("dynamics", "repair_inertias", "repair_inertia"),
        ("assert_energy_parity", "floatng", "floating"),
    ],
)
def test_misspelt_keyword_names_the_closest(call, typo, closest):
    with pytest.raises(ArgumentTypeError, match=f"unexpected keyword argument '{typo}'; did you mean '{closest}'"):
        CALLS[call](**{typo: True})
