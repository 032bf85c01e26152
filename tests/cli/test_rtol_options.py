"""``--rtol`` on every command that compares, and what it changes on a twin differing at 4e-7 (6-digit rounding)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from koenig_check.cli.main import build_parser, main
from koenig_check.engines import resolve_model

#: Commands that compare numbers, each with its own --rtol (``models`` only lists names).
COMPARING = ("compare", "demo", "parity", "dynamics", "export", "selfcheck")


def test_every_comparing_command_has_rtol():
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    assert set(sub.choices) - set(COMPARING) == {"models", "causes"}  # listings: nothing is compared
    for name in COMPARING:
        assert "--rtol" in sub.choices[name]._option_string_actions, name


@pytest.fixture(scope="module")
def twin(tmp_path_factory) -> tuple[str, str]:
    """double_pendulum.urdf, and a twin whose masses differ by 4e-7 relative (what 6 digits can round away)."""
    original = resolve_model("double_pendulum.urdf").path
    text = Path(original).read_text()
    changed = re.sub(r'mass value="([^"]+)"', lambda m: f'mass value="{float(m.group(1)) * (1 + 4e-7):.12g}"', text)
    assert changed != text
    path = tmp_path_factory.mktemp("twin") / "double_pendulum_6digits.urdf"
    path.write_text(changed)
    return str(original), str(path)


def test_parity_rtol(twin, capsys):
    original, copy = twin
    assert main(["parity", original, "--pinocchio-model", copy]) == 1
    assert "mass" in capsys.readouterr().out
    assert main(["parity", original, "--pinocchio-model", copy, "--rtol", "1e-6"]) == 0
    out = capsys.readouterr().out
    assert "relative tolerance 1e-06" in out and "no import difference" in out
    assert main(["parity", original, "--pinocchio-model", copy, "--rtol", "1e-7"]) == 1  # 4e-7 is beyond 1e-7


def test_dynamics_rtol_is_the_engines_agreement(twin, capsys):
    original, copy = twin
    assert main(["dynamics", original, "--pinocchio-model", copy]) == 1
    err = capsys.readouterr().err  # only where the two readings meet, at a file's rounding: the option for it
    assert "MuJoCo and Pinocchio differ by at most" in err and "--rtol 1e-05 accepts it" in err
    assert main(["dynamics", original, "--pinocchio-model", copy, "--rtol", "1e-6"]) == 0
    assert main(["dynamics", original, "--pinocchio-model", copy, "--rtol", "1e-7"]) == 1


def test_dynamics_rtol_leaves_the_routes_own_tolerance(twin):
    """rtol widens where two readings meet, never a route against its own engine's mass matrix."""
    from koenig_check import dynamics

    original, copy = twin
    result = dynamics(original, pinocchio_model=copy, rtol=1e-6)
    assert result.ok
    same = [e for e in result.errors if e.formula == "exact" and e.route.endswith("@" + e.engine)]
    across = [e for e in result.errors if e.formula == "exact" and not e.route.endswith("@" + e.engine)]
    assert same and across
    assert all(result.tolerance(e) == (result.m_rtol if e.quantity == "M" else result.q_rtol) for e in same)
    assert max(e.max_rel_error for e in across if e.quantity == "M") > result.m_rtol  # the twin shows
