"""The table printed on the terminal, within 100 columns: one row per model, then one row per formula.

When an optional engine (Drake) ran on a model (on every pose, or as tie-breaker where MuJoCo and Pinocchio
disagree), the model rows have a column for its gap to MuJoCo, one per optional engine that ran.  No line is
longer than :data:`LINE_LIMIT` characters, whatever the length of a model's label or of a word in its cause.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from koenig_check.engines.registry import label, optional, reference, required
from koenig_check.findings import Finding, Kind
from koenig_check.line_width import LINE_LIMIT
from koenig_check.report.engine_sets import engine_set_lines
from koenig_check.roundoff import ROUNDOFF, shown
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.cross_check import CrossCheck
from koenig_check.run.stats import relative_error
from koenig_check.run.summaries import FormulaSummary

#: Terminal width the table fits in.
WIDTH = 100


def _number(value: float) -> str:
    value = shown(value)
    return "0" if value == 0 else f"{value:.1e}"


def _wrap(head: str, text: str, width: int = WIDTH) -> list[str]:
    """``head`` then ``text``, continued under the text's first column; words are never cut."""
    indent = " " * min(len(head), width - 24)
    lines = textwrap.wrap(
        text, width=width, initial_indent=head, subsequent_indent=indent, break_long_words=False, break_on_hyphens=False
    )
    return _fold(lines or [head.rstrip()])


def _fold(lines: list[str]) -> list[str]:
    """Cut any line longer than :data:`LINE_LIMIT` (a word longer than a whole line: a path, a label)."""
    out = []
    for line in lines:
        while len(line) > LINE_LIMIT:
            out.append(line[:LINE_LIMIT])
            line = "  " + line[LINE_LIMIT:]
        out.append(line)
    return out


def _row(model: str, width: int, cells: str, text: str) -> list[str]:
    """A model's row: a label wider than its column goes on a line of its own, the cells under it."""
    if len(model) <= width:
        return _wrap(f"{model:{width}s}  {cells}", text)
    return _fold([model]) + _wrap(f"{'':{width}s}  {cells}", text)


def optional_gap(comparison: ModelComparison, engine: str | None = None) -> tuple[float, bool] | None:
    """An optional engine's largest relative gap to MuJoCo's rigid-body energy on a model, if it ran on it.

    Parameters
    ----------
    comparison : ModelComparison
    engine : str, optional
        An optional engine (:func:`koenig_check.engines.registry.optional`); by default the first one.

    Returns
    -------
    (float, bool) or None
        The gap, and whether the engine ran on every pose (False: as tie-breaker on the poses of the
        three-engine verdict, the gap at the pose where the engines differ most); None when it did not run.
    """
    from koenig_check.findings import Kind

    engine = engine or optional()[0]
    gap = comparison.stats.agreement.gaps.get(engine) if comparison.stats is not None else None
    if gap is not None and gap.where:
        return gap.value, True
    for f in comparison.findings:
        if f.kind is Kind.VERDICT and f.element == "rigid-body energy" and {reference(), engine} <= set(f.values):
            mujoco, other = float(f.values[reference()]), float(f.values[engine])
            return float(np.abs(relative_error(np.array([other]), np.array([mujoco])))[0]), False
    return None


def _gap_cell(gap: tuple[float, bool] | None, unable: bool = False) -> str:
    """An optional engine's gap as printed: ``—`` not run, ``*`` as tie-breaker, ``unable`` where it misreads.

    A gap measured on a robot the engine's parser misread (``ENGINE_UNABLE``) is no measure of the file.
    """
    if unable:
        return "unable"
    return "—" if gap is None else _number(gap[0]) + ("" if gap[1] else "*")


def _status(agrees: bool, findings: Sequence[Finding]) -> str:
    """A row's verdict: agree, DISAGREE (the engines, or one departs), UNABLE (a named engine could not check)."""
    if not agrees or any(f.kind is Kind.VERDICT for f in findings):
        return "DISAGREE"
    return "UNABLE" if any(f.kind is Kind.ENGINE_UNABLE for f in findings) else "agree"


