"""The reason text of a diagnosis: which findings explain a disagreement, in which order, in one line."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from koenig_check.diagnosis.cause_effect import by_effect
from koenig_check.findings import Finding, Kind, root_causes

#: Kinds of per-segment import differences (symptoms, after the root causes in a reason).
_SYMPTOMS = (Kind.MASS, Kind.COM, Kind.INERTIA, Kind.ANCHOR, Kind.AXIS, Kind.ARMATURE, Kind.SEGMENTS, Kind.FRAME)


#: A relative difference at most this is what numbers written with 6 significant digits explain (MuJoCo's
#: XML writer, ``MjSpec.to_xml``, MuJoCo's URDF import saved: up to 5e-6 per number): a written file's
#: rounding, not a construct.
ROUNDING_LEVEL = 1e-5
#: The longest one-line reason of a model (characters, its label included): with the command line's
#: ``koenig-check: `` before it, the line fits 200 characters.
REASON_WIDTH = 200 - len("koenig-check: ")


def _relative(f: Finding) -> float:
    """A symptom's size relative to its scale (0 when unknown)."""
    value = f.values.get("relative difference", 0.0)
    return float(value) if isinstance(value, float) and value == value else 0.0


def ordered_causes(findings: Sequence[Finding]) -> list[Finding]:
    """The findings that explain a change of energy, the most important first; rounding-level ones left out.

    Root causes that change the energy come first (a repaired or compiler-altered inertia, a construct one
    parser ignores), those whose values show their effect ordered by it, the largest first
    (:func:`koenig_check.diagnosis.cause_effect.by_effect`); then the per-segment import differences no root
    cause explains, the largest relative difference first; then each engine's inconsistencies with itself.
    A symptom whose relative difference is at the level of a written file's rounding
    (:data:`ROUNDING_LEVEL`) is never listed.

    Parameters
    ----------
    findings : sequence of Finding

    Returns
    -------
    list of Finding
    """
    energy = [f for f in findings if f.affects_energy]
    roots = by_effect([f for f in root_causes(energy) if f.affects_energy])  # the largest change of energy first
    symptoms = [f for f in energy if f.kind in _SYMPTOMS and f not in roots]
    symptoms = [f for f in symptoms if "relative difference" not in f.values or _relative(f) > ROUNDING_LEVEL]
    symptoms.sort(key=lambda f: -_relative(f))
    selves = [f for f in energy if f.kind is Kind.SELF_CONSISTENCY and f not in roots]
    chosen: list[Finding] = []
    for f in roots + symptoms + selves:
        if f not in chosen:
            chosen.append(f)
    return chosen


