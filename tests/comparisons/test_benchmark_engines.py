"""``comparisons/benchmark.py --engine NAME``: each new engine's bare loop against the adapter's sweep, a smoke run."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from named_engines import NEW_ENGINES, named

SCRIPT = Path(__file__).resolve().parents[2] / "comparisons" / "benchmark.py"
LINE = re.compile(r"ur5: (\w+) bare loop ([0-9.]+) µs/pose, adapter sweep ([0-9.]+) µs/pose \(CPU\), ratio ([0-9.]+)")


@pytest.mark.parametrize("engine", [named(e) for e in NEW_ENGINES])
def test_the_engine_benchmark_times_its_bare_loop_and_the_adapters_sweep(engine: str) -> None:
    argv = [sys.executable, str(SCRIPT), "--engine", engine, "--smoke", "--models", "ur5"]
    proc = subprocess.run(argv, capture_output=True, text=True, check=False, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    (found,) = [m for m in map(LINE.fullmatch, proc.stdout.splitlines()) if m]
    bare, sweep, ratio = (float(x) for x in found.groups()[1:])
    assert found.group(1) == engine and bare > 0 and sweep > 0
    # the ratio printed to 0.01 from the unrounded times, the times to 0.1 µs: the quotient of the printed times is
    # within the ratio's rounding plus the times' (0.05 each, propagated)
    assert ratio == pytest.approx(sweep / bare, abs=0.005 + 0.05 * (bare + sweep) / bare**2 + 1e-9)
