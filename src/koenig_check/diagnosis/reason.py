"""The reason text of a diagnosis: which findings explain a disagreement, in which order, in one line."""

from __future__ import annotations

from collections.abc import Sequence

from koenig_check.findings import Finding, Kind, root_causes

#: Kinds of per-segment import differences (symptoms, after the root causes in a reason).
_SYMPTOMS = (Kind.MASS, Kind.COM, Kind.INERTIA, Kind.ANCHOR, Kind.AXIS, Kind.ARMATURE, Kind.SEGMENTS, Kind.FRAME)


def disagreement_cause(findings: Sequence[Finding], limit: int = 3) -> str:
    """The cause of an engine disagreement, chosen from the findings, for the one-line reason.

    Root causes that change the energy come first (a repaired or compiler-altered inertia, a
    construct one parser ignores), then the per-segment import differences, then each engine's
    inconsistencies with itself.

    Parameters
    ----------
    findings : sequence of Finding
    limit : int
        At most this many findings are named (the count of the others is given).

    Returns
    -------
    str
        Empty when no finding explains a change of energy.
    """
    energy = [f for f in findings if f.affects_energy]
    roots = [f for f in root_causes(energy) if f.affects_energy]
    symptoms = [f for f in energy if f.kind in _SYMPTOMS and f not in roots]
    selves = [f for f in energy if f.kind is Kind.SELF_CONSISTENCY and f not in roots]
    chosen: list[Finding] = []
    for f in roots + symptoms + selves:
        if f not in chosen:
            chosen.append(f)
    text = "; ".join(f.message() for f in chosen[:limit])
    if len(chosen) > limit:
        text += f"; and {len(chosen) - limit} more finding(s)"
    return text


#: Findings that lead a reason: a check the user asked for that was not made, an engine that departs.
LEADING_KINDS = (Kind.ENGINE_UNABLE, Kind.VERDICT)


def lead_line(findings: Sequence[Finding]) -> str:
    """The head of a one-line reason (empty when none): checks asked for and not made, then the verdicts.

    Parameters
    ----------
    findings : sequence of Finding

    Returns
    -------
    str
    """
    ordered = [f for kind in LEADING_KINDS for f in findings if f.kind is kind]
    return "; ".join(f.message() for f in ordered)


def engine_usage(findings: Sequence[Finding], engine: str = "drake") -> str:
    """Why an optional engine was not used on a model, from its findings (empty when it was used).

    Parameters
    ----------
    findings : sequence of Finding
    engine : str

    Returns
    -------
    str
    """
    for f in findings:
        if f.engine == engine and f.kind is Kind.ENGINE_NOT_USED:
            return f.summary
    return ""


def changes_line(findings: Sequence[Finding], shown: int = 4) -> str:
    """The links changed so that MuJoCo loads the model (``REPAIR``), and whether each can change the energy.

    Parameters
    ----------
    findings : sequence of Finding
    shown : int
        At most this many links are named per group (the count of the others is given).

    Returns
    -------
    str
        Empty when nothing was changed.
    """
    repairs = [f for f in findings if f.kind is Kind.REPAIR]
    if not repairs:
        return ""
    groups = (
        ("moving: can change MuJoCo's energy", [f.element for f in repairs if f.segments]),
        ("welded to the world: cannot change the energy", [f.element for f in repairs if not f.segments]),
    )
    parts = []
    for what, elements in groups:
        if elements:
            more = f" (+{len(elements) - shown} more)" if len(elements) > shown else ""
            parts.append(f"{', '.join(elements[:shown])}{more} ({what})")
    return "changed so that MuJoCo loads it (Pinocchio keeps the file's values): " + "; ".join(parts)
