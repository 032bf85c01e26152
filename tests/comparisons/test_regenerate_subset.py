"""Each comparison script, re-run on a few models, reproduces its committed rows.

Verdict words and every number at physics level are compared exactly as printed.  Numbers at round-off or
finite-difference level depend on the CPU and the BLAS, so they are compared against their own error bound,
never as text: two values that are both below the bound of their column are the same result.  The bounds are
the ones the scripts print by: round-off below :data:`koenig_check.roundoff.ROUNDOFF` (1e-12, printed
``0 (rounding)`` or ``0``), and Q* from central differences below ``Q_FLOOR`` (1e-8, printed ``< 1e-08``;
paper_claims.py and inertia_forces.py say so where they define it).  Rows are keyed by their first cells; a
subset's pooled rows (marked ``subset``) and the corpus counts are not compared.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from common import parse_table_rows

from koenig_check.engines.drake.loader import drake_available
from koenig_check.roundoff import ROUNDOFF

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


#: Q* comes from central differences: below this a Q* error is the differences' own error (the scripts' Q_FLOOR).
Q_FLOOR = 1e-8
_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def _tables(text: str) -> list[tuple[list[str], list[list[str]]]]:
    """Each Markdown table of a text as (header cells, body rows)."""
    tables: list[tuple[list[str], list[list[str]]]] = []
    lines = text.splitlines()
    for i, line in enumerate(lines[:-1]):
        if line.startswith("| ") and re.fullmatch(r"\|( -{3}:? \|)+", lines[i + 1]):
            end = i + 2
            while end < len(lines) and lines[end].startswith("| "):
                end += 1
            header = [c.strip() for c in line.split("|")[1:-1]]
            tables.append((header, parse_table_rows("\n".join(lines[i:end]))))
    return tables


def _rows(path: Path, heading: str | None, key: int) -> dict[tuple[str, ...], tuple[list[str], list[str]]]:
    """Rows keyed by their first ``key`` cells, each with its table's header."""
    tables = _tables(_section(path.read_text(encoding="utf-8"), heading))
    return {tuple(r[:key]): (header, r) for header, rows in tables for r in rows}


def bound_of(column: str) -> float:
    """The error bound of a column's small numbers: finite differences for Q*, round-off otherwise."""
    return Q_FLOOR if "Q*" in column else ROUNDOFF


def same_cell(fresh: str, committed: str, bound: float) -> bool:
    """Equal text, or the same text around numbers each equal as printed or both below ``bound``."""
    fresh, committed = (c.replace("0 (rounding)", "0") for c in (fresh, committed))
    if fresh == committed:
        return True
    if _NUMBER.sub("#", fresh) != _NUMBER.sub("#", committed):
        return False  # other words, or another count of numbers
    pairs = zip(_NUMBER.findall(fresh), _NUMBER.findall(committed), strict=True)
    return all(a == b or (abs(float(a)) < bound and abs(float(b)) < bound) for a, b in pairs)


def _compare(new: Path, heading: str | None, key: int, expect: int) -> None:
    committed = _rows(COMPARISONS / new.name, heading, key)
    fresh = _rows(new, heading, key)
    compared = [k for k in fresh if k in committed and not k[0].endswith("subset")]
    assert len(compared) >= expect, (sorted(fresh), heading)
    for k in compared:
        (header, row), (header_then, row_then) = fresh[k], committed[k]
        assert header == header_then and len(row) == len(row_then), f"{new.name} row {k}: columns changed"
        differ = [
            f"{column}: fresh {a!r}, committed {b!r} (bound {bound_of(column):g})"
            for column, a, b in zip(header, row, row_then, strict=True)
            if not same_cell(a, b, bound_of(column))
        ]
        assert not differ, f"{new.name} row {k}: " + "; ".join(differ)


@pytest.mark.parametrize(
    ("fresh", "committed", "column", "same"),
    [
        ("1.8e-10", "1.4e-10", "Q*", True),  # both finite-difference noise (the case seen on two machines)
        ("1.2e-08", "< 1e-08", "Q* vs MuJoCo", False),  # above the floor: a finding, not noise
        ("2.0e-10", "1.4e-10", "M", False),  # M is exact to rounding: 2e-10 is not round-off
        ("2.1e-15", "2.4e-15", "MuJoCo vs Pinocchio, max rel.", True),
        ("6.6e-16 / 4.8e-16 / 4.8e-16", "6.1e-16 / 5.0e-16 / 4.8e-16", "self-consistency", True),
        ("0 (rounding)", "4.4e-13", "M", True),
        ("5.5e-01", "5.6e-01", "Q*", False),  # physics level: exact as printed
        ("+15.4 % throughout", "+15.5 % throughout", "difference", False),
        ("holds", "fails", "verdict", False),
        ("0 (rounding)", "0 (rounding)", "verdict", True),
        ("agree", "agree 1.0e-15", "verdict", False),
    ],
)
def test_cells_compare_numbers_within_their_error_bound_and_words_exactly(
    fresh: str, committed: str, column: str, same: bool
) -> None:
    assert same_cell(fresh, committed, bound_of(column)) is same


def test_the_bounds_are_the_scripts_own() -> None:
    import inertia_forces
    import paper_claims

    assert Q_FLOOR == paper_claims.Q_FLOOR == inertia_forces.Q_FLOOR


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
