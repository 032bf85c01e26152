"""The two matrices ``report.html`` opens on: models × engines coloured by verdict, formulas × models by error.

The first says, per model and engine, whether that engine reads the model as the others do (``agree``), departs
from them (``departs``: a three-engine verdict names it), differs from another engine with no third to tell which
(``differs``), could not check it (``unable``), did not run, or the model could not be loaded (``failed``).  The
second gives, per formula and model, the largest relative error of the formula's total energy against each
engine's own (each engine's states), on a logarithmic colour scale.  Each cell links to the model's section,
where its root cause is.  Nothing here names an engine: the columns are the engines the registry declares
(:func:`koenig_check.engines.specs.specs`) that ran.
"""

from __future__ import annotations

import html
import itertools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from koenig_check.engines.specs import specs
from koenig_check.findings import Kind
from koenig_check.report.terminal import optional_gap
from koenig_check.roundoff import ROUNDOFF, fmt

if TYPE_CHECKING:
    from koenig_check.run.comparison import ModelComparison
    from koenig_check.run.cross_check import CrossCheck
    from koenig_check.run.summaries import EngineAgreement

#: Each verdict of a models × engines cell: its background colour and what it means (the legend).
VERDICTS = {
    "agree": ("#b7e1bd", "agrees with the other engines and with exact"),
    "departs": ("#f08a80", "departs from the engines that agree (root cause in the model's section)"),
    "differs": ("#f7c08a", "differs from another engine, no third engine to tell which reads the file as written"),
    "unable": ("#d7c4ec", "could not check: its parser reads another robot from the file"),
    "not run": ("#f4f4f4", "not run on this model"),
    "failed": ("#9e9e9e", "the model could not be loaded or compared"),
}
#: The logarithmic colour scale of the error matrix: relative errors and their colours, light to dark; between
#: two stops the colour is interpolated in log10 of the error, beyond the ends it is the end's colour.
STOPS = (
    (1e-12, "#ffffcc"),
    (1e-6, "#fed976"),
    (1e-3, "#feb24c"),
    (1e-2, "#fd8d3c"),
    (1e-1, "#e31a1c"),
    (1.0, "#800026"),
)
SCALE = (STOPS[0][0], STOPS[-1][0])
#: Up to this many runs, the two matrices stand side by side (the first screen at 1280 px); beyond, one under the other.
SIDE_BY_SIDE = 12
#: The colour of an error within the tolerance (exact to it), and of a formula refused for a model.
EXACT_COLOUR, REFUSED_COLOUR = "#e3f2e5", "#ffffff"


def model_anchor(model: str, position: int) -> str:
    """The id of a model's section in the page (its label and its position in the run).

    Parameters
    ----------
    model : str
    position : int

    Returns
    -------
    str
    """
    return "model-" + "".join(c if c.isalnum() else "-" for c in model) + f"-{position}"


@dataclass(frozen=True)
class Cell:
    """One cell of a matrix: its verdict (or error), what it shows, its colour, its tooltip and its link.

    ``value`` is the number behind the cell (an engine's gap, a formula's largest relative error), or None.
    """

    verdict: str
    text: str
    colour: str
    title: str
    href: str
    value: float | None = None


def engine_verdict(engine: str, comp: ModelComparison, parity: EngineAgreement | None, rtol: float) -> str:
    """The verdict of one engine on one model (a key of :data:`VERDICTS`).

    Parameters
    ----------
    engine : str
    comp : ModelComparison
    parity : EngineAgreement, optional
    rtol : float

    Returns
    -------
    str
    """
    verdicts = [f for f in comp.findings if f.kind is Kind.VERDICT]
    if any(f.kind is Kind.ENGINE_UNABLE and f.engine == engine for f in comp.findings):
        return "unable"
    reference = comp.engines[0]
    gap = None if engine == reference else optional_gap(comp, engine)
    if engine != reference and gap is None and engine not in comp.engines:
        return "not run"
    if any(f.engine in (engine, "all") for f in verdicts):
        return "departs"
    if parity is not None and parity.exact_vs_engine.get(engine, 0.0) > rtol:
        return "differs"  # the engine's own energy is not the exact energy of its own states
    if verdicts:
        return "agree"  # another engine departs; this one is with the majority
    if gap is not None and gap[0] > rtol:
        return "differs"
    if engine == reference and parity is not None and not parity.agrees:
        return "differs"
    return "agree"


def model_agrees(comp: ModelComparison, parity: EngineAgreement | None, rtol: float) -> bool:
    """Whether every engine that ran on the model agrees (the model's prose is then folded in the page).

    Parameters
    ----------
    comp : ModelComparison
    parity : EngineAgreement, optional
    rtol : float

    Returns
    -------
    bool
    """
    return all(engine_verdict(s.name, comp, parity, rtol) in ("agree", "not run") for s in specs())


