"""The per-model table of the report: each formula's row shows its worst engine's numbers, not the first one's."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import koenig_check
import koenig_check.run.records
from koenig_check.cli import main
from koenig_check.report.content import model_table
from koenig_check.run.summaries import FormulaSummary


def _summary(engine: str, max_rel: float, median: float, over: float, pose: str, agrees: bool) -> FormulaSummary:
    """One engine's states against its own energy (the rows the table reads), values chosen by hand."""
    return FormulaSummary("robot.xml", "koenig_world", engine, engine, max_rel, median, over, 0.0, pose, None, agrees)


@pytest.mark.parametrize("order", [("mujoco", "pinocchio"), ("pinocchio", "mujoco")])
def test_a_row_shows_the_engine_with_the_largest_error(order: tuple[str, str]) -> None:
    """MuJoCo's states give koenig_world a 3e-4 error (median 1e-4, 20 % over, at random-1); Pinocchio's 7e-2
    (median 5e-3, 60 % over, at random-7): whichever engine comes first, the row is Pinocchio's."""
    given = {
        "mujoco": _summary("mujoco", 3e-4, 1e-4, 0.2, "random-1", False),
        "pinocchio": _summary("pinocchio", 7e-2, 5e-3, 0.6, "random-7", False),
    }
    (row,) = model_table([given[e] for e in order], ["mujoco", "pinocchio"])
    assert row.verdict == "differs"
    assert row.worst_pose == "random-7"
    assert float(row.median) == pytest.approx(5e-3)
    assert row.over_under == "60% / 0%"
    assert [float(x) for x in row.max_error.split(" / ")] == pytest.approx([3e-4, 7e-2])  # MuJoCo / Pinocchio


def test_a_formula_exact_on_one_engine_only_differs() -> None:
    rows = model_table(
        [
            _summary("mujoco", 1e-15, 1e-16, 0.0, "random-0", True),
            _summary("pinocchio", 1e-3, 1e-4, 1.0, "random-2", False),
        ],
        ["mujoco", "pinocchio"],
    )
    assert [r.verdict for r in rows] == ["differs"]


def test_the_overview_names_the_largest_error_of_the_run() -> None:
    """Two models, koenig_world against exact: the overview's "Largest error" is the summary with the largest error
    of all (each engine's states against its own energy), with its model and pose."""
    import koenig_check
    from koenig_check.report.content import run_overview

    check = koenig_check.compare(["gimbal.xml", "double_pendulum.xml"], n_poses=4, formulas=["exact", "koenig_world"])
    own = [s for s in check.summaries if s.source == s.reference]
    worst = max(own, key=lambda s: s.max_rel_error)
    assert worst.formula == "koenig_world" and not worst.agrees  # eq. (1) in world axes drops the products
    assert max(s.max_rel_error for s in own if s.model != worst.model) < worst.max_rel_error  # one model is worse
    lines = run_overview(check.comparisons, check.summaries, check.agreements)
    (largest,) = [line for line in lines if line.startswith("Largest error:")]
    assert "`koenig_world`" in largest and f" on {worst.model} at pose {worst.worst_pose} " in largest


@pytest.mark.parametrize("order", [("mujoco", "pinocchio"), ("pinocchio", "mujoco")])
def test_a_models_findings_give_the_worst_engines_error_and_median(order: tuple[str, str]) -> None:
    """The plain-words line of an inexact formula: its largest error over the engines (7e-2, Pinocchio's) with that
    engine's median (5e-3), whichever engine comes first."""
    import koenig_check
    from koenig_check.report.content import model_findings

    check = koenig_check.compare("gimbal.xml", n_poses=2, formulas=["exact", "koenig_world"])
    given = {
        "mujoco": _summary("mujoco", 3e-4, 1e-4, 0.2, "random-1", False),
        "pinocchio": _summary("pinocchio", 7e-2, 5e-3, 0.6, "random-7", False),
    }
    found = model_findings(check.comparisons[0], [given[e] for e in order], check.agreements[0], 1e-9)
    assert found.exact == []
    (line,) = found.inexact
    assert line.startswith("koenig_world: up to 7 % (median 0.5 %), always over: over on 60% of poses")


DM_CONTROL = Path(__import__("dm_control").__file__).parent


def _shares_from_records(records: koenig_check.run.records.RecordTable, formula: str, engine: str, rtol: float):
    """Over / under shares of one engine's states against its own energy, from the records read back."""
    rows = records.where(records.mask(formula=formula, source=engine, reference=engine, scope="total"))
    signed, ref = np.asarray(rows["signed_error"]), np.asarray(rows["reference_value"])
    return float(np.mean(signed > rtol * ref)), float(np.mean(signed < -rtol * ref)), float(np.max(rows["rel_error"]))


def test_a_models_findings_give_one_engines_shares_as_its_table_does(tmp_path: Path) -> None:
    """dm_control's jaco_arm.xml: the engines' shares of over / under differ (their files disagree); the line of
    summary.md and of report.html gives the shares of the engine with the largest error, the same as the table
    beside it, read back from the records (not MuJoCo's over share with Pinocchio's under share: 105 %)."""
    model = DM_CONTROL / "third_party" / "kinova" / "jaco_arm.xml"
    formulas = ["exact", "koenig_world", "alyushin_paper:rotvec"]
    assert main(["compare", str(model), "--poses", "20", "--formulas", *formulas, "--out", str(tmp_path)]) == 1
    records = koenig_check.read_records(tmp_path / "records.parquet")
    summary = (tmp_path / "summary.md").read_text(encoding="utf-8")
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    mixed = 0
    for formula in ("koenig_world", "alyushin_paper:rotvec"):
        shares = {e: _shares_from_records(records, formula, e, 1e-9) for e in ("mujoco", "pinocchio")}
        worst = max(shares, key=lambda e: shares[e][2])
        over, under, _ = shares[worst]
        other = shares["pinocchio" if worst == "mujoco" else "mujoco"]
        mixed += max(over, other[0]) != over or max(under, other[1]) != under  # a max over engines would mix
        line = next(x for x in summary.splitlines() if f"`{formula}` up to" in x)
        shown = [int(x) / 100 for x in re.findall(r"(\d+)% ", line + " ")[:2]]
        assert shown == pytest.approx([over, under], abs=0.005), line
        assert sum(shown) <= 1.0
        row = next(x for x in summary.splitlines() if x.startswith(f"| `{formula}`"))
        assert f"| {over:.0%} / {under:.0%} |" in row  # the table: the same engine
        assert f"over on {over:.0%} of poses, under on {under:.0%}" in page
    assert mixed  # the case the fix is for: on at least one formula the engines' shares differ
