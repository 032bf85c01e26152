"""``report.html``: one self-contained page with the content of ``summary.md``.

Figures are embedded as base64 PNG (no network); one section per model, its figures beside its table, and
the parity causes.
"""

from __future__ import annotations

import base64
import html
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from koenig_check.findings import Finding, Kind, root_causes
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
from koenig_check.report.matrices import matrices_html, model_agrees, model_anchor
from koenig_check.roundoff import ROUNDOFF, fmt
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.summaries import FormulaSummary

if TYPE_CHECKING:
    from koenig_check.run.cross_check import CrossCheck

_CSS = """
body { font-family: system-ui, -apple-system, 'Segoe UI', sans-serif; margin: 0 auto; max-width: 1500px;
       padding: 1em 2em; color: #1a1a1a; line-height: 1.45; overflow-wrap: break-word; }
h1 { border-bottom: 2px solid #444; }
h2 { border-bottom: 1px solid #bbb; margin-top: 2em; }
code { background: #f2f2f2; padding: 0 .25em; border-radius: 3px; }
table { border-collapse: collapse; font-size: 0.88em; }
th, td { border: 1px solid #ccc; padding: .25em .4em; text-align: left; vertical-align: top; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.pose { overflow-wrap: anywhere; }
tr.exact td.verdict { color: #1b6e20; font-weight: 600; }
tr.differs td.verdict { color: #a12020; font-weight: 600; }
.side { display: grid; grid-template-columns: minmax(0, 8fr) minmax(0, 7fr); gap: 1.2em; align-items: start; }
.side table { font-size: 0.8em; width: 100%; }
@media (max-width: 1000px) { .side { grid-template-columns: minmax(0, 1fr); } }
small { color: #555; }
figure { margin: 0 0 1em 0; }
.wide figure img { max-width: min(100%, 1200px); }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
.side figure img { width: 100%; }
figcaption { font-size: .85em; color: #444; }
.agree { color: #1b6e20; font-weight: 600; }
.disagree { color: #a12020; font-weight: 600; }
ul.causes li { margin-bottom: .2em; }
details summary { cursor: pointer; color: #444; }
dl dt { font-weight: 600; } dl dd { margin: 0 0 .4em 1.5em; }
h1 { margin: .2em 0 .3em 0; font-size: 1.6em; }
p.lead { margin: 0 0 .5em 0; font-size: .92em; }
.matrices { display: grid; grid-template-columns: fit-content(24em) minmax(0, 1fr); gap: 1.5em; align-items: start; }
.matrices.many { grid-template-columns: minmax(0, 1fr); }
.matrices h2 { margin-top: .3em; font-size: 1.15em; }
@media (max-width: 1000px) { .matrices { grid-template-columns: minmax(0, 1fr); } }
table.matrix { font-size: .8em; line-height: 1.25; }
table.matrix td.cell { text-align: center; padding: .15em .25em; white-space: nowrap;
                       font-variant-numeric: tabular-nums; }
table.matrix td.cell a { color: #1a1a1a; text-decoration: none; display: block; }
table.matrix th.row { font-weight: 400; background: #fafafa; overflow-wrap: anywhere; }
table.errors th.row { white-space: nowrap; overflow-wrap: normal; }
table.errors th.model { height: 10.5em; vertical-align: bottom; padding: .2em 0; background: #fafafa; }
table.errors th.model span { writing-mode: vertical-rl; transform: rotate(180deg); font-weight: 400;
                             max-height: 10.5em; overflow: hidden; white-space: nowrap; text-overflow: ellipsis; }
p.legend { font-size: .8em; color: #333; margin: .4em 0; line-height: 1.5; }
.key { display: inline-block; width: 1em; height: .9em; border: 1px solid #999; margin: 0 .3em -.1em 0; }
.bar { display: inline-block; width: 9em; height: .9em; border: 1px solid #999; margin: 0 .3em -.1em .3em; }
section.model > details > summary { margin-bottom: .5em; }
"""


#: Figures shown beside a model's table (the others are wide: full width under it).
_SIDE_FIGURES = ("error_distribution", "engine_gap")


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def image_tag(png: Path, alt: str) -> str:
    """An ``<img>`` holding the PNG file itself as a ``data:`` URI.

    Parameters
    ----------
    png : Path
    alt : str

    Returns
    -------
    str
    """
    data = base64.b64encode(Path(png).read_bytes()).decode("ascii")
    return f'<img src="data:image/png;base64,{data}" alt="{_e(alt)}">'


def _figure(png: Path, caption: str) -> str:
    return f"<figure>{image_tag(png, caption)}<figcaption>{_e(caption)}</figcaption></figure>"


