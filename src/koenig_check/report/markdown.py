"""``summary.md``: the Markdown summary of a run, readable without the paper."""

from __future__ import annotations

from collections.abc import Sequence

from koenig_check.report.content import (
    COLUMNS,
    POSE_LABELS,
    glossary,
    model_findings,
    model_table,
    refusal_lines,
    run_conditions,
    run_overview,
    shared_notes,
)
from koenig_check.roundoff import ROUNDOFF, fmt
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.summaries import EngineAgreement, FormulaSummary


def summary_markdown(
    comparisons: Sequence[ModelComparison],
    summaries: Sequence[FormulaSummary],
    agreements: Sequence[EngineAgreement],
    failures: Sequence[tuple[str, str]] = (),
    rtol: float = 1e-9,
    settings: dict[str, dict] | None = None,
) -> str:
    """The Markdown summary, readable without the paper.

    Sections: what this run found (per model, in plain words), the formulas (glossary with the paper's
    equation numbers in brackets), how to read the tables (every column and pose label), one section per
    model (conditions, engine parity, the table, refusals), models that could not be compared, notes (each
    once, with the models it concerns).

    Parameters
    ----------
    comparisons : sequence of ModelComparison
    summaries : sequence of FormulaSummary
    agreements : sequence of EngineAgreement
    failures : sequence of (model, reason)
        Models that could not be compared.
    rtol : float
    settings : dict, optional
        Per model, the run's pose settings (:attr:`koenig_check.run.cross_check.CrossCheck.settings`).

    Returns
    -------
    str
    """
    settings = settings or {}
    parity = {p.model: p for p in agreements}
    by_model: dict[str, list[FormulaSummary]] = {}
    for s in summaries:
        by_model.setdefault(s.model, []).append(s)
    formulas = list(dict.fromkeys(s.formula for s in summaries)) + sorted(
        {r["formula"] for c in comparisons for r in c.refusals} - {s.formula for s in summaries}
    )
    lines = [
        "# koenig-check report",
        "",
        "Kinetic energy of every moving segment of each model, computed by MuJoCo and by Pinocchio from the "
        "same joint positions and rates, and by each formula under test (Yu. Alyushin, *Correction of the "
        "Koenig formula for the kinetic energy of a rotating solid*) from each engine's segment states. "
        f"Tolerance: relative {rtol:g}. Numbers below {ROUNDOFF:g} are rounding and are printed as 0.",
        "",
        "## What this run found",
        "",
        *[" ".join(run_overview(comparisons, summaries, agreements, failures))],
        "",
    ]
    for comp in comparisons:
        f = model_findings(comp, by_model.get(comp.model, []), parity.get(comp.model), rtol)
        lines.append(f"- **{comp.model}** ({f.poses}): {f.engines}.")
        if f.exact:
            lines.append(f"  - exact to rounding: {', '.join(f'`{n}`' for n in f.exact)}.")
        for text in f.inexact:
            name, rest = text.split(": ", 1)
            lines.append(f"  - not exact: `{name}` {rest}.")
        if f.refused:
            lines.append(f"  - refused (does not apply to this motion): {', '.join(f'`{n}`' for n in f.refused)}.")
    for model, reason in failures:
        lines.append(f"- **{model}**: could not be compared: {reason}")
    lines += ["", "## Formulas", "", "The paper's equation numbers are in brackets.", ""]
    lines += [f"- `{g.name}` [{g.equations}]: {g.text}." for g in glossary(formulas)]
    lines += ["", "## How to read the tables", ""]
    lines += [f"- **{name}**: {text}." for name, text in COLUMNS.items()]
    lines += ["", "Pose labels:", ""]
    lines += [f"- `{label}`: {text}." for label, text in POSE_LABELS.items()]
    lines.append("")
    for comp in comparisons:
        p = parity.get(comp.model)
        lines += [f"## {comp.model}", "", f"Conditions: {run_conditions(comp, settings.get(comp.model))}.", ""]
        if p is not None:
            exact = ", ".join(f"{k} {fmt(v)}" for k, v in p.exact_vs_engine.items())
            verdict = "the engines agree" if p.agrees else f"the engines DISAGREE: {p.reason}"
            lines.append(
                f"Engine parity: {verdict}. MuJoCo vs Pinocchio rigid-body energy, largest relative difference "
                f"{fmt(p.rigid_max_rel)} (pose {p.worst_pose}); armature energy, largest difference "
                f"{fmt(p.armature_max_abs)} J; `exact` on each engine's states vs that engine's energy: {exact}."
            )
            lines.append("")
        engines = list(comp.engines)
        lines.append(f"Max rel. error is given as {' / '.join(engines)}.")
        lines.append("")
        lines.append("| " + " | ".join(COLUMN_TITLES) + " |")
        lines.append("| " + " | ".join("---" for _ in COLUMN_TITLES) + " |")
        for row in model_table(by_model.get(comp.model, []), engines, comp.segment_labels):
            lines.append(
                f"| `{row.formula}` [{row.equations}] | {row.verdict} | {row.max_error} | {row.median} | "
                f"{row.over_under} | {row.worst_pose} | {row.worst_segment or '—'} |"
            )
        refusals = refusal_lines(comp)
        if refusals:
            lines.append("")
            lines += [f"- {text}" for text in refusals]
        lines.append("")
    if failures:
        lines += ["## Models that could not be compared", ""]
        lines += [f"- {model}: {reason}" for model, reason in failures]
        lines.append("")
    notes = shared_notes(comparisons)
    if notes:
        lines += ["## Notes", "", "Each note once, with the models it concerns.", ""]
        for note, models in notes:
            lines.append(f"- {note} ({'all models' if not models else ', '.join(models)})")
        lines.append("")
    return "\n".join(lines)


#: Column titles of the per-model tables (defined in :data:`koenig_check.report.content.COLUMNS`).
COLUMN_TITLES = ("formula", "verdict", "max rel. error", "median", "over / under", "worst pose", "worst segment")
