"""The terminal verdict: within 100 columns, full names, one row per model and per formula, round-off as 0."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.demo import run_demo
from koenig_check.engines.registry import installed
from koenig_check.findings import Kind
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
    assert [r.split("  ")[0] for r in rows] == [p.model for p in demo_check.agreements]
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
    from koenig_check.diagnosis.import_parity import import_parity
    from koenig_check.engines import load_model
    from koenig_check.report.parity_table import format_parity

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
    label = check.agreements[0].model
    row = " ".join(" ".join(line.split()) for line in terminal_table(check).split("\n\n")[0].splitlines()[2:])
    assert row.startswith(label) and "changed so that MuJoCo loads it" in row
    assert element in row and effect in row


def _drake_installed() -> bool:

    return installed("drake")


needs_drake = pytest.mark.skipif(not _drake_installed(), reason="Drake is not installed (koenig-check[drake])")


def _model_rows(table: str) -> list[str]:
    return [line for line in table.split("\n\n")[0].splitlines() if line and not line.startswith(" ")]


@needs_drake
@pytest.mark.parametrize(  # Pinocchio departs (a class mass); Drake departs (a rotor inertia only it reads)
    "model", [CAUSES / "class_mass.xml", CAUSES.parent / "tiebreak" / "rotor_inertia.urdf"], ids=lambda p: p.name
)
def test_drake_on_every_pose_has_its_column_with_its_gap_to_mujoco(model: Path) -> None:
    check = koenig_check.compare(  # in chunks of 2 poses: the largest gap is merged across them
        [model, "gimbal.xml"], n_poses=7, chunk_poses=2, engines=("mujoco", "pinocchio", "drake")
    )
    table = terminal_table(check)
    assert table.startswith("Models: do MuJoCo, Pinocchio and Drake agree?")
    header = next(line for line in table.splitlines() if line.startswith("model "))
    assert header.split()[:7] == ["model", "verdict", "pinocchio", "gap", "drake", "gap", "exact"]
    for comp, row in zip(check.comparisons, _model_rows(table)[3:], strict=True):
        # Independent route: the records' exact totals on each engine's states (equal to its energy to rounding).
        value = {
            e: comp.records.where(formula="exact", scope="total", source=e, reference=e)["value"]
            for e in ("mujoco", "drake")
        }
        gap = float(np.max(np.abs(value["drake"] - value["mujoco"]) / np.abs(value["mujoco"])))
        printed = row.split()[3]
        assert printed == "0" if gap < 1e-13 else float(printed) == pytest.approx(gap, rel=0.06)
    assert max(len(line) for line in table.splitlines()) <= WIDTH


@needs_drake
def test_drake_as_tie_breaker_shows_its_gap_where_the_engines_differ_most() -> None:
    from koenig_check.findings import Kind

    check = koenig_check.compare([CAUSES / "class_mass.xml", "gimbal.xml"], n_poses=5)
    table = terminal_table(check)
    verdict = next(
        f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT and f.element == "rigid-body energy"
    )
    by_hand = abs(verdict.values["drake"] - verdict.values["mujoco"]) / abs(verdict.values["mujoco"])
    rows = _model_rows(table)[3:]
    drake_cell = rows[0].split()[3]
    assert drake_cell.endswith("*") and drake_cell[:-1] == ("0" if by_hand < ROUNDOFF else f"{by_hand:.1e}")
    assert rows[1].split()[3] == "—"  # gimbal.xml: the engines agree, Drake not consulted
    assert any(line.startswith("*: Drake as tie-breaker") for line in table.splitlines())


def test_without_drake_the_header_and_columns_are_the_two_engines() -> None:
    check = koenig_check.compare(["gimbal.xml"], n_poses=2, engines=("mujoco", "pinocchio"))
    table = terminal_table(check)
    assert table.startswith("Models: do MuJoCo and Pinocchio agree?") and "drake gap" not in table


def test_no_line_is_longer_than_200_characters_whatever_the_label_or_word() -> None:
    from koenig_check.report.terminal import LINE_LIMIT

    check = koenig_check.compare([CAUSES / "class_mass.xml"], n_poses=2)
    long_label = "robots/" + "very_long_directory_name/" * 10 + "arm.urdf"
    check.failures.append((long_label, "could not load " + "/deep" * 60 + "/mesh.stl: no such file"))
    table = terminal_table(check)
    assert LINE_LIMIT == 200 and max(len(line) for line in table.splitlines()) <= LINE_LIMIT
    assert long_label in table.replace("\n  ", "")  # folded, not dropped


def test_every_line_compare_prints_on_stdout_fits_200_characters(tmp_path: Path, capsys) -> None:
    from koenig_check.cli import main

    status = main(["compare", str(CAUSES / "class_mass.xml"), "gimbal.xml", "--poses", "3", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert status == 1 and "DISAGREE" in out
    assert max(len(line) for line in out.splitlines()) <= 200


@pytest.mark.skipif(
    not __import__("koenig_check.engines.registry").engines.registry.installed("drake"),
    reason="Drake (extra [drake]) not installed",
)
def test_a_model_failed_by_a_departing_engine_is_not_agree_on_its_row(capsys) -> None:
    """The row says what the exit status says: named Drake cannot check armature_chain (no armature read), while
    MuJoCo and Pinocchio agree: UNABLE, not agree and not DISAGREE."""
    from koenig_check.cli import main

    argv = ["compare", "armature_chain", "--poses", "2", "--formulas", "exact", "--engines", "mujoco,pinocchio,drake"]
    assert main(argv) == 1
    row = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("armature_chain"))
    assert row.split()[1] == "UNABLE" and "Drake cannot check" in row
    assert row.split()[3] == "unable"  # Drake's gap is to a robot its parser misread: no number


@pytest.mark.parametrize(
    ("agrees", "kinds", "status"),
    [
        (True, [], "agree"),
        (True, [Kind.MASS], "agree"),  # a difference below the tolerance's effect is no failure
        (False, [], "DISAGREE"),
        (True, [Kind.VERDICT], "DISAGREE"),  # a third engine departs
        (True, [Kind.ENGINE_UNABLE], "UNABLE"),  # a named engine could not check
        (False, [Kind.ENGINE_UNABLE], "DISAGREE"),  # the disagreement is the stronger word
        (True, [Kind.ENGINE_UNABLE, Kind.VERDICT], "DISAGREE"),
    ],
)
def test_the_row_status_names_why_a_model_fails(agrees: bool, kinds: list, status: str) -> None:
    from koenig_check.findings import Finding
    from koenig_check.report.terminal import _status

    findings = [Finding(kind, "drake", "model", "what the engine found") for kind in kinds]
    assert _status(agrees, findings) == status