def _cause(check: CrossCheck, model: str) -> str:
    from koenig_check.diagnosis.reason import changes_line
    from koenig_check.engines.mujoco.meshes import dropped_meshes_line

    for comparison, parity in zip(check.comparisons, check.agreements, strict=True):
        if parity.model == model:
            why = check.model_reason(comparison, parity, cli=True)  # --rtol named
            short = why.whole().removeprefix(f"{model}: ") if why is not None else ""  # the check not made whole
            changes = changes_line(comparison.findings)  # a model changed to be loaded says so, agreeing or not
            dropped = dropped_meshes_line(comparison.findings)  # so does one loaded without some of its meshes
            return "; ".join(t for t in (short, changes, dropped) if t)
    return ""


@dataclass
class FormulaRow:
    """One formula over a whole run: its worst summary, on how many models it is exact, over/under shares."""

    worst: FormulaSummary
    exact_on: int
    models: int
    over: float
    under: float


def formula_rows(summaries: Sequence[FormulaSummary], poses: dict[str, int]) -> dict[str, FormulaRow]:
    """Per formula, pooled over models and engines (each engine's states against its own energy).

    Parameters
    ----------
    summaries : sequence of FormulaSummary
    poses : dict
        Poses per model (weights of the over/under fractions).

    Returns
    -------
    dict of str to FormulaRow
    """
    worst: dict[str, FormulaSummary] = {}
    per_model: dict[tuple[str, str], bool] = {}
    weights: dict[str, list[tuple[float, float, float]]] = {}
    for s in summaries:
        if s.source != s.reference:
            continue
        if s.formula not in worst or s.max_rel_error > worst[s.formula].max_rel_error:
            worst[s.formula] = s
        per_model[(s.formula, s.model)] = per_model.get((s.formula, s.model), True) and s.agrees
        weights.setdefault(s.formula, []).append((poses.get(s.model, 1), s.over_fraction, s.under_fraction))
    out = {}
    for f, s in worst.items():
        flags = [ok for (formula, _), ok in per_model.items() if formula == f]
        n = sum(w for w, _, _ in weights[f]) or 1
        over = sum(w * o for w, o, _ in weights[f]) / n
        under = sum(w * u for w, _, u in weights[f]) / n
        out[f] = FormulaRow(s, sum(flags), len(flags), over, under)
    return out


