"""What the report says, independent of its format: findings in words, glossary, column definitions, notes.

``summary.md`` (:mod:`koenig_check.report`) and ``report.html`` (:mod:`koenig_check.report.html`) render
the same content from these functions.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from koenig_check.formulas import FORMULAS
from koenig_check.roundoff import ROUNDOFF, fmt
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.summaries import EngineAgreement, FormulaSummary

#: Plain-words description of each formula family (the registry name's part before the first ':').
_BASE_TEXT = {
    "exact": "the textbook kinetic energy ½ m v_C² + ½ ω·I_C ω with the full inertia tensor of the current pose",
    "koenig_world": "Koenig's formula read literally: moments of inertia about world axes through the centre of "
    "mass at the current pose, products of inertia left out",
    "koenig_principal": "Koenig's formula in the segment's principal central axes with its body-frame angular "
    "velocity (the textbook form)",
    "alyushin_current": "the paper's corrected formula with the axial and centrifugal moments of the current pose",
    "alyushin_paper": "the paper's recipe: axial moments taken from the initial pose (claimed invariant by (29)), "
    "centrifugal moments updated by (36) with rotation angles Δθ",
    "alyushin_pole": "the paper's energy about the joint anchor (the pole P) instead of the centre of mass",
    "planar": "the paper's plane-parallel formula; refused where a segment's motion is not plane-parallel",
    "point_masses": "the energy summed over an equimomental set of point masses per segment, each point's "
    "velocity from the engine",
}
_CONVENTION_TEXT = {
    "rotvec": "Δθ = the rotation vector from the initial pose",
    "euler_xyz": "Δθ = x-y-z Euler angles from the initial pose",
    "integrated": "Δθ = time integral of the world ω components along a trajectory (trajectories only)",
    "current": "moments of the current pose",
    "paper": "the paper's recipe (initial moments, (33))",
}

#: Pose labels, as they appear in tables, records and figures.
POSE_LABELS = {
    "random-i": "the i-th random pose: joint positions uniform within limits (unlimited hinges over [-π, π], "
    "unlimited slides and free-joint positions within ±1 of the reference), orientations uniform, joint rates "
    "normal (std: the velocity scale), drawn from the seed",
    "grid-i": "the i-th pose of an N × N sweep of two joints (the first joint varies slowest); the swept joints "
    "turn at a fixed rate, the others rest",
    "traj-i": "the i-th sample of a torque-free MuJoCo simulation with gravity off, from the reference pose",
    "key:NAME": "the model's keyframe NAME; at rest, it gets the joint rates of the random pose of its index",
}

#: The columns of the per-model tables.
COLUMNS = {
    "formula": "the formula's name (glossary above)",
    "verdict": "exact: within the tolerance on every pose for both engines; differs: beyond it somewhere; "
    "refused: the formula does not apply to this motion",
    "max rel. error": "largest |formula − engine| / engine of the total kinetic energy over all poses, with each "
    "engine's own segment states and energy (armature excluded), MuJoCo / Pinocchio",
    "median": "median of that relative error over the poses (the engine with the larger maximum)",
    "over / under": "share of poses where the formula over- / under-estimates the engine's energy by more than "
    "the tolerance (the sign of the error)",
    "worst pose": "the pose label of the largest error of the total",
    "worst segment": "the segment (the link or body as the file names it, and the joint that moves it) with the "
    "largest per-segment error, and the pose where it occurs",
}


@dataclass(frozen=True)
class GlossaryEntry:
    """One formula of the glossary: name, the paper's equations, one line of plain words."""

    name: str
    equations: str
    text: str


def glossary(names: Sequence[str] | None = None) -> list[GlossaryEntry]:
    """The glossary of formula names (all, or those given), with the paper's equation numbers.

    Parameters
    ----------
    names : sequence of str, optional

    Returns
    -------
    list of GlossaryEntry
    """
    entries = []
    for name in names or list(FORMULAS):
        parts = name.split(":")
        text = _BASE_TEXT[parts[0]]
        extra = [_CONVENTION_TEXT[p] for p in parts[1:] if p in _CONVENTION_TEXT]
        if extra:
            text += "; " + "; ".join(extra)
        entries.append(GlossaryEntry(name, FORMULAS[name].equations, text))
    return entries


def _size(x: float) -> str:
    """A relative error in words: a percentage from 0.1 %, else a power of ten; round-off as 0."""
    if x >= 1e-3:
        return f"{100 * x:.3g} %"
    return fmt(x, ".1e")


@dataclass(frozen=True)
class ModelFindings:
    """What the run found on one model, in plain words."""

    model: str
    poses: str
    engines: str
    exact: list[str]
    inexact: list[str]
    refused: list[str]