def _engine_text(engine: str, comp: ModelComparison, verdict: str) -> str:
    if verdict in ("not run", "failed", "unable"):
        return "—" if verdict == "not run" else verdict
    if engine == comp.engines[0]:
        return "reference"
    gap = optional_gap(comp, engine)
    return "0" if gap is None or gap[0] < ROUNDOFF else f"{gap[0]:.1e}"


def engine_matrix(check: CrossCheck) -> tuple[list[str], list[tuple[str, list[Cell]]]]:
    """The models × engines matrix: the engines that ran on some model, and one row of cells per model.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    (list of str, list of (str, list of Cell))
        The engines (columns, in registry order) and, per model (then per model that failed), its label and cells.
    """
    parity = {id(c): p for c, p in zip(check.comparisons, check.agreements, strict=True)}
    engines = [
        s.name
        for s in specs()
        if any(engine_verdict(s.name, c, parity[id(c)], check.rtol) != "not run" for c in check.comparisons)
    ]
    gravity = any(c.gravity is not None for c in check.comparisons)
    rows = []
    for k, comp in enumerate(check.comparisons):
        p = parity[id(comp)]
        href = "#" + model_anchor(comp.model, k)
        cells = []
        for engine in engines:
            verdict = engine_verdict(engine, comp, p, check.rtol)
            title = f"{comp.model}, {engine}: {VERDICTS[verdict][1]}"
            if verdict in ("departs", "differs", "unable") and p is not None and p.cause:
                title += f"; {p.cause}"
            text = _engine_text(engine, comp, verdict)
            gap = optional_gap(comp, engine) if engine != comp.engines[0] else None
            cells.append(Cell(verdict, text, VERDICTS[verdict][0], title, href, gap[0] if gap else None))
        if gravity:
            cells.append(gravity_cell(comp, href))
        rows.append((comp.model, cells))
    columns = (engines or [s.name for s in specs() if s.required]) + ([GRAVITY] if gravity else [])
    for model, reason in check.failures:
        failed = Cell("failed", "failed", VERDICTS["failed"][0], f"{model}: {reason}", "#failures")
        rows.append((model, [failed] * len(columns)))
    return columns, rows


#: The column after the engines: do the engines' gravity terms agree (:mod:`koenig_check.gravity`)?
GRAVITY = "gravity"


def gravity_cell(comp: ModelComparison, href: str) -> Cell:
    """The gravity cell of one model: agree, differs (its largest gap and the causes' ids), or not run.

    Parameters
    ----------
    comp : ModelComparison
    href : str
        The link to the model's section.

    Returns
    -------
    Cell
    """
    parity = comp.gravity
    if parity is None:
        return Cell("not run", "—", VERDICTS["not run"][0], f"{comp.model}: gravity not compared", href)
    worst = parity.worst
    verdict = "agree" if parity.agrees else "differs"
    title = f"{comp.model}, gravity: g(q) and V of every engine " + ("agree" if parity.agrees else "differ")
    causes = sorted({f.cause for f in parity.findings if f.cause})
    if causes and not parity.agrees:
        title += f"; causes {', '.join(causes)}"
    text = "0" if worst is None or worst.relative <= parity.rtol else f"{worst.relative:.2g}"
    return Cell(verdict, text, VERDICTS[verdict][0], title, href, None if worst is None else worst.relative)


def error_colour(error: float) -> str:
    """The colour of a relative error on the logarithmic scale :data:`STOPS` (light: small, dark: large).

    Parameters
    ----------
    error : float

    Returns
    -------
    str
        ``#rrggbb``.
    """
    x = math.log10(min(max(error, SCALE[0]), SCALE[1]))
    for (e0, c0), (e1, c1) in itertools.pairwise(STOPS):
        lo, hi = math.log10(e0), math.log10(e1)
        if x <= hi:
            t = (x - lo) / (hi - lo)
            rgb0, rgb1 = _rgb(c0), _rgb(c1)
            return "#" + "".join(f"{round(a + t * (b - a)):02x}" for a, b in zip(rgb0, rgb1, strict=True))
    return STOPS[-1][1]


def _rgb(colour: str) -> tuple[int, int, int]:
    r, g, b = (int(colour[i : i + 2], 16) for i in (1, 3, 5))
    return r, g, b


