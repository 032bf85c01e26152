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


def run_on(stderr_is_terminal: bool, *extra: str) -> tuple[int, str]:
    """Run the command with its stderr on a pseudo-terminal (120 columns) or a pipe; return its stderr."""
    env = dict(os.environ, KOENIG_CHECK_PROGRESS_DELAY="0", MPLBACKEND="Agg")
    if not stderr_is_terminal:
        done = subprocess.run([*COMMAND, *extra], capture_output=True, env=env, timeout=300)
        return done.returncode, done.stderr.decode()
    main, child = os.openpty()
    fcntl.ioctl(child, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))
    proc = subprocess.Popen([*COMMAND, *extra], stdout=subprocess.DEVNULL, stderr=child, env=env)
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


def test_no_bar_on_a_pipe():
    status, err = run_on(False)
    assert status == 0
    assert "poses" not in err and "\r" not in err


def test_no_bar_with_quiet():
    status, err = run_on(True, "--quiet")
    assert status == 0
    assert "poses" not in err and "models:" not in err


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
