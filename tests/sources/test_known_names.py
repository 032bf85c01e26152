"""Model arguments: an unknown plain name is a usage error (exit 2, closest names); a missing path fails alone."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check import cli
from koenig_check.sources.catalogue import accepted_names
from koenig_check.sources.known_names import ambiguous_name, looks_like_path, unknown_name

COMMANDS = {
    "compare": ["compare", "gimbal.xml", "ur5_robt"],
    "parity": ["parity", "ur5_robt"],
    "dynamics": ["dynamics", "ur5_robt"],
}


@pytest.fixture
def no_model_loaded(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """Fail loudly if any model is loaded (the CLI modules import load_model from these two places)."""
    import koenig_check.engines as engines
    from koenig_check.implied_dynamics import analysis

    asked: list[str] = []

    def refuse(name, *args, **kwargs):
        asked.append(str(name))
        raise AssertionError(f"a model was loaded before the usage error: {name}")

    monkeypatch.setattr(engines, "load_model", refuse)
    monkeypatch.setattr(analysis, "load_model", refuse)
    return asked


@pytest.mark.parametrize("argv", COMMANDS.values(), ids=COMMANDS.keys())
def test_unknown_name_exits_2_with_the_closest_names_before_any_work(
    argv: list[str], no_model_loaded: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as exc:
        cli.main(argv)
    assert exc.value.code == 2 and not no_model_loaded
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert "ur5_robt: no model of that name" in line and "ur5_robot" in line and "`koenig-check models`" in line


def test_known_names_files_and_paths_are_not_unknown(tmp_path: Path) -> None:
    existing = tmp_path / "my_robot"  # a file without a suffix is a file
    existing.write_text("<robot name='r'/>")
    for name in ("ur5", "talos", "gimbal", "gimbal.urdf", "anymal", "menagerie:no_such", str(existing)):
        assert unknown_name(name) is None, name
    for path in ("my_robot.urdf", "nowhere/robot", "robot.XML"):  # missing files: a per-model failure, later
        assert looks_like_path(path) and unknown_name(path) is None
    reason = unknown_name("no_such_robot")
    assert reason is not None and "\n" not in reason and "no_such_robot" in reason
    assert all(name in accepted_names() for name in reason.split("closest: ")[1].split(" (")[0].split(", "))


def test_a_missing_file_in_a_batch_fails_alone(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "nowhere" / "robot.urdf"
    assert cli.main(["compare", "gimbal.xml", str(missing), "--poses", "2", "--formulas", "exact"]) == 1
    out, err = capsys.readouterr()
    assert any(line.startswith("gimbal.xml") and "agree" in line for line in out.splitlines())
    (line,) = err.strip().splitlines()
    assert str(missing) in line and ("no such file" in line or "file not found" in line)


@pytest.mark.parametrize("argv", [["compare", "gimbal.xml", "anymal"], ["parity", "anymal"], ["dynamics", "anymal"]])
def test_an_ambiguous_name_exits_2_naming_the_models_before_any_work(
    argv: list[str], no_model_loaded: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as exc:
        cli.main(argv)
    assert exc.value.code == 2 and not no_model_loaded
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert "anymal: ambiguous model name" in line
    assert "anymal_b_simple/anymal" in line and "anymal_c_simple/anymal" in line


@pytest.mark.parametrize("name", ["anymal_b_simple/anymal", "anymal_c_simple/anymal", "romeo", "double_pendulum"])
def test_a_name_that_names_one_model_is_not_ambiguous(name: str) -> None:
    assert ambiguous_name(name) is None and unknown_name(name) is None
