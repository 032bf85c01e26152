"""The gravity verdict in words: one line for the terminal table, summary.md, report.html and the exit reason."""

from __future__ import annotations

from koenig_check.findings import Finding
from koenig_check.gravity.parity import GravityParity
from koenig_check.roundoff import fmt

_QUANTITY = {"g(q)": "g(q)", "dV": "V(q)-V(q_ref)"}


def causes(parity: GravityParity) -> list[Finding]:
    """The findings that explain the gravity gaps: root causes first, then those that refer to another cause.

    Parameters
    ----------
    parity : GravityParity

    Returns
    -------
    list of Finding
    """
    return sorted(parity.explanations, key=lambda f: not f.root_cause)  # stable: engines in order


def cause_words(finding: Finding) -> str:
    """One cause as the short form reads it: ``pinocchio: <element>: <brief> [id]``.

    Parameters
    ----------
    finding : Finding

    Returns
    -------
    str
    """
    named = finding.cause or finding.values.get("explained by cause", "")
    tail = f" [{named}]" if named else ""
    return f"{finding.engine}: {finding.element}: {finding.summary}{tail}"


def verdict_text(parity: GravityParity) -> str:
    """The gravity verdict without its status word: the largest gap, its causes, each engine's vector.

    Parameters
    ----------
    parity : GravityParity

    Returns
    -------
    str
    """
    vectors = "; ".join(f"{e} ({', '.join(f'{x:g}' for x in v)})" for e, v in parity.vectors().items())
    worst = parity.worst
    if worst is None:
        return f"{vectors}; no second engine to compare"
    if parity.agrees:
        return f"g(q) and V(q)-V(q_ref) within {parity.rtol:g}, largest {fmt(worst.relative)} relative; {vectors}"
    where = f"pose {worst.pose}" + (f", dof {worst.dof}" if worst.dof >= 0 else "")
    size = f"off by {fmt(worst.relative)} relative ({worst.absolute:+.4g} at {where})"
    head = f"{worst.engine} {_QUANTITY[worst.quantity]} {size}"
    named = [cause_words(f) for f in causes(parity)]
    return head + (f"; {'; '.join(named)}" if named else "") + f"; {vectors}"


def verdict_line(parity: GravityParity) -> str:
    """``gravity: agree: ...`` or ``gravity: DIFFER: ...`` (:func:`verdict_text` after the status).

    Parameters
    ----------
    parity : GravityParity

    Returns
    -------
    str
    """
    return f"gravity: {'agree' if parity.agrees else 'DIFFER'}: {verdict_text(parity)}"


def reason_words(parity: GravityParity) -> str:
    """The short reason of a gravity disagreement (empty when the engines agree).

    Parameters
    ----------
    parity : GravityParity

    Returns
    -------
    str
    """
    worst = parity.worst
    if parity.agrees or worst is None:
        return ""
    found = causes(parity)
    found = [f for f in found if f.engine == worst.engine] + [f for f in found if f.engine != worst.engine]
    first = found[0] if found else None
    named = f": {cause_words(first).split(': ', 1)[1]}" if first else ""
    if first is not None and first.engine != worst.engine:
        named = f"; {cause_words(first)}"
    more = f" (+{len(found) - 1} more)" if len(found) > 1 else ""
    return f"gravity differs: {worst.engine} {_QUANTITY[worst.quantity]} off by {fmt(worst.relative)}{named}{more}"