def _table(comp: ModelComparison, summaries: Sequence[FormulaSummary]) -> str:
    titles = ("formula", "verdict", "max rel. error", "median", "over / under", "worst pose", "worst segment")
    engines = list(comp.engines)
    out = [f"<p>Max rel. error: {_e(', then '.join(engines))}.</p>", "<table>"]
    out.append("<thead><tr>" + "".join(f"<th>{_e(t)}</th>" for t in titles) + "</tr></thead><tbody>")
    for row in model_table(summaries, engines, comp.segment_labels):
        maxima = "<br>".join(map(_e, row.max_error.split(" / ")))
        out.append(
            f'<tr class="{row.verdict}"><td><code>{_breakable(row.formula)}</code><br>'
            f"<small>[{_e(row.equations)}]</small></td>"
            f'<td class="verdict">{_e(row.verdict)}</td><td class="num">{maxima}</td>'
            f'<td class="num">{_e(row.median)}</td><td class="num">{_e(row.over_under)}</td>'
            f'<td class="pose">{_e(row.worst_pose)}</td><td class="pose">{_e(row.worst_segment or "—")}</td></tr>'
        )
    out.append("</tbody></table>")
    return "\n".join(out)


#: Causes named in a model's section before the rest is folded ("and N more").
SHOWN_CAUSES = 3


def _cause_item(f: Finding) -> str:
    """One cause, short: the element, what was found, which engine; the values are in the folded list."""
    who = f"<small>({_e(f.engine)}, {_e(f.kind.value)})</small>"
    return f"<li><strong>{_e(f.element)}</strong>: {_e(f.summary)} {who}</li>"


def _causes(comp: ModelComparison) -> str:
    """The causes of a disagreement as a short list: root causes that change the energy first.

    At most :data:`SHOWN_CAUSES` are listed, then "and N more"; every finding that changes the energy, with
    its values, is in a folded list under it.
    """
    energy = [f for f in comp.findings if f.affects_energy]
    roots = root_causes(energy)
    verdicts = [f for f in energy if f.kind is Kind.VERDICT and f not in roots]
    rest = [f for f in energy if f not in roots and f not in verdicts]
    ordered = roots + verdicts + rest
    if not ordered:
        return "<p>Parity causes: no import difference that changes the kinetic energy.</p>"
    shown = ordered[:SHOWN_CAUSES]
    out = ['<p>Parity causes (root causes first):</p><ul class="causes">', *map(_cause_item, shown)]
    if len(ordered) > len(shown):
        out.append(f"<li>and {len(ordered) - len(shown)} more</li>")
    out.append("</ul>")
    details = "".join(f"<li>{_e(f.message())}</li>" for f in ordered)
    summary = f"<summary>every finding, with its values ({len(ordered)})</summary>"
    out.append(f"<details>{summary}<ul>{details}</ul></details>")
    return "".join(out)


