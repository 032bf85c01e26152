"""The progress bar over poses and models: drawn on a terminal, absent on a pipe and with --quiet."""

from __future__ import annotations

import fcntl
import os
import re
import struct
import subprocess
import sys
import termios

import pytest

#: Two models of 40,000 poses: several chunks each (a chunk is about 32,768 segment-poses).
COMMAND = [sys.executable, "-m", "koenig_check.cli", "compare", "double_pendulum", "gimbal", "--poses", "40000"]


def run_on(stderr_is_terminal: bool, *extra: str, columns: int = 120) -> tuple[int, str]:
    """Run the command with its stderr on a pseudo-terminal (``columns`` wide) or a pipe; return its stderr.

    On a pseudo-terminal, standard output goes there too (as on a user's terminal): the table follows the bar.
    """
    # A delay above 0, as by default (2 s): a bar shown only after it must still be erased (tqdm thought such a
    # bar never drawn when each model restarted its clock); the run lasts several times longer.
    env = dict(os.environ, KOENIG_CHECK_PROGRESS_DELAY="0.1", MPLBACKEND="Agg")
    if not stderr_is_terminal:
        done = subprocess.run([*COMMAND, *extra], capture_output=True, env=env, timeout=300)
        return done.returncode, done.stderr.decode()
    main, child = os.openpty()
    rows = 24 if columns else 0
    fcntl.ioctl(child, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, 0, 0))
    proc = subprocess.Popen([*COMMAND, *extra], stdout=child, stderr=child, env=env)
    os.close(child)
    out = b""
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:  # the child closed the terminal
            break
        if not data:
            break
        out += data
    os.close(main)
    return proc.wait(timeout=300), out.decode(errors="replace")


@pytest.fixture(scope="module")
def on_terminal() -> tuple[int, str]:
    return run_on(True)


def test_bar_on_a_terminal_counts_poses_per_model(on_terminal):
    status, err = on_terminal
    assert status == 0
    assert "1/2 models: double_pendulum" in err and "2/2 models: gimbal" in err
    counts = [int(n) for n in re.findall(r"(\d+)/40000 \[", err)]
    assert counts and max(counts) > 0, err[-2000:]  # advanced by chunks of poses, not only at model starts
    assert any(0 < n < 40000 for n in counts), counts  # a count between the chunks


def rendered(text: str) -> list[str]:
    """The lines a terminal shows for ``text``: ``\\r`` returns to the line's start, ``ESC[K`` erases to its end."""
    lines, line, col = [], [], 0
    for token in re.findall(r"\x1b\[[0-9;]*[A-Za-z]|\r\n|.|\n", text, flags=re.S):
        if token in ("\n", "\r\n"):
            lines.append("".join(line).rstrip())
            line, col = [], 0
        elif token == "\r":
            col = 0
        elif token.startswith("\x1b["):
            if token[-1] == "K":
                del line[col:]
        else:
            line[col : col + 1] = [token]
            col += 1
    return [*lines, "".join(line).rstrip()]


def test_bar_is_erased_before_the_table(on_terminal):
    """What stays on the screen: the table's first line alone on its line, no frame of the bar before it."""
    status, out = on_terminal
    assert status == 0
    (header,) = [line for line in rendered(out) if "Models:" in line]
    assert header.startswith("Models:"), repr(header)
    assert not any("poses/s" in line for line in rendered(out)), rendered(out)[:5]


def test_rate_has_three_significant_digits(on_terminal):
    _, out = on_terminal
    rates = re.findall(r"([0-9.]+)([kMG]?) poses/s", out)
    assert rates, out[-2000:]
    for number, _ in rates:  # 45.7k, 457, 4.57: tqdm's own '45743.98' has 7
        assert len(number.replace(".", "").lstrip("0")) <= 3, number


def test_bar_on_a_terminal_of_unknown_width():
    """A terminal that reports 0 columns (some containers, serial consoles) still gets the bar, then erases it."""
    status, out = run_on(True, columns=0)
    assert status == 0
    assert re.search(r"\d+/40000 \[", out), out[-2000:]
    assert next(line for line in rendered(out) if "Models:" in line).startswith("Models:")


def test_no_bar_on_a_pipe():
    status, err = run_on(False)
    assert status == 0
    assert "poses" not in err and "\r" not in err


def test_no_bar_with_quiet():
    status, err = run_on(True, "--quiet")
    assert status == 0
    assert "poses/s" not in err and "models:" not in err and "\r" not in err.replace("\r\n", "\n")


def test_no_bar_for_a_short_run():
    """Below the delay (2 s by default) a run on a terminal prints no bar."""
    env = {k: v for k, v in os.environ.items() if k != "KOENIG_CHECK_PROGRESS_DELAY"}
    main, child = os.openpty()
    fcntl.ioctl(child, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))
    proc = subprocess.Popen(
        [*COMMAND[:-1], "20"], stdout=subprocess.DEVNULL, stderr=child, env=dict(env, MPLBACKEND="Agg")
    )
    os.close(child)
    out = b""
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:
            break
        if not data:
            break
        out += data
    os.close(main)
    assert proc.wait(timeout=300) == 0
    assert b"poses" not in out, out