def describe_poses(comp: ModelComparison) -> str:
    """How many poses of which kind, in words (``20 random poses``)."""
    kind = {"random": "random poses", "grid": "poses of a two-joint grid", "trajectory": "trajectory samples"}
    text = f"{comp.n_poses} {kind.get(comp.pose_kind, comp.pose_kind + ' poses')}"
    if comp.poses is not None and comp.poses.grid is not None:
        a, b = comp.poses.grid["joints"]
        n = comp.poses.grid["shape"][0]
        text += f" ({n} × {n}: {a} × {b})"
    return text


def model_findings(
    comp: ModelComparison, summaries: Sequence[FormulaSummary], parity: EngineAgreement | None, rtol: float
) -> ModelFindings:
    """The plain-words findings of one model.

    Parameters
    ----------
    comp : ModelComparison
    summaries : sequence of FormulaSummary
        This model's summaries.
    parity : EngineAgreement, optional
    rtol : float

    Returns
    -------
    ModelFindings
    """
    from koenig_check.diagnosis.reason import lead_line
    from koenig_check.engines.registry import label as engine_label

    if parity is None:
        engines = "no engine comparison"
    elif parity.agrees and fmt(parity.rigid_max_rel) == "0":
        engines = (
            f"MuJoCo and Pinocchio agree to rounding (their rigid-body kinetic energies differ by less than "
            f"{ROUNDOFF:g}, relative)"
        )
    elif parity.agrees:
        engines = (
            f"MuJoCo and Pinocchio agree: their rigid-body kinetic energies differ by at most "
            f"{_size(parity.rigid_max_rel)} (relative)"
        )
    else:
        engines = f"MuJoCo and Pinocchio DISAGREE: {parity.reason}"
    lead = lead_line(comp.findings, counted=True)
    if lead:  # an engine asked for and unable, then the verdicts after the number of engines that voted
        engines += f"; {lead}"
    exact, inexact = [], []
    for formula, rows in _by_formula(summaries).items():
        if all(s.agrees for s in rows):
            exact.append(formula)
            continue
        # One engine's numbers throughout (the one with the largest error, as in the table beside this line):
        # shares of different engines do not add up to the poses of either.
        worst = max(rows, key=lambda s: s.max_rel_error)
        over, under = worst.over_fraction, worst.under_fraction
        sign = "always over" if under == 0 else "always under" if over == 0 else "both signs"
        inexact.append(
            f"{formula}: up to {_size(worst.max_rel_error)} (median {_size(worst.median_rel_error)}), {sign}: "
            f"over on {over:.0%} of poses, under on {under:.0%} ({engine_label(worst.source)})"
        )
    refused = sorted({r["formula"] for r in comp.refusals})
    return ModelFindings(comp.model, describe_poses(comp), engines, exact, inexact, refused)


def _by_formula(summaries: Sequence[FormulaSummary]) -> dict[str, list[FormulaSummary]]:
    out: dict[str, list[FormulaSummary]] = {}
    for s in summaries:
        if s.source == s.reference:
            out.setdefault(s.formula, []).append(s)
    return out


@dataclass(frozen=True)
class TableRow:
    """One formula's row of a model's table (cells as text)."""

    formula: str
    equations: str
    verdict: str
    max_error: str
    median: str
    over_under: str
    worst_pose: str
    worst_segment: str


def model_table(
    summaries: Sequence[FormulaSummary], engines: Sequence[str], segment_labels: Mapping[str, str] | None = None
) -> list[TableRow]:
    """The rows of one model's table (see :data:`COLUMNS`).

    Parameters
    ----------
    summaries : sequence of FormulaSummary
        This model's summaries.
    engines : sequence of str
    segment_labels : mapping of str to str, optional
        Each segment (keyed by its joint) as the user wrote it (:attr:`ModelComparison.segment_labels`).

    Returns
    -------
    list of TableRow
    """
    rows = []
    for formula, group in _by_formula(summaries).items():
        by_engine = {s.source: s for s in group}
        worst = max(group, key=lambda s: s.max_rel_error)
        verdict = "exact" if all(s.agrees for s in group) else "differs"
        maxima = " / ".join(fmt(by_engine[e].max_rel_error, ".2e") if e in by_engine else "—" for e in engines)
        segment = "" if verdict == "exact" else _segment_at(worst.worst_segment or "", segment_labels or {})
        rows.append(
            TableRow(
                formula,
                FORMULAS[formula].equations,
                verdict,
                maxima,
                fmt(worst.median_rel_error, ".2e"),
                f"{worst.over_fraction:.0%} / {worst.under_fraction:.0%}",
                worst.worst_pose,
                segment,
            )
        )
    return rows


def _segment_at(where: str, labels: Mapping[str, str]) -> str:
    """``"joint @ pose"`` as ``"link L (joint J) at pose"``: the segment as the user wrote it."""
    segment, _, pose = where.partition(" @ ")
    name = labels.get(segment, segment).removeprefix("segment ")
    return f"{name} at {pose}" if pose else name


