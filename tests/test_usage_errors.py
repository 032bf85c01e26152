"""Usage errors: status 2 with the usage line before any work (CLI); TypeError / ValueError (API)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import koenig_check
from koenig_check import cli
from koenig_check.arguments import ArgumentTypeError, ArgumentValueError
from koenig_check.exceptions import KoenigCheckError

USAGE_ERRORS = {
    "zero poses": ["compare", "gimbal.xml", "--poses", "0"],
    "unknown formula": ["compare", "gimbal.xml", "--formulas", "exakt"],
    "grid without joints": ["compare", "gimbal.xml", "--pose-kind", "grid"],
    "grid joints without grid": ["compare", "gimbal.xml", "--grid-joints", "outer_z", "inner_x"],
    "negative seed": ["compare", "gimbal.xml", "--seed", "-1"],
    "zero duration": ["compare", "gimbal.xml", "--pose-kind", "trajectory", "--duration", "0"],
    "bad tolerance": ["compare", "gimbal.xml", "--rtol", "abc"],
    "demo zero poses": ["demo", "--poses", "0"],
    "unknown model name": ["compare", "gimbal.xml", "no_such_robot"],
    "unknown twin name": ["compare", "gimbal.xml", "--pinocchio-model", "no_such_twin"],
    "missing pose file": ["compare", "gimbal.xml", "--pose-file", "no_such_dir/poses.csv"],
}


def _refuse_loading(monkeypatch: pytest.MonkeyPatch, module: object, loader: str) -> list[str]:
    """Make ``module.loader`` fail loudly; return the list of the names it is asked for."""
    asked: list[str] = []

    def refuse(name, *args, **kwargs):
        asked.append(str(name))
        raise AssertionError(f"a model was loaded before the usage error: {name}")

    monkeypatch.setattr(module, loader, refuse)
    return asked


@pytest.fixture
def no_model_loaded(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Fail loudly if any model is loaded; collect the names asked for."""
    import koenig_check.engines as engines
    import koenig_check.implied_dynamics.analysis  # noqa: F401  (imported, so bound to the real load_model, first)

    return _refuse_loading(monkeypatch, engines, "load_model")


@pytest.mark.parametrize("argv", USAGE_ERRORS.values(), ids=USAGE_ERRORS.keys())
def test_usage_error_exits_2_with_usage_before_any_work(
    argv: list[str], tmp_path: Path, no_model_loaded: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "report"
    with pytest.raises(SystemExit) as exc:
        cli.main([*argv, "--out", str(out)])
    err = capsys.readouterr().err
    assert exc.value.code == 2
    assert err.startswith(f"usage: koenig-check {argv[0]} [options]") and "error:" in err
    assert not out.exists() and not no_model_loaded


@pytest.mark.parametrize("command", [["demo"], ["compare", "gimbal.xml"], ["dynamics", "gimbal.xml"]])
def test_out_naming_a_file_is_a_usage_error(
    command: list[str], tmp_path: Path, no_model_loaded: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    existing = tmp_path / "a_file"
    existing.write_text("mine", encoding="utf-8")
    for out in (existing, existing / "below"):
        with pytest.raises(SystemExit) as exc:
            cli.main([*command, "--out", str(out)])
        assert exc.value.code == 2 and "is a file, not a directory" in capsys.readouterr().err
    assert existing.read_text(encoding="utf-8") == "mine" and not no_model_loaded


def test_usage_error_in_a_fresh_process_is_two_lines_and_status_2(tmp_path: Path) -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "compare", "gimbal.xml", "--formulas", "koenig"],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )
    lines = proc.stderr.strip().splitlines()
    assert proc.returncode == 2 and len(lines) == 2 and "unknown formula 'koenig'" in lines[1]
    assert not list(tmp_path.iterdir())  # nothing written, not even MUJOCO_LOG.TXT


def test_help_lists_every_formula_and_explains_the_pose_kinds(capsys: pytest.CaptureFixture[str]) -> None:
    from koenig_check.arguments import POSE_KINDS
    from koenig_check.formulas import FORMULAS

    with pytest.raises(SystemExit):
        cli.main(["compare", "--help"])
    text = capsys.readouterr().out
    for name, formula in FORMULAS.items():
        assert f"  {name} " in text and formula.equations in text
    for kind in POSE_KINDS:
        assert f"\n  {kind} " in text