def report_html(check: CrossCheck, figures: Mapping[int | None, Sequence[tuple[Path, str]]]) -> str:
    """The page: the content of ``summary.md`` with each model's figures beside its table.

    Parameters
    ----------
    check : CrossCheck
    figures : mapping
        Per position in ``check.comparisons``, that model's figures as (PNG file, caption); the key ``None``
        holds figures of the whole run (shown after the findings).

    Returns
    -------
    str
    """
    rtol = check.rtol
    parity = {p.model: p for p in check.agreements}
    by_model: dict[str, list[FormulaSummary]] = {}
    for s in check.summaries:
        by_model.setdefault(s.model, []).append(s)
    formulas = list(dict.fromkeys(s.formula for s in check.summaries)) + sorted(
        {r["formula"] for c in check.comparisons for r in c.refusals} - {s.formula for s in check.summaries}
    )
    body = [
        "<h1>koenig-check report</h1>",
        '<p class="lead">The kinetic energy of every moving segment of each model from each engine, and from each '
        "formula under test (Yu. Alyushin, <em>Correction of the Koenig formula for the kinetic energy of a rotating "
        f"solid</em>) on each engine's segment states. Tolerance: relative {_e(f'{rtol:g}')}; numbers below "
        f"{_e(f'{ROUNDOFF:g}')} are rounding, printed as 0. Each cell of the matrices links to its model's "
        "section.</p>",
        matrices_html(check),
        "<nav><p>Models: "
        + ", ".join(f'<a href="#{model_anchor(c.model, k)}">{_e(c.model)}</a>' for k, c in enumerate(check.comparisons))
        + "</p></nav>",
        '<section id="findings"><h2>What this run found</h2>',
        "<p>"
        + _code(" ".join(run_overview(check.comparisons, check.summaries, check.agreements, check.failures)))
        + "</p><ul>",
    ]
    for k, comp in enumerate(check.comparisons):
        f = model_findings(comp, by_model.get(comp.model, []), parity.get(comp.model), rtol)
        cls = "agree" if "DISAGREE" not in f.engines else "disagree"
        items = []
        if f.exact:
            items.append("exact to rounding: " + ", ".join(f"<code>{_e(n)}</code>" for n in f.exact))
        for text in f.inexact:
            name, rest = text.split(": ", 1)
            items.append(f"not exact: <code>{_e(name)}</code> {_e(rest)}")
        if f.refused:
            items.append("refused (does not apply): " + ", ".join(f"<code>{_e(n)}</code>" for n in f.refused))
        shown = cls == "disagree" or not model_agrees(comp, check.agreements[k], rtol)  # folded when they agree
        body.append(
            f'<li><details{" open" if shown else ""}><summary><a href="#{model_anchor(comp.model, k)}">'
            f"<strong>{_e(comp.model)}</strong></a> ({_e(f.poses)}): "
            f'<span class="{cls}">{_e(f.engines)}</span>.</summary><ul>'
            + "".join(f"<li>{i}.</li>" for i in items)
            + "</ul></details></li>"
        )
    for model, reason in check.failures:
        body.append(
            f'<li><strong>{_e(model)}</strong>: <span class="disagree">could not be compared</span>: {_e(reason)}</li>'
        )
    body.append("</ul>")
    body += [_figure(png, caption) for png, caption in figures.get(None, ())]
    body.append("</section>")
    body += ['<section id="formulas"><h2>Formulas</h2><p>The paper\'s equation numbers are in brackets.</p><dl>']
    body += [
        f"<dt><code>{_e(g.name)}</code> [{_e(g.equations)}]</dt><dd>{_e(g.text)}.</dd>" for g in glossary(formulas)
    ]
    body += ["</dl></section>", '<section id="reading"><h2>How to read the tables</h2><dl>']
    body += [f"<dt>{_e(name)}</dt><dd>{_e(text)}.</dd>" for name, text in COLUMNS.items()]
    body += ["</dl><p>Pose labels:</p><dl>"]
    body += [f"<dt><code>{_e(label)}</code></dt><dd>{_e(text)}.</dd>" for label, text in POSE_LABELS.items()]
    body.append("</dl></section>")
    for k, comp in enumerate(check.comparisons):
        p = parity.get(comp.model)
        agrees = model_agrees(comp, check.agreements[k], rtol)
        body.append(f'<section class="model" id="{model_anchor(comp.model, k)}"><h2>{_e(comp.model)}</h2>')
        body.append(
            f"<details{'' if agrees else ' open'}><summary>"
            + ("the engines agree: conditions, table and figures" if agrees else "conditions, causes, table, figures")
            + "</summary>"
        )
        body.append(f"<p>Conditions: {_e(run_conditions(comp, check.settings.get(comp.model)))}.</p>")
        if p is not None:
            verdict = (
                '<span class="agree">the engines agree</span>'
                if p.agrees
                else '<span class="disagree">the engines DISAGREE</span> (causes below)'
            )
            exact = ", ".join(f"{k} {fmt(v)}" for k, v in p.exact_vs_engine.items())
            body.append(
                f"<p>Engine parity: {verdict}. MuJoCo vs Pinocchio rigid-body energy, largest relative difference "
                f"{_e(fmt(p.rigid_max_rel))} (pose {_e(p.worst_pose)}); armature energy, largest difference "
                f"{_e(fmt(p.armature_max_abs))} J; <code>exact</code> on each engine's states vs that engine's "
                f"energy: {_e(exact)}.</p>"
            )
        body.append(_causes(comp))
        mine = figures.get(k, ())
        figs = "".join(_figure(png, caption) for png, caption in mine if png.name.startswith(_SIDE_FIGURES))
        wide = "".join(_figure(png, caption) for png, caption in mine if not png.name.startswith(_SIDE_FIGURES))
        body.append(f'<div class="side"><div>{_table(comp, by_model.get(comp.model, []))}</div>')
        body.append(f"<div>{figs}</div></div>" if figs else "</div>")
        if wide:  # the error map and the trajectory are wide: full width under the table they illustrate
            body.append(f'<div class="wide">{wide}</div>')
        refusals = refusal_lines(comp)
        if refusals:
            body.append("<ul>" + "".join(f"<li>{_e(t)}</li>" for t in refusals) + "</ul>")
        body.append("</details></section>")
    if check.failures:
        body.append('<section id="failures"><h2>Models that could not be compared</h2><ul>')
        body += [f"<li>{_e(m)}: {_e(r)}</li>" for m, r in check.failures]
        body.append("</ul></section>")
    notes = shared_notes(check.comparisons)
    if notes:
        body.append('<section id="notes"><h2>Notes</h2><p>Each note once, with the models it concerns.</p><ul>')
        body += [f"<li>{_e(n)} ({_e('all models' if not m else ', '.join(m))})</li>" for n, m in notes]
        body.append("</ul></section>")
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>koenig-check report</title><style>{_CSS}</style></head><body>\n"
        + "\n".join(body)
        + "\n</body></html>\n"
    )


def _breakable(name: str) -> str:
    """Escape a formula name, allowing a line break after each ``:`` and ``_`` (narrow table columns)."""
    return "".join(_e(c) + ("<wbr>" if c in ":_" else "") for c in name)


def _code(text: str) -> str:
    """Escape text, turning `name` into <code>name</code>."""
    parts = _e(text).split("`")
    return "".join(f"<code>{p}</code>" if k % 2 else p for k, p in enumerate(parts))