def refusal_lines(comp: ModelComparison) -> list[str]:
    """Each refused formula once, with the engines whose states it was refused on and the reason."""
    grouped: dict[tuple[str, str], list[str]] = {}
    for r in comp.refusals:
        grouped.setdefault((r["formula"], r["reason"]), []).append(r["source"])
    return [f"{f} refused on {' and '.join(s)} states: {reason}" for (f, reason), s in grouped.items()]


def shared_notes(comparisons: Sequence[ModelComparison]) -> list[tuple[str, list[str]]]:
    """Every note once, with the models it concerns (all models: an empty list).

    Parameters
    ----------
    comparisons : sequence of ModelComparison

    Returns
    -------
    list of (note, models)
    """
    seen: dict[str, list[str]] = {}
    for comp in comparisons:
        for note in dict.fromkeys(comp.notes):
            seen.setdefault(note, []).append(comp.model)
    everyone = [c.model for c in comparisons]
    return [(note, [] if models == everyone and len(everyone) > 1 else models) for note, models in seen.items()]


def run_conditions(comp: ModelComparison, settings: dict | None = None) -> str:
    """The conditions of one model's poses in one line: kind, count, seed, joint rates, gravity.

    Parameters
    ----------
    comp : ModelComparison
    settings : dict, optional
        The run's settings (``seed``, ``velocity_scale``, ``duration``) when known.

    Returns
    -------
    str
    """
    settings = settings or {}
    parts = [describe_poses(comp)]
    ps = comp.poses
    if comp.pose_kind == "random":
        parts.append(f"seed {settings.get('seed', 0)}")
        parts.append(f"joint rates normal with std {settings.get('velocity_scale', 1.0):g} (rad/s or m/s)")
    elif comp.pose_kind == "grid" and ps is not None:
        rates = sorted({float(v) for v in ps.qvel[0] if v != 0})
        rate = ", ".join(f"{r:g}" for r in rates) or "0"
        parts.append(f"both swept joints turn at {rate} rad/s, the other joints rest")
    elif comp.pose_kind == "trajectory" and ps is not None and ps.times is not None:
        parts.append(
            f"{ps.times[-1]:.3g} s of torque-free MuJoCo simulation, gravity off, "
            f"initial joint rates random (seed {settings.get('seed', 0)}, "
            f"std {settings.get('velocity_scale', 1.0):g})"
        )
    return "; ".join(parts)


def run_overview(
    comparisons: Sequence[ModelComparison],
    summaries: Sequence[FormulaSummary],
    agreements: Sequence[EngineAgreement],
    failures: Sequence[tuple[str, str]] = (),
) -> list[str]:
    """The run in a few sentences: engines, formulas exact everywhere, exact nowhere, the largest error.

    Parameters
    ----------
    comparisons : sequence of ModelComparison
    summaries : sequence of FormulaSummary
    agreements : sequence of EngineAgreement
    failures : sequence of (model, reason)

    Returns
    -------
    list of str
    """
    n = len(comparisons)
    if not n:
        return [f"No model could be compared ({len(failures)} failed)."]
    agree = sum(p.agrees for p in agreements)
    lines = [
        f"{n} model run(s) compared"
        + (f", {len(failures)} could not be" if failures else "")
        + f". MuJoCo and Pinocchio agree on {agree} of {len(agreements)}"
        + ("." if agree == len(agreements) else ": see the models marked DISAGREE.")
    ]
    groups = _by_formula(summaries)
    models_of = {f: {s.model for s in rows} for f, rows in groups.items()}
    exact_on = {f: {s.model for s in rows} - {s.model for s in rows if not s.agrees} for f, rows in groups.items()}
    everywhere = [f for f in groups if exact_on[f] == models_of[f]]
    nowhere = [f for f in groups if not exact_on[f]]

    def _where(f: str) -> str:
        k = len(models_of[f])
        return f"`{f}`" if k == n else f"`{f}` (applies to {k} of {n}, refused or skipped elsewhere)"

    if everywhere:
        lines.append("Exact to rounding on every model it applies to: " + ", ".join(map(_where, everywhere)) + ".")
    if nowhere:
        lines.append("Exact on no model: " + ", ".join(f"`{f}`" for f in nowhere) + ".")
    others = [f for f in groups if f not in everywhere and f not in nowhere]
    if others:
        lines.append(
            "Exact on some models only: "
            + ", ".join(f"`{f}` ({len(exact_on[f])} of {len(models_of[f])})" for f in others)
            + "."
        )
    worst = max((s for rows in groups.values() for s in rows), key=lambda s: s.max_rel_error, default=None)
    if worst is not None and not worst.agrees:
        lines.append(
            f"Largest error: `{worst.formula}`, {_size(worst.max_rel_error)} on {worst.model} at pose "
            f"{worst.worst_pose} ({worst.source})."
        )
    return lines