def disagreement_cause(findings: Sequence[Finding], limit: int = 3) -> str:
    """The cause of an engine disagreement, chosen from the findings (:func:`ordered_causes`), in full.

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
    return "; ".join(cause_lines(findings, limit))


def cause_lines(findings: Sequence[Finding], limit: int = 3) -> list[str]:
    """The causes of :func:`disagreement_cause`, one item each, then how many more (for a view of several lines).

    Parameters
    ----------
    findings : sequence of Finding
    limit : int

    Returns
    -------
    list of str
    """
    chosen = ordered_causes(findings)
    lines = [f.message() for f in chosen[:limit]]
    if len(chosen) > limit:
        lines.append(f"and {len(chosen) - limit} more finding(s)")
    return lines


def short_cause(f: Finding) -> str:
    """A cause in a few words: its element and the first clause of its summary, without parentheses or values.

    An element that lists several names keeps the first and says how many more.

    Parameters
    ----------
    f : Finding

    Returns
    -------
    str
    """
    element = f.element
    more = re.search(r" \(\+(\d+) more\)$", element)
    listed = element[: more.start()] if more else element
    if ", " in listed:
        first, rest = listed.split(", ", 1)
        extra = rest.count(", ") + 1 + (int(more.group(1)) if more else 0)
        element = f"{first} (+{extra} more)"
    clause = re.sub(r" \([^)]*\)", "", f.summary.split("; ")[0])
    return f"{element}: {clause}"


def _departures(findings: Sequence[Finding]) -> str:
    """The three-engine verdicts in a few words: which engine departs (once each), or that all differ."""
    heads = []
    for f in findings:
        if f.kind is Kind.VERDICT:
            head = re.sub(
                r" \([^)]*\)", "", f.summary.split("; ")[0]
            )  # "Pinocchio departs", "all three engines differ"
            if head not in heads:
                heads.append(head)
    return ", ".join(heads)


def short_reason(
    label: str, findings: Sequence[Finding], gap: str = "", limit: int = 3, width: int = REASON_WIDTH
) -> str:
    """Why a model fails, in one sentence of at most :data:`REASON_WIDTH` characters.

    The engine that departs first, then at most ``limit`` root causes, the most important first, and how many
    more, then the engines' gap, and last a check asked for and not made, with the engine's own reason (cut at
    a word when it does not fit: the verdict table's row, ``summary.md`` and the report hold it whole, and
    ``koenig-check parity`` the details).  To fit, the gap loses its pose,
    then the gap goes (the verdict table shows it), then causes after the first go ("and N more"), and last the
    first cause is cut at a word ("…").

    Parameters
    ----------
    label : str
        The model's label.
    findings : sequence of Finding
    gap : str
        The engines' disagreement in a few words (empty when they agree).
    limit : int
    width : int
        The longest line (the verdict table's row gives room for the check not made, whole).

    Returns
    -------
    str
    """
    from koenig_check.report.line_width import cut

    unable_findings = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    unmade = "; ".join(f.summary for f in unable_findings)  # each summary names its engine and gives its reason
    head = _departures(findings)
    if unmade and not head and not gap:  # MuJoCo and Pinocchio agree: the check not made is the whole reason
        hints = "; ".join(f.hint for f in unable_findings if f.hint)
        text = f"{label}: {unmade}"
        hinted = f"{text}; {hints}" if hints else text
        return hinted if len(hinted) <= width else cut(text, width)  # whole: the table row
    unable = {f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE}  # its causes are in its reason
    causes = [short_cause(f) for f in ordered_causes(findings) if f.engine not in unable]
    gaps = [gap, gap.split(" (pose ")[0]] if " (pose " in gap else [gap]
    if head or causes:  # the gap may go when something else says why (the verdict table shows it)
        gaps.append("")
    room = min(len(unmade) + 2, _UNMADE_ROOM) if unmade else 0  # kept for the check not made, which closes the line
    text = ""
    for n in range(min(limit, len(causes)), 0 if causes else -1, -1):
        for g in gaps:
            said = "; ".join(causes[:n]) + (f" and {len(causes) - n} more" if len(causes) > n else "")
            parts = [head, f"root cause: {said}" if n else "", g]
            text = f"{label}: " + "; ".join(t for t in parts if t)
            if len(text) + room <= width:
                return _closed(text, unmade, width)
    text = text[: width - room - 1].rsplit(" ", 1)[0] + "…"  # one long cause cut at a word
    return _closed(text, unmade, width)


def short_error(
    err: BaseException, width: int = REASON_WIDTH, rename: Callable[[str], str] | None = None, limit: int = 3
) -> str:
    """An error in one sentence of at most ``width`` characters: its message, then at most ``limit`` root causes.

    The message is the error's brief form when it has one (:attr:`KoenigCheckError.brief`), else its message
    without the root causes appended to it; the root causes follow, those that change the energy first, each
    once: in a few words each (:func:`short_cause`), or, to fit, the first ones so and the others by their
    element, and how many more.  To fit further the message is cut at a word (``…``), the causes kept.  The
    whole message stays ``str(err)`` (the report's failures, ``--debug``).

    Parameters
    ----------
    err : BaseException
    width : int
    rename : callable, optional
        Applied to the message and the causes (e.g. a resolved path written as the user gave it).
    limit : int

    Returns
    -------
    str
    """
    from koenig_check.exceptions import one_line
    from koenig_check.report.line_width import cut

    def tidy(text: str) -> str:
        text = " ".join(text.split())
        return rename(text) if rename else text

    causes = sorted(getattr(err, "causes", ()), key=lambda c: not c.affects_energy)  # energy first, stable
    head = tidy(getattr(err, "brief", "") or (getattr(err, "head", "") if causes else "") or one_line(err))
    named: dict[str, str] = {}  # a cause in a few words -> by its element alone
    for c in causes:
        name = tidy(short_cause(c))
        if name not in named and name not in head:
            named[name] = tidy(f"{c.element}")
    if not named:
        return cut(head, width)
    shorts, elements = list(named), list(named.values())
    n = min(limit, len(shorts))
    more = f" and {len(shorts) - n} more" if len(shorts) > n else ""
    for k in range(n, -1, -1):  # every cause up to the limit: the first k in a few words, the others by element
        tail = "; root cause: " + "; ".join(shorts[:k] + elements[k:n]) + more
        if len(head) + len(tail) <= width:
            return head + tail
        if len(tail) <= width - _SHORTEST_HEAD:  # the message cut at a word, the causes kept
            return cut(head, width - len(tail)) + tail
    return cut(cut(head, _SHORTEST_HEAD) + tail, width)


#: The fewest characters of an error's own message kept before its root causes.
_SHORTEST_HEAD = 40


#: The room a reason keeps for a check asked for and not made (the rest of its text is in the verdict table's row).
_UNMADE_ROOM = 80


def _closed(text: str, unmade: str, width: int) -> str:
    """A reason closed by the checks asked for and not made, cut at a word to fit (whole in the table's row)."""
    from koenig_check.report.line_width import cut

    if not unmade:
        return text
    return cut(f"{text}{'' if text.endswith(': ') else '; '}{unmade}", width)


def rounding_hint(max_relative: float, rtol: float, between: str = "MuJoCo and Pinocchio") -> str:
    """A hint when every difference is at the level a written file's rounding explains, else empty.

    A number written with 6 significant digits is rounded by up to 5e-6 of itself, and an energy or a mass
    matrix, quadratic in lengths, by up to about twice that: the hint names ``--rtol`` :data:`ROUNDING_LEVEL`,
    the bound that holds at every pose, never a smaller tolerance that the poses drawn happen to meet.

    Parameters
    ----------
    max_relative : float
        The largest relative difference found (engines' energies, mass matrices or segment quantities).
    rtol : float
        The tolerance it exceeds.
    between : str
        What differs (``"MuJoCo and Pinocchio"``, ``"the original and the export"``).

    Returns
    -------
    str
    """
    if not rtol < max_relative <= ROUNDING_LEVEL:
        return ""
    return (
        f"{between} differ by at most {max_relative:.2g} relative, what a file written with 6 significant "
        f"digits explains (up to 5e-06 per number): --rtol {ROUNDING_LEVEL:g} accepts it"
    )


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


def engine_usage(findings: Sequence[Finding], engine: str | None = None) -> str:
    """Why an optional engine was not used on a model, from its findings (empty when it was used).

    Parameters
    ----------
    findings : sequence of Finding
    engine : str, optional
        One optional engine; by default each optional engine not used, in report order, joined by ``"; "``.

    Returns
    -------
    str
    """
    from koenig_check.engines.registry import optional

    why = {f.engine: f.summary for f in reversed(findings) if f.kind is Kind.ENGINE_NOT_USED}  # the first kept
    return "; ".join(why[e] for e in ((engine,) if engine else optional()) if e in why)


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
