"""comparisons/export_corpus.py, re-run on a few models, reproduces the committed verdicts of those rows."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from common import dm_control_corpus, parse_table_rows

from koenig_check.engines.drake.loader import drake_available

COMPARISONS = Path(__file__).resolve().parents[2] / "comparisons"
#: One MJCF that exports to both targets, one refused for URDF, one URDF (verdicts, engines and options compared).
MODELS = ("cartpole.xml", "ball_in_cup.xml", "double_pendulum.urdf")


def _rows(path: Path) -> dict[tuple[str, str], list[str]]:
    rows = parse_table_rows(path.read_text(encoding="utf-8"))
    return {(r[0], r[1]): r[:5] for r in rows if len(r) == 6}


@pytest.mark.skipif(not dm_control_corpus() or not drake_available(), reason="needs dm_control and Drake")
def test_subset_reproduces_the_committed_verdicts(tmp_path: Path) -> None:
    cmd = [sys.executable, str(COMPARISONS / "export_corpus.py"), "--out", str(tmp_path), "--models", *MODELS]
    subprocess.run(cmd, check=True, cwd=tmp_path, capture_output=True, text=True, timeout=300)
    fresh, committed = _rows(tmp_path / "export_corpus.md"), _rows(COMPARISONS / "export_corpus.md")
    assert len(fresh) >= 5
    for key, row in fresh.items():
        assert committed[key] == row, key
