"""What a model's comparison says, read from its merged statistics.

Per formula, its errors (:class:`FormulaSummary`); and whether the engines agree with each other and each with
``exact`` on its own states (:class:`EngineAgreement`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from koenig_check.diagnosis.reason import disagreement_cause, ordered_causes, rounding_hint
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.records import RecordTable
from koenig_check.run.stats import DEFAULT_RTOL, ModelStats


@dataclass(frozen=True)
class FormulaSummary:
    """Summary of one formula against one reference, totals over all poses of a model."""

    model: str
    formula: str
    source: str
    reference: str
    max_rel_error: float
    median_rel_error: float
    over_fraction: float
    under_fraction: float
    worst_pose: str
    worst_segment: str | None
    agrees: bool


def summarize(comparison: ModelComparison, rtol: float = DEFAULT_RTOL) -> list[FormulaSummary]:
    """Per formula, source and reference: max/median relative error, over/under fractions, worst pose/segment.

    Read from the comparison's merged statistics when they were accumulated at this ``rtol``,
    otherwise from its records (see :func:`summarize_records`).

    Parameters
    ----------
    comparison : ModelComparison
    rtol : float
        A formula over- (under-) estimates at a pose when its signed relative error is
        above ``rtol`` (below ``-rtol``); it agrees when every pose is within ``rtol``.

    Returns
    -------
    list of FormulaSummary
    """
    if comparison.stats is not None and comparison.stats.rtol == rtol:
        return summaries_from_stats(comparison.model, comparison.stats)
    return summarize_records(comparison.records, rtol, comparison.model)


def summaries_from_stats(model: str, stats: ModelStats) -> list[FormulaSummary]:
    """The summaries of one model from its merged statistics.

    Parameters
    ----------
    model : str
    stats : ModelStats

    Returns
    -------
    list of FormulaSummary
        Formula by formula (in order of first appearance), then source, then reference.
    """
    out = []
    for (formula, source, reference), g in stats.kept_groups().items():
        seg = stats.worst_segments.get((formula, source))
        out.append(
            FormulaSummary(
                model=model,
                formula=formula,
                source=source,
                reference=reference,
                max_rel_error=g.worst.value,
                median_rel_error=g.sketch.median(),
                over_fraction=g.over / g.n,
                under_fraction=g.under / g.n,
                worst_pose=g.worst.where,
                worst_segment=seg.where if seg is not None and seg.value > 0 else None,
                agrees=bool(g.worst.value <= stats.rtol),
            )
        )
    rank = {f: k for k, f in enumerate(dict.fromkeys(s.formula for s in out))}
    return sorted(out, key=lambda s: rank[s.formula])


def summarize_records(
    records: RecordTable, rtol: float = DEFAULT_RTOL, model: str | None = None
) -> list[FormulaSummary]:
    """The summaries computed from a full record table (the reference route for the streamed ones).

    Parameters
    ----------
    records : RecordTable
        One model's records; ``worst_segment`` needs its per-segment records.
    rtol : float
    model : str, optional
        The label written in the summaries (default: the records' model column).

    Returns
    -------
    list of FormulaSummary
    """
    out: list[FormulaSummary] = []
    if not len(records):
        return out
    rec = records.columns
    total = rec["scope"] == "total"
    for formula in dict.fromkeys(rec["formula"].tolist()):
        f_mask = rec["formula"] == formula
        for source in dict.fromkeys(rec["source"][f_mask].tolist()):
            fs = f_mask & (rec["source"] == source)
            seg = fs & ~total
            worst_segment = None
            if seg.any():
                k = int(np.flatnonzero(seg)[np.argmax(rec["abs_error"][seg])])
                if rec["abs_error"][k] > 0:
                    worst_segment = f"{rec['scope'][k]} @ {rec['pose'][k]}"
            for reference in dict.fromkeys(rec["reference"][fs & total].tolist()):
                rows = np.flatnonzero(fs & total & (rec["reference"] == reference))
                rel = rec["rel_error"][rows]
                signed = rec["signed_error"][rows]
                ref = np.abs(rec["reference_value"][rows])
                out.append(
                    FormulaSummary(
                        model=model or str(rec["model"][rows[0]]),
                        formula=formula,
                        source=source,
                        reference=reference,
                        max_rel_error=float(rel.max()),
                        median_rel_error=float(np.median(rel)),
                        over_fraction=float(np.mean(signed > rtol * ref)),
                        under_fraction=float(np.mean(signed < -rtol * ref)),
                        worst_pose=str(rec["pose"][rows[int(np.argmax(rel))]]),
                        worst_segment=worst_segment,
                        agrees=bool(rel.max() <= rtol),
                    )
                )
    return out


@dataclass(frozen=True)
class EngineAgreement:
    """Engine-versus-engine and engine-versus-exact agreement of one model.

    ``reason`` says in full why they do not agree (with the cause's values); ``gap`` says it in a few words, for
    the one-line reason (:func:`koenig_check.diagnosis.reason.short_reason`).  ``reason`` is built from
    ``symptoms`` (each way the engines differ, one sentence each) and ``cause`` (the known cause, or empty):
    read those, never ``reason`` cut apart.  ``causes`` holds the ids of the catalogued causes among them
    (:func:`koenig_check.causes.cause`), the most important first.
    """

    model: str
    rigid_max_rel: float  # MuJoCo rigid energy vs Pinocchio rigid energy
    armature_max_abs: float  # |armature energy difference| (J)
    exact_vs_engine: dict[str, float]  # per engine: exact on its states vs its own energy
    worst_pose: str
    agrees: bool
    reason: str
    gap: str = ""
    symptoms: tuple[str, ...] = ()
    cause: str = ""
    causes: tuple[str, ...] = ()


def engine_agreement(comparison: ModelComparison, rtol: float = DEFAULT_RTOL) -> EngineAgreement:
    """Check that the engines agree with each other and each with ``exact`` on its own states.

    Parameters
    ----------
    comparison : ModelComparison
    rtol : float

    Returns
    -------
    EngineAgreement
        ``agrees`` with a one-line ``reason`` when it does not.
    """
    if comparison.stats is None:
        raise ValueError(f"{comparison.model}: no statistics to read the engines' agreement from")
    p = comparison.stats.agreement
    reasons = []
    if p.rigid.value > rtol:
        mj, pn = p.rigid.extra
        reasons.append(
            f"MuJoCo and Pinocchio rigid-body energies differ by {p.rigid.value:.3g} relative at pose "
            f"{p.rigid.where} (MuJoCo {mj:.9g} J, Pinocchio {pn:.9g} J)"
        )
    if p.armature_scaled > rtol:
        mj, pn = p.armature.extra
        reasons.append(
            f"armature energies differ by {p.armature.value:.3g} J at pose {p.armature.where} "
            f"(MuJoCo {mj:.6g} J, Pinocchio {pn:.6g} J)"
        )
    for name, value in p.self_rel.items():
        if value > rtol:
            reasons.append(f"{name}: exact on its own segment states differs from its own energy by {value:.3g}")
    gap = _gap(p, rtol) if reasons else ""
    cause = disagreement_cause(comparison.findings) if reasons else ""
    return EngineAgreement(
        comparison.model,
        float(p.rigid.value),
        float(p.armature.value),
        dict(p.self_rel),
        p.rigid.where,
        not reasons,
        "; ".join(reasons + ([f"cause: {cause}"] if cause else [])),
        gap,
        tuple(reasons),
        cause,
        tuple(dict.fromkeys(f.cause for f in ordered_causes(comparison.findings) if f.cause)) if reasons else (),
    )


def gap_words(comparison: ModelComparison, rtol: float = DEFAULT_RTOL, cli: bool = False) -> str:
    """The engines' disagreement on a model in a few words (empty when they agree), the option spelt for the CLI.

    Parameters
    ----------
    comparison : ModelComparison
    rtol : float
    cli : bool
        The rounding hint names ``--rtol`` (the command line), else ``rtol=`` (the API).

    Returns
    -------
    str
    """
    return _gap(comparison.stats.agreement, rtol, cli) if comparison.stats is not None else ""


def _gap(p: Any, rtol: float, cli: bool = False) -> str:
    """The engines' disagreement in a few words, with the rounding hint when a written file's rounding explains it."""
    parts = []
    if p.rigid.value > rtol:
        parts.append(f"MuJoCo and Pinocchio differ by {p.rigid.value:.2g} relative (pose {p.rigid.where})")
    if p.armature_scaled > rtol:
        parts.append(f"their armature energies by {p.armature.value:.2g} J")
    parts += [f"{name}'s exact differs from its own energy by {v:.2g}" for name, v in p.self_rel.items() if v > rtol]
    hint = rounding_hint(float(p.rigid.value), rtol, cli=cli) if len(parts) == 1 else ""
    return hint or ", ".join(parts)  # within a written file's rounding, the hint says the gap and what to do
