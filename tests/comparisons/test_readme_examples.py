"""The README's example outputs are what the commands print today: each example is run again and compared with
its quote, text as text and numbers within the last digit the README prints (never as text: they may differ
with the CPU at round-off level), so that an example cannot drift from the tool again."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.engines import resolve_model

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w.])")


def _quoted(after: str, until: str) -> str:
    """The README's text between the line ``after`` and the next ``until``."""
    start = README.index(after) + len(after)
    return README[start : README.index(until, start)]


def _last_digit(text: str) -> float:
    """One unit in the last digit a number is printed with (0 for an integer: equal)."""
    if "." not in text and "e" not in text:
        return 0.0
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** (int(exponent or 0) - decimals)


def assert_same_output(quoted: str, printed: str) -> None:
    """Words equal once the numbers are masked (wherever a line folds); each number within the README's last digit."""
    words_q, words_p = quoted.split(), printed.split()
    masked = [NUMBER.sub("#", w) for w in words_q], [NUMBER.sub("#", w) for w in words_p]
    assert masked[0] == masked[1], f"README example differs from the run:\n{quoted}\n---- now ----\n{printed}"
    numbers = [
        (q, p)
        for wq, wp in zip(words_q, words_p, strict=True)
        for q, p in zip(NUMBER.findall(wq), NUMBER.findall(wp), strict=True)
    ]
    for q, p in numbers:
        assert abs(float(q) - float(p)) <= _last_digit(q) * (1 + 1e-9), f"README {q}, now {p}"


def test_the_check_only_example_is_what_the_command_prints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    command = "$ koenig-check export --check-only models/serial7.urdf serial7_mujoco.xml\n"
    block = _quoted("`--check-only ORIGINAL EXPORT` proves a conversion", "```\n\n")
    script = re.search(r'\$ python -c "(.*?)"\n', block, re.S).group(1).replace("\\\n", "")
    quoted = _quoted(command, "$ echo $?")
    status = int(_quoted(command + quoted + "$ echo $?\n", "\n"))
    (tmp_path / "models").symlink_to(ROOT / "models")
    monkeypatch.chdir(tmp_path)
    subprocess.run([sys.executable, "-c", script], check=True)  # the README's own command writes the twin
    assert main(["export", "--check-only", "models/serial7.urdf", "serial7_mujoco.xml"]) == status
    assert_same_output(quoted, capsys.readouterr().out)


#: Variables that change what pytest prints or which plugins it loads.
PYTEST_ENVIRONMENT = (
    "CI",
    "BUILD_NUMBER",
    "PYTEST_ADDOPTS",
    "PYTEST_PLUGINS",
    "PYTEST_DISABLE_PLUGIN_AUTOLOAD",
    "PY_COLORS",
    "FORCE_COLOR",
    "NO_COLOR",
)


def test_the_plugin_example_is_what_pytest_prints(tmp_path: Path) -> None:
    toml = _quoted("```toml\n", "```")
    (tmp_path / "pyproject.toml").write_text(toml, encoding="utf-8")
    (tmp_path / "models").mkdir()
    shutil.copy(ROOT / "models" / "double_pendulum.xml", tmp_path / "models")  # the project's model
    shutil.copy(ROOT / "tests" / "models" / "causes" / "class_mass.xml", tmp_path / "models")  # its trap file
    quoted = _quoted("$ pytest --koenig-check\n", "```")
    # The README shows what a user's terminal of 80 columns prints. pytest cuts the short summary's line to the
    # terminal only when it does not think it runs on CI (the CI or BUILD_NUMBER variable set): there the line is
    # the whole message. So the quote is compared with a plain run outside CI (no colours, no added options),
    # whatever machine runs this test.
    outside_ci = {k: v for k, v in os.environ.items() if k not in PYTEST_ENVIRONMENT}
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "--koenig-check", "-p", "no:cacheprovider"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env={**outside_ci, "COLUMNS": "80"},
    )
    assert run.returncode == 1
    printed = run.stdout[run.stdout.index("collected ") :]
    last = re.compile(r"=+ (.*) in [\d.]+s =+\n?$")  # the duration and the rule's width vary
    assert last.search(quoted).group(1) == last.search(printed).group(1)
    assert_same_output(last.sub("", quoted), last.sub("", printed))


@pytest.mark.parametrize(
    "context",
    [r"which\s+it replaces: ([^:]+?) get other moments", r"or a massless moving link \(([^)]+)\)"],
)
def test_robots_the_readme_names_are_names_the_tool_accepts(context: str) -> None:
    """Each robot of a README list resolves (``hyq`` does not: ``hyq_no_sensors`` does)."""
    names = [n.strip() for n in re.search(context, README, re.S).group(1).replace("\n", " ").split(",")]
    for name in [n for n in names if n and n != "..."]:
        assert resolve_model(name).path.is_file(), name