API_TYPE_ERRORS = {
    "misspelt keyword": {"n_pose": 5},
    "unknown keyword": {"colour": "red"},
    "rtol a string": {"rtol": "abc"},
    "n_poses a float": {"n_poses": 2.5},
    "formulas a string": {"formulas": "exact"},
}
API_VALUE_ERRORS = {
    "rtol negative": {"rtol": -1.0},
    "rtol nan": {"rtol": float("nan")},
    "zero poses": {"n_poses": 0},
    "unknown formula": {"formulas": ["exact", "exakt"]},
    "unknown pose kind": {"pose_kind": "spiral"},
    "grid without joints": {"pose_kind": "grid"},
    "records mode": {"records": "all"},
    "negative seed": {"seed": -3},
    "missing pose file": {"pose_file": "no_such_dir/poses.csv"},
}


@pytest.mark.parametrize("kwargs", API_TYPE_ERRORS.values(), ids=API_TYPE_ERRORS.keys())
def test_api_raises_type_error_before_loading(kwargs: dict, no_model_loaded: list[str]) -> None:
    with pytest.raises(TypeError) as exc:
        koenig_check.compare("ur5", **kwargs)
    assert isinstance(exc.value, ArgumentTypeError) and isinstance(exc.value, KoenigCheckError)
    assert not no_model_loaded and "\n" not in str(exc.value)


@pytest.mark.parametrize("kwargs", API_VALUE_ERRORS.values(), ids=API_VALUE_ERRORS.keys())
def test_api_raises_value_error_before_loading(kwargs: dict, no_model_loaded: list[str]) -> None:
    with pytest.raises(ValueError) as exc:
        koenig_check.compare("ur5", **kwargs)
    assert isinstance(exc.value, ArgumentValueError) and not no_model_loaded


def test_misspelt_keyword_names_the_right_one() -> None:
    with pytest.raises(TypeError, match=r"'n_pose'.*did you mean 'n_poses'"):
        koenig_check.compare("ur5", n_pose=5)


def test_valid_keywords_still_reach_the_model(no_model_loaded: list[str]) -> None:
    """Every load option and every compare_model keyword passes the check (then the stub refuses to load)."""
    result = koenig_check.compare("ur5", n_poses=3, seed=1, floating=True, records="none", jobs=1)
    assert no_model_loaded == ["ur5"] and result.failures


DYNAMICS_TYPE_ERRORS = {
    "misspelt keyword": {"n_pose": 5},
    "misspelt load option": {"flaoting": True},
    "n_poses a float": {"n_poses": 2.5},
    "formulas a string": {"formulas": "exact"},
    "m_rtol a string": {"m_rtol": "tight"},
}
DYNAMICS_VALUE_ERRORS = {
    "zero poses": {"n_poses": 0},
    "negative seed": {"seed": -1},
    "unknown formula": {"formulas": ["exakt"]},
    "q_rtol negative": {"q_rtol": -1e-6},
    "velocity scale zero": {"velocity_scale": 0.0},
}


@pytest.fixture
def no_dynamics_model_loaded(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Fail loudly if dynamics() loads its model; collect the names asked for."""
    from koenig_check.implied_dynamics import analysis

    return _refuse_loading(monkeypatch, analysis, "load_model")


@pytest.mark.parametrize("kwargs", DYNAMICS_TYPE_ERRORS.values(), ids=DYNAMICS_TYPE_ERRORS.keys())
def test_dynamics_raises_type_error_before_loading(kwargs: dict, no_dynamics_model_loaded: list[str]) -> None:
    with pytest.raises(ArgumentTypeError) as exc:
        koenig_check.dynamics("gimbal.xml", **kwargs)
    assert isinstance(exc.value, TypeError) and not no_dynamics_model_loaded and "\n" not in str(exc.value)


@pytest.mark.parametrize("kwargs", DYNAMICS_VALUE_ERRORS.values(), ids=DYNAMICS_VALUE_ERRORS.keys())
def test_dynamics_raises_value_error_before_loading(kwargs: dict, no_dynamics_model_loaded: list[str]) -> None:
    with pytest.raises(ArgumentValueError) as exc:
        koenig_check.dynamics("gimbal.xml", **kwargs)
    assert isinstance(exc.value, ValueError) and not no_dynamics_model_loaded
    assert str(next(iter(kwargs))) in str(exc.value) or "formula" in str(exc.value)


def test_dynamics_misspelt_keyword_names_the_right_one() -> None:
    with pytest.raises(TypeError, match=r"'flaoting'.*did you mean 'floating'"):
        koenig_check.dynamics("gimbal.xml", flaoting=True)


def test_dynamics_valid_keywords_reach_the_model(no_dynamics_model_loaded: list[str]) -> None:
    with pytest.raises(AssertionError):
        koenig_check.dynamics("gimbal.xml", n_poses=2, seed=0, formulas=["exact"], m_rtol=1e-9, floating=True)
    assert no_dynamics_model_loaded == ["gimbal.xml"]
