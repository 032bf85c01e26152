"""The dynamics section of a report: terminal lines, Markdown and JSON out of a :class:`DynamicsResult`."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from koenig_check.engines.specs import reference
from koenig_check.findings import Kind
from koenig_check.implied_dynamics.analysis import ENGINE_PARITY, ENGINES, DynamicsResult
from koenig_check.implied_dynamics.errors import Discrepancy
from koenig_check.implied_dynamics.lagrange import CONFIGURATION_STEP, TIME_STEP_SCALE
from koenig_check.line_width import hanging


def _columns(result: DynamicsResult) -> list[tuple[str, str]]:
    """``(quantity, engine)`` columns: both engines, and each optional engine (Drake) where it was run."""
    engines = [*ENGINES, *(e for e in result.engine_mass if e not in ENGINES)]
    return [(q, e) for q in ("M", "Q*") for e in engines]


def _worst(errors: list[Discrepancy]) -> Discrepancy:
    return max(errors, key=lambda e: e.worst_entry_rel)


def _describe(result: DynamicsResult, e: Discrepancy) -> str:
    return (
        f"{e.quantity}[{result.entry_name(e)}] pose {e.worst_pose} vs {e.engine} by {e.route}: "
        f"{e.worst_entry_error:+.3g} ({e.worst_entry_rel:.2g} of the norm)"
    )


def _cell(result: DynamicsResult, formula: str, quantity: str, engine: str) -> str:
    errs = [e for e in result.errors_of(formula, quantity) if e.engine == engine]
    return f"{max(e.max_rel_error for e in errs):.2g}" if errs else "-"


def terminal_lines(result: DynamicsResult) -> list[str]:
    """One line per formula: largest norm-relative error of ``M`` and ``Q*`` against each engine, worst entry.

    Parameters
    ----------
    result : DynamicsResult

    Returns
    -------
    list of str
    """
    P, nv = result.qvel.shape
    columns = _columns(result)
    lines = [
        f"dynamics of {result.model}: {P} poses, {nv} dofs; largest relative error over poses and routes "
        "(M: Frobenius norm, Q*: Euclidean norm, per pose)",
        f"{'formula':30s} " + " ".join(f"{q + ' vs ' + e:>15s}" for q, e in columns) + "  worst entry",
    ]
    for formula in result.formulas:
        if formula in result.refusals:  # a long row continues under its last column (200 characters a line)
            lines += hanging(f"{formula:30s} ", f"refused: {result.refusals[formula]}")
            continue
        cells = " ".join(f"{_cell(result, formula, q, e):>15s}" for q, e in columns)
        lines += hanging(f"{formula:30s} {cells}  ", _describe(result, _worst(result.errors_of(formula))))
    for other in [e for e in result.engine_mass if e != reference()]:  # Pinocchio, then each optional engine run
        lines.append(
            f"{f'engines (mujoco vs {other})':30s} {_cell(result, ENGINE_PARITY, 'M', other):>15s} {'':>15s} "
            f"{_cell(result, ENGINE_PARITY, 'Q*', other):>15s}"
        )
    lines += [f.message() for f in result.findings if f.kind is Kind.ENGINE_NOT_USED]
    return lines


def to_markdown(result: DynamicsResult) -> str:
    """The dynamics section in Markdown.

    Parameters
    ----------
    result : DynamicsResult

    Returns
    -------
    str
    """
    P, nv = result.qvel.shape
    verdict = "agree" if result.ok else f"**FAIL**: {result.reason()}"
    out = [
        f"## Dynamics: {result.model}",
        "",
        f"{P} random poses with random velocities and accelerations, {nv} dofs. For each formula, the mass matrix "
        "it implies (M = ∂²T/∂q̇², by polarization) and its generalized inertia forces "
        "(Q* = −(d/dt ∂T/∂q̇ − ∂T/∂q), Lagrange's equations, Hamel's form on body-frame angular velocities), "
        "evaluated on each engine's segment states, against each engine's mass matrix and inverse dynamics "
        "(gravity, springs, dampers, constraints off; each engine's own armature taken out). `exact` also by "
        "Kane's form with each engine's Jacobians and accelerations.",
        "",
        f"Verdict on `exact` (M to {result.m_rtol:g}, Q* to {result.q_rtol:g} relative, every route, both "
        f"engines): {verdict}.",
        "",
        f"Steps: ∂T/∂q by central differences of {CONFIGURATION_STEP:g} on the manifold (mj_integratePos); "
        f"d/dt ∂T/∂q̇ by central differences in time with h = {TIME_STEP_SCALE:g}/Ω, "
        "Ω = max(|q̇|∞, √|q̈|∞, 1).",
        "",
        "| formula | route | engine | quantity | max rel. error | median | worst pose | worst entry | "
        "entry error | entry / norm |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for e in result.errors:
        name = "engines" if e.formula == ENGINE_PARITY else f"`{e.formula}`"
        out.append(
            f"| {name} | {e.route} | {e.engine} | {e.quantity} | {e.max_rel_error:.3g} | "
            f"{float(np.median(e.rel_error)):.3g} | {e.max_pose} | {result.entry_name(e)} | "
            f"{e.worst_entry_error:+.3g} | {e.worst_entry_rel:.3g} |"
        )
    if result.refusals:
        out += ["", "Refused:", ""]
        out += [f"- `{f}`: {why}" for f, why in result.refusals.items()]
    return "\n".join(out) + "\n"


def to_json(result: DynamicsResult) -> dict:
    """The errors and refusals as JSON-ready data.

    Parameters
    ----------
    result : DynamicsResult

    Returns
    -------
    dict
    """
    return {
        "model": result.model,
        "ok": result.ok,
        "reason": result.reason(),
        "dofs": list(result.dof_names),
        "m_rtol": result.m_rtol,
        "q_rtol": result.q_rtol,
        "refusals": result.refusals,
        "errors": [
            {
                "formula": e.formula,
                "route": e.route,
                "engine": e.engine,
                "quantity": e.quantity,
                "rel_error": e.rel_error.tolist(),
                "worst_pose": e.worst_pose,
                "worst_entry": result.entry_name(e),
                "worst_entry_error": e.worst_entry_error,
                "worst_entry_rel": e.worst_entry_rel,
            }
            for e in result.errors
        ],
    }


def write_dynamics(out: Path, result: DynamicsResult) -> list[Path]:
    """Write ``dynamics.md`` and ``dynamics.json`` into a directory (created if needed).

    Parameters
    ----------
    out : Path
    result : DynamicsResult

    Returns
    -------
    list of Path
        The files written.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    md, js = out / "dynamics.md", out / "dynamics.json"
    md.write_text(to_markdown(result), encoding="utf-8")
    js.write_text(json.dumps(to_json(result), indent=1, ensure_ascii=False), encoding="utf-8")
    return [md, js]
