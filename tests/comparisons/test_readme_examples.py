"""The example outputs quoted by the README and the documentation pages (``docs/*.md``) are what the commands print
today: each example is run again and compared with its quote, text as text and numbers within the last digit the
document prints (never as text: they may differ with the CPU at round-off level), so that an example cannot drift
from the tool again.  Each quote is found in whichever document holds it (tests/documents.py)."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from documents import README, all_documents, document_with
from koenig_check.cli import main
from koenig_check.engines import resolve_model
from koenig_check.roundoff import ROUNDOFF

ROOT = Path(__file__).resolve().parents[2]
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w.])")


def _quoted(after: str, until: str) -> str:
    """The text between the line ``after`` and the next ``until``, in the one document that holds ``after``."""
    text = document_with(after)
    start = text.index(after) + len(after)
    return text[start : text.index(until, start)]


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
        if max(abs(float(q)), abs(float(p))) < ROUNDOFF:  # both round-off (printed as 0 elsewhere): CPU-dependent
            continue
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
    """Each robot of a documented list resolves (``hyq`` does not: ``hyq_no_sensors`` does)."""
    names = [n.strip() for n in re.search(context, all_documents(), re.S).group(1).replace("\n", " ").split(",")]
    for name in [n for n in names if n and n != "..."]:
        assert resolve_model(name).path.is_file(), name


def test_the_readme_example_on_a_users_file_is_what_compare_prints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The README's own file, written from its quote, gives the quoted table (Drake's column: with Drake)."""
    pytest.importorskip("pydrake", reason="the README's example shows Drake's column")
    readme = README.read_text(encoding="utf-8")
    command = "$ koenig-check compare cartpole.xml\n"
    xml = re.search(r"```xml\n(.*?)```", readme, re.S).group(1)
    start = readme.index(command) + len(command)
    quoted = readme[start : readme.index("```", start)]
    (tmp_path / "cartpole.xml").write_text(xml, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    status = main(["compare", "cartpole.xml"])
    captured = capsys.readouterr()
    assert status == 1 and "The exit status is 1" in readme
    printed = "".join(captured.out.splitlines(keepends=True)[: len(quoted.splitlines())])
    assert_same_output(quoted, printed)
    assert captured.err.count("\n") == 1 and "root cause" in captured.err  # the same reason, one line


def test_the_export_example_is_what_the_command_prints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("pydrake", reason="the example proves the export in Drake too")
    command = "$ koenig-check export armature_chain --to urdf --out armature_chain.urdf\n"
    quoted = _quoted(command, "$ echo $?")
    status = int(_quoted(command + quoted + "$ echo $?\n", "\n"))
    monkeypatch.chdir(tmp_path)
    assert main(["export", "armature_chain", "--to", "urdf", "--out", "armature_chain.urdf"]) == status
    assert_same_output(quoted, capsys.readouterr().out)


def test_the_first_robot_example_is_what_compare_prints(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The getting-started page quotes the head of ``compare serial7.urdf`` (then ``...``)."""
    command = "$ koenig-check compare serial7.urdf\n"
    quoted = _quoted(command, "...\n")
    assert main(["compare", "serial7.urdf"]) == 0
    printed = "".join(capsys.readouterr().out.splitlines(keepends=True)[: len(quoted.splitlines())])
    assert_same_output(quoted, printed)