def terminal_table(check: CrossCheck) -> str:
    """Render a cross-check for a 100-column terminal.

    First one row per model: do MuJoCo and Pinocchio agree (the largest relative difference of their
    rigid-body kinetic energies, "engine gap"), and each optional engine where it ran (Drake: its gap to
    MuJoCo, a column of its own), does ``exact`` on each engine's segment states reproduce that engine's energy,
    and the root cause when they disagree (wrapped at :data:`WIDTH`; a word is cut only beyond
    :data:`LINE_LIMIT`).  Then one row per formula: the worst relative error of its total energy over every
    model, pose and engine (each engine's states against its own energy), on how many models it is exact, and
    where the worst is.
    Values below :data:`~koenig_check.roundoff.ROUNDOFF` print as 0.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    str
    """
    rtol = check.rtol
    names = [p.model for p in check.agreements] + [m for m, _ in check.failures]
    mw = min(max([len(n) for n in names] + [5]), 40)
    gaps = {e: [optional_gap(c, e) for c in check.comparisons] for e in optional()}
    ran = [e for e, per_model in gaps.items() if any(g is not None for g in per_model)]  # a column each
    widths = {e: max(10, len(e) + 4) for e in ran}
    scale = f"(tolerance {rtol:g} relative; 0: below {ROUNDOFF:g}, rounding)"
    if ran:
        engines = ", ".join(label(e) for e in (*required(), *ran[:-1])) + f" and {label(ran[-1])}"
        columns = "".join(f"{e + ' gap':>{widths[e]}s}  " for e in ran)
        lines = [
            f"Models: do {engines} agree? {scale}",
            "gap: largest relative difference of the engine's rigid-body energy from MuJoCo's",
            f"{'model':{mw}s}  {'verdict':8s}  {'pinocchio gap':>13s}  {columns}{'exact vs own':>12s}  root cause",
        ]
    else:
        lines = [
            f"Models: do MuJoCo and Pinocchio agree? {scale}",
            f"{'model':{mw}s}  {'verdict':8s}  {'engine gap':>10s}  {'exact vs own':>12s}  root cause",
        ]
    tiebreak: list[str] = []  # the engines that ran as tie-breaker on some model

    for i, (p, comparison) in enumerate(zip(check.agreements, check.comparisons, strict=True)):
        # The row says what the exit status says: an engine that departs, or a check asked for and not made,
        # fails the model even where MuJoCo and Pinocchio agree.
        status = _status(p.agrees, comparison.findings)
        exact = max(p.exact_vs_engine.values(), default=0.0)
        if ran:
            row_gaps = {e: gaps[e][i] for e in ran}
            tiebreak += [e for e, g in row_gaps.items() if g is not None and not g[1] and e not in tiebreak]
            unable = {f.engine for f in comparison.findings if f.kind is Kind.ENGINE_UNABLE}
            columns = "".join(f"{_gap_cell(g, e in unable):>{widths[e]}s}  " for e, g in row_gaps.items())
            cells = f"{status:8s}  {_number(p.rigid_max_rel):>13s}  {columns}{_number(exact):>12s}  "
        else:
            cells = f"{status:8s}  {_number(p.rigid_max_rel):>10s}  {_number(exact):>12s}  "
        lines += _row(p.model, mw, cells, _cause(check, p.model) or "—")
    blank = f"{'':>13s}  " + "  ".join(f"{'':>{widths[e]}s}" for e in ran) if ran else f"{'':>10s}"
    for model, reason in check.failures:  # the short failure line, the file as the user gave it
        short = check.failure_lines.get(model, reason).removeprefix(f"{model}: ")
        status = "DISAGREE" if check.disagrees(model) else "FAILED"  # a construct one parser ignores: not an error
        lines += _row(model, mw, f"{status:8s}  {blank}  {'':>12s}  ", short)
    for e in [e for e in ran if e in tiebreak]:
        lines.append(f"*: {label(e)} as tie-breaker on the first poses: its gap where the engines differ most")
    engine_sets = engine_set_lines(check)  # a paragraph of its own after the table, continued two spaces in
    lines += [""] if engine_sets else []
    for line in engine_sets:
        lines += _fold(textwrap.wrap(line, width=WIDTH, subsequent_indent="  ", break_long_words=False))
    if not check.summaries:
        return "\n".join(lines + gravity_rows(check, mw))
    rows = formula_rows(check.summaries, {c.model: c.n_poses for c in check.comparisons})
    refused = {r["formula"] for c in check.comparisons for r in c.refusals}
    fw = max(len(f) for f in [*rows, *refused, "formula"])
    lines += [
        "",
        "Formulas: worst relative error of the total energy, each engine's states vs its own energy",
        f"{'formula':{fw}s}  {'worst':9s}  {'exact':>5s}  {'over/under':>10s}  worst at: model, pose, engine",
    ]
    for formula, row in rows.items():
        s = row.worst
        mark = "=" if s.agrees else "≠"
        share = f"{row.over:.0%}/{row.under:.0%}"
        head = f"{formula:{fw}s}  {mark} {_number(s.max_rel_error):7s}  {f'{row.exact_on}/{row.models}':>5s}  "
        lines += _wrap(f"{head}{share:>10s}  ", f"{s.model}, {s.worst_pose}, {s.source}")
    for formula in sorted(refused - set(rows)):
        lines.append(f"{formula:{fw}s}  {'refused':9s}  {'0':>5s}  {'':>10s}  not defined for these motions")
    lines += [
        f"=: every pose within {rtol:g}; ≠: beyond. exact: models where every pose is within tolerance.",
        "over/under: share of poses where the formula over- / under-estimates the engine's energy.",
    ]
    return "\n".join(lines + gravity_rows(check, mw))


def gravity_rows(check: CrossCheck, mw: int) -> list[str]:
    """The gravity verdict beside the kinetic one: one row per model with each engine's vector and the causes.

    The lines are indented under their heading and the label ends with a colon: a line that starts with a model's
    label, then its cells, is its kinetic row.

    Parameters
    ----------
    check : CrossCheck
    mw : int
        Width of the model column.

    Returns
    -------
    list of str
    """
    from koenig_check.gravity.words import verdict_text

    rows = [(c.model, c.gravity) for c in check.comparisons if c.gravity is not None]
    if not rows:
        return []
    lines = ["", "Gravity: g(q) and V(q)-V(q_ref) of every engine against MuJoCo's, each vector as read from the file"]
    for model, parity in rows:
        status = "agree" if parity.agrees else "DIFFER"
        lines += _wrap(f"  {model}: {status}: ", verdict_text(parity))  # not a table row: the kinetic row is
    return lines
