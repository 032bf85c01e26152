"""The verdict table printed on the terminal: engines first, then formulas."""

from __future__ import annotations

from koenig_check.api import CrossCheck


def _cell(value: float | None, rtol: float) -> str:
    if value is None:
        return "—"
    return f"= {value:7.1e}" if value <= rtol else f"≠ {value:7.1e}"


def verdict_table(check: CrossCheck) -> str:
    """Render a cross-check for the terminal.

    One line per model says whether the engines agree with each other and with
    ``exact``; then one row per formula and one column per model, each cell the largest
    relative error of the formula's total energy over both engines and every pose
    (``=`` within tolerance, ``≠`` beyond, ``refused`` where the formula does not apply).

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    str
    """
    rtol = check.rtol
    lines = [f"Engines (tolerance {rtol:g}):"]
    for p in check.parities:
        status = "agree" if p.agrees else "DISAGREE"
        lines.append(
            f"  {p.model:34s} {status:8s} MuJoCo vs Pinocchio {p.rigid_max_rel:8.1e}; "
            + ", ".join(f"exact vs {k} {v:8.1e}" for k, v in p.exact_vs_engine.items())
            + ("" if p.agrees else f"\n      {p.reason}")
        )
    for model, reason in check.failures:
        lines.append(f"  {model:34s} FAILED   {reason}")
    models = [c.model for c in check.comparisons]
    if not models:
        return "\n".join(lines)
    worst: dict[tuple[str, str], float] = {}
    for s in check.summaries:
        if s.source != s.reference:
            continue
        key = (s.formula, s.model)
        worst[key] = max(worst.get(key, 0.0), s.max_rel_error)
    refused = {(r["formula"], c.model) for c in check.comparisons for r in c.refusals}
    formulas = list(dict.fromkeys([s.formula for s in check.summaries] + [f for f, _ in refused]))
    short = [m if len(m) <= 14 else m[:13] + "…" for m in models]
    width = max(len(f) for f in formulas) + 2
    lines += [
        "",
        "Formulas: max relative error against each engine's own energy (= within tolerance, ≠ beyond)",
        "formula".ljust(width) + "".join(s.rjust(16) for s in short),
    ]
    for f in formulas:
        cells = []
        for m in models:
            if (f, m) in worst:
                cells.append(_cell(worst[(f, m)], rtol))
            elif (f, m) in refused:
                cells.append("refused")
            else:
                cells.append("—")
        lines.append(f.ljust(width) + "".join(c.rjust(16) for c in cells))
    return "\n".join(lines)
