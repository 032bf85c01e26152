"""Each comparison script, re-run on a few models, reproduces its committed rows exactly.

Numbers are compared as printed (their printed precision), verdict words exactly.  Rows are keyed by their
first cells; a subset's pooled rows (marked ``subset``) and the corpus counts are not compared.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from common import parse_table_rows

from koenig_check.engines.drake.loader import drake_available

COMPARISONS = Path(__file__).resolve().parents[2] / "comparisons"


def _run(script: str, out: Path, *args: str) -> None:
    cmd = [sys.executable, str(COMPARISONS / script), "--out", str(out), *args]
    subprocess.run(cmd, check=True, cwd=out, capture_output=True, text=True, timeout=600)


def _section(text: str, heading: str | None) -> str:
    if heading is None:
        return text
    start = text.index(heading)
    end = text.find("\n## ", start + len(heading))
    return text[start : end if end >= 0 else None]


def _rows(path: Path, heading: str | None, key: int) -> dict[tuple[str, ...], list[str]]:
    rows = parse_table_rows(_section(path.read_text(encoding="utf-8"), heading))
    return {tuple(r[:key]): r for r in rows}


def _compare(new: Path, heading: str | None, key: int, expect: int) -> None:
    committed = _rows(COMPARISONS / new.name, heading, key)
    fresh = _rows(new, heading, key)
    compared = [k for k in fresh if k in committed and not k[0].endswith("subset")]
    assert len(compared) >= expect, (sorted(fresh), heading)
    for k in compared:
        assert fresh[k] == committed[k], f"{new.name} row {k}:\nfresh:     {fresh[k]}\ncommitted: {committed[k]}"


@pytest.fixture(scope="module")
def claims_subset(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("claims")
    _run("paper_claims.py", out, "--claims", "a,b,c,d,e,f,g,h", "--models", "koenig-check:gimbal.xml,ur5_robot")
    return out / "paper_claims.md"


def test_paper_claims_rows(claims_subset: Path) -> None:
    _compare(claims_subset, "# The paper's claims", 1, expect=6)  # (a), (b), (c), both (d), (h)


def test_paper_claims_detail_rows(claims_subset: Path) -> None:
    _compare(claims_subset, "## (c) each reading", 2, expect=5)
    _compare(claims_subset, "## (h) gimbal.xml", 1, expect=7)


def test_paper_claims_model_rows(claims_subset: Path) -> None:
    _compare(claims_subset, "## (e), (f), (g) model by model", 2, expect=2)


def test_paper_claims_subset_marks_pooled_rows(claims_subset: Path) -> None:
    keys = {r[0] for r in parse_table_rows(claims_subset.read_text(encoding="utf-8"))}
    assert {"(e) subset", "(f) subset", "(g) subset"} <= keys


#: The committed tables have Drake's columns; without the extra they cannot be regenerated as committed.
needs_drake = pytest.mark.skipif(
    not drake_available(), reason="Drake (the optional extra [drake]) is not installed: its columns are committed"
)


@needs_drake
def test_engine_parity_rows(tmp_path: Path) -> None:
    models = ",".join(
        [
            "koenig-check:gimbal.xml",
            "dm_control:suite/cartpole.xml",
            "example-robot-data:ur_description/urdf/ur5_robot.urdf",
        ]
    )
    _run("engine_parity.py", tmp_path, "--models", models, "--jobs", "1")
    _compare(tmp_path / "engine_parity.md", "## Model by model", 2, expect=6)


@needs_drake
def test_inertia_forces_rows(tmp_path: Path) -> None:
    _run("inertia_forces.py", tmp_path, "--models", "koenig-check:gimbal.xml")
    _compare(tmp_path / "inertia_forces.md", None, 2, expect=10)
