"""The terminal verdict: within 100 columns, full names, one row per model and per formula, round-off as 0."""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check
from koenig_check.demo import run_demo
from koenig_check.report.terminal import WIDTH, terminal_table
from koenig_check.roundoff import ROUNDOFF, fmt, shown

CAUSES = Path(__file__).parents[1] / "models" / "causes"


@pytest.fixture(scope="module")
def demo_check():
    check, _ = run_demo(n_poses=3, grid_samples=5, trajectory_samples=20)
    return check


@pytest.fixture(scope="module")
def demo_table(demo_check) -> str:
    return terminal_table(demo_check)


def test_demo_verdict_fits_100_columns(demo_table: str) -> None:
    assert WIDTH == 100 and max(len(line) for line in demo_table.splitlines()) <= WIDTH


def test_one_row_per_model_with_its_full_name(demo_check, demo_table: str) -> None:
    rows = demo_table.split("\n\n")[0].splitlines()[2:]
    assert [r.split("  ")[0] for r in rows] == [p.model for p in demo_check.parities]
    assert "armature_chain.xml" in demo_table and "armature_chain.urdf" in demo_table and "…" not in demo_table


def test_one_row_per_formula_with_worst_and_where(demo_check, demo_table: str) -> None:
    block = demo_table.split("\n\n")[1].splitlines()
    starts = [line.split()[0] for line in block[2:] if line and not line.startswith(" ")]
    formulas = list(dict.fromkeys(s.formula for s in demo_check.summaries))
    assert [f for f in starts if f in formulas] == formulas
    worst = max(
        (s for s in demo_check.summaries if s.formula == "koenig_world" and s.source == s.reference),
        key=lambda s: s.max_rel_error,
    )
    row = next(line for line in block if line.startswith("koenig_world "))
    assert f"≠ {worst.max_rel_error:.1e}" in row and worst.model in row and worst.worst_pose in row


def test_disagreeing_model_shows_its_root_cause_wrapped_within_100_columns() -> None:
    check = koenig_check.compare([CAUSES / "class_mass.xml", "gimbal.xml"], n_poses=3)
    table = terminal_table(check)
    assert "DISAGREE" in table and max(len(line) for line in table.splitlines()) <= WIDTH
    reason = check.reason().split(": ", 1)[1]
    words = reason.split()[:6]
    assert all(w in table for w in words)  # the cause is printed, wrapped, never cut


def test_failed_model_is_a_row_with_its_reason() -> None:
    check = koenig_check.compare(["no_such_model_here", "gimbal.xml"], n_poses=2)
    table = terminal_table(check)
    assert any(line.startswith("no_such_model_here") and "FAILED" in line for line in table.splitlines())


@pytest.mark.parametrize(
    "value, printed", [(-4e-16, "0"), (4.4e-15, "0"), (-0.0, "0"), (ROUNDOFF, "1.00e-12"), (0.41, "4.10e-01")]
)
def test_round_off_prints_as_zero_below_the_threshold(value: float, printed: str) -> None:
    assert fmt(value) == printed
    assert shown(value) == (0.0 if abs(value) < ROUNDOFF else value)


def test_exact_formulas_print_zero_in_the_verdict(demo_table: str) -> None:
    row = next(line for line in demo_table.splitlines() if line.startswith("exact "))
    assert "= 0 " in row


@pytest.mark.parametrize("model", ["serial7.urdf", "ur5"])
def test_parity_report_prints_armature_round_off_as_zero(model: str) -> None:
    from koenig_check.diagnosis.import_parity import format_parity, import_parity
    from koenig_check.engines import load_model

    report = import_parity(load_model(model))
    raw = [a for d in report.dofs for a in d.armature]
    assert any(0 < abs(a) < ROUNDOFF for a in raw)  # the engines' round-off is there to hide
    text = format_parity(report)
    rows = text.split("armature MuJoCo", 1)[1].split("\n(armature values below", 1)[0].splitlines()[1:]
    assert len(rows) == len(report.dofs)
    for row in rows:
        mj, pn = (float(x) for x in row.split()[1:3])
        assert all(v == 0 or abs(v) >= ROUNDOFF for v in (mj, pn)) and "e-16" not in row.split()[1]


@pytest.mark.parametrize(
    ("model", "element", "effect"),
    [
        ("go1", "link base", "welded to the world: cannot change the energy"),
        (
            Path(__file__).resolve().parents[1] / "engines" / "models" / "repair_needed.urdf",
            "link tilted",
            "moving: can change MuJoCo's energy",
        ),
    ],
)
def test_a_model_changed_to_be_loaded_says_so_on_its_row(model, element: str, effect: str) -> None:
    check = koenig_check.compare(
        model, repair_inertia=True, n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio")
    )
    label = check.parities[0].model
    row = " ".join(" ".join(line.split()) for line in terminal_table(check).split("\n\n")[0].splitlines()[2:])
    assert row.startswith(label) and "changed so that MuJoCo loads it" in row
    assert element in row and effect in row


def test_the_former_name_and_module_give_the_same_table() -> None:
    from koenig_check.verdict import verdict_table  # type: ignore[import-not-found]  # the module's old name

    assert verdict_table is terminal_table