def error_matrix(check: CrossCheck) -> tuple[list[str], list[tuple[str, list[Cell]]]]:
    """The formulas × models matrix of the largest relative error of each formula's total energy.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    (list of str, list of (str, list of Cell))
        The models (columns) and, per formula, its name and one cell per model: the largest relative error over
        the poses and engines (each engine's states against its own energy), or ``refused``.
    """
    from koenig_check.run.summaries import summarize

    models = [c.model for c in check.comparisons]
    worst: dict[tuple[str, int], float] = {}
    formulas: list[str] = []
    for k, comp in enumerate(check.comparisons):  # each run its own column, even when two share a label
        for s in (s for s in summarize(comp, check.rtol) if s.source == s.reference):
            if s.formula not in formulas:
                formulas.append(s.formula)
            worst[(s.formula, k)] = max(worst.get((s.formula, k), 0.0), s.max_rel_error)
    rows = []
    for formula in formulas:
        cells = []
        for k, comp in enumerate(check.comparisons):
            href = "#" + model_anchor(comp.model, k)
            error = worst.get((formula, k))
            if error is None:
                cells.append(Cell("refused", "—", REFUSED_COLOUR, f"{formula} on {comp.model}: refused", href))
                continue
            exact = error <= check.rtol
            colour = EXACT_COLOUR if exact else error_colour(error)
            text = fmt(error, ".0e") if error >= ROUNDOFF else "0"
            title = f"{formula} on {comp.model}: largest relative error {fmt(error)}"
            cells.append(Cell("exact" if exact else "differs", text, colour, title, href, error))
        rows.append((formula, cells))
    return models, rows


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def _dark(colour: str) -> bool:
    r, g, b = _rgb(colour)
    return 0.299 * r + 0.587 * g + 0.114 * b < 140


def _cell_html(cell: Cell) -> str:
    ink = ' style="color:#fff"' if _dark(cell.colour) else ""
    value = "" if cell.value is None else f' data-value="{cell.value!r}"'
    return (
        f'<td class="cell {_e(cell.verdict.replace(" ", "-"))}" style="background:{cell.colour}"{value} '
        f'title="{_e(cell.title)}"><a href="{_e(cell.href)}"{ink}>{_e(cell.text)}</a></td>'
    )


def matrices_html(check: CrossCheck) -> str:
    """Both matrices side by side, with their legends: the first screen of ``report.html``.

    Parameters
    ----------
    check : CrossCheck

    Returns
    -------
    str
    """
    from koenig_check.engines.registry import label

    engines, rows = engine_matrix(check)
    layout = "matrices" if len(check.comparisons) <= SIDE_BY_SIDE else "matrices many"
    out = [f'<section id="matrices" class="{layout}"><div>', "<h2>Do the engines agree?</h2>"]
    out.append('<table class="matrix engines"><thead><tr><th>model</th>')
    out += [f"<th>{_e(label(e))}</th>" for e in engines]
    out.append("</tr></thead><tbody>")
    for model, cells in rows:
        out.append(f'<tr><th class="row">{_e(model)}</th>' + "".join(map(_cell_html, cells)) + "</tr>")
    out.append('</tbody></table><p class="legend">')
    present = {cell.verdict for _, cells in rows for cell in cells}
    out += [
        f'<span class="key" style="background:{c}"></span>{_e(v)} <small>({_e(t)})</small><br>'
        for v, (c, t) in VERDICTS.items()
        if v in present
    ]
    reference = label(check.comparisons[0].engines[0]) if check.comparisons else "the reference"
    gravity = f"; {GRAVITY}: the largest relative gap of g(q) or V between the engines" if GRAVITY in engines else ""
    out.append(f"numbers: each engine's largest relative gap to {_e(reference)}'s rigid-body energy{gravity}</p></div>")
    models, formula_rows = error_matrix(check)
    out += ["<div><h2>How far is each formula from the engines?</h2>", '<table class="matrix errors"><thead><tr>']
    out.append(
        "<th>formula</th>" + "".join(f'<th class="model" title="{_e(m)}"><span>{_e(m)}</span></th>' for m in models)
    )
    out.append("</tr></thead><tbody>")
    for formula, cells in formula_rows:
        head = f'<tr><th class="row"><code>{_e(formula)}</code></th>'
        out.append(head + "".join(map(_cell_html, cells)) + "</tr>")
    out.append("</tbody></table>")
    ticks = [10.0**e for e in range(round(math.log10(SCALE[0])), round(math.log10(SCALE[1])) + 1)]
    stops = ", ".join(error_colour(t) for t in ticks)
    out.append(
        f'<p class="legend">largest relative error of the total energy over the poses and engines (each engine\'s '
        f'states against its own energy), log scale: <span class="key" style="background:{EXACT_COLOUR}"></span>'
        f'within the tolerance {_e(f"{check.rtol:g}")}; <span class="bar" style="background:linear-gradient(to right, '
        f'{stops})"></span> {_e(f"{ticks[0]:g}")} … {_e(f"{ticks[-1]:g}")}; — refused</p></div></section>'
    )
    return "\n".join(out)
