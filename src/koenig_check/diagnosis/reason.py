"""The reason text of a diagnosis: which findings explain a disagreement, in which order, in one line."""

from __future__ import annotations

from collections.abc import Sequence

from koenig_check.diagnosis.cause_effect import by_effect
from koenig_check.diagnosis.cause_groups import CauseGroup, brief_form, cause_groups, element_words, more_causes
from koenig_check.diagnosis.one_line import short_error
from koenig_check.findings import Finding, Kind, root_causes
from koenig_check.line_width import closed_cut

__all__ = ["short_error"]  # its home is diagnosis/one_line.py; imported from here by earlier code

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
    cause explains (a symptom on segments a root cause names is its consequence, not another cause), the
    largest relative difference first; then each engine's inconsistencies with itself.
    A symptom whose relative difference is at the level of a written file's rounding
    (:data:`ROUNDING_LEVEL`) is never listed, nor the findings of an optional engine (Drake) that no
    three-engine verdict blames: it agrees with an engine, its import is not why they differ.

    Parameters
    ----------
    findings : sequence of Finding

    Returns
    -------
    list of Finding
    """
    blamed = _blamed(findings)
    energy = [f for f in findings if f.affects_energy and (f.engine not in _optional() or f.engine in blamed)]
    roots = by_effect([f for f in root_causes(energy) if f.affects_energy])  # the largest change of energy first
    explained = {s for f in roots for s in f.segments}
    symptoms = [f for f in energy if f.kind in _SYMPTOMS and f not in roots]
    symptoms = [f for f in symptoms if not (f.segments and set(f.segments) <= explained)]
    symptoms = [f for f in symptoms if "relative difference" not in f.values or _relative(f) > ROUNDING_LEVEL]
    symptoms.sort(key=lambda f: -_relative(f))
    selves = [f for f in energy if f.kind is Kind.SELF_CONSISTENCY and f not in roots]
    chosen: list[Finding] = []
    for f in roots + symptoms + selves:
        if f not in chosen:
            chosen.append(f)
    return chosen


def _optional() -> tuple[str, ...]:
    from koenig_check.engines.registry import optional

    return tuple(optional())


def _blamed(findings: Sequence[Finding]) -> set[str]:
    """The optional engines a three-engine verdict blames: the one that departs, or every one when all differ."""
    engines = {f.engine for f in findings if f.kind is Kind.VERDICT}
    return set(_optional()) if "all" in engines else engines


def root_cause_groups(findings: Sequence[Finding]) -> list[CauseGroup]:
    """The causes of :func:`ordered_causes`, the same cause on several elements made one.

    Parameters
    ----------
    findings : sequence of Finding

    Returns
    -------
    list of CauseGroup
    """
    return cause_groups(ordered_causes(findings))


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
    """The causes of :func:`disagreement_cause`, one item each, the last saying how many more (a view of lines).

    The same cause found on several elements is one item naming them (:func:`root_cause_groups`); the last item
    ends with ``; and N more root causes`` when more were found.

    Parameters
    ----------
    findings : sequence of Finding
    limit : int

    Returns
    -------
    list of str
    """
    groups = root_cause_groups(findings)
    lines = [g.message() for g in groups[:limit]]
    more = more_causes(groups[limit:])
    if more:
        lines[-1] += f"; {more}"
    return lines


def short_cause(f: Finding) -> str:
    """A cause in a few words: its element and its brief form (:func:`~koenig_check.diagnosis.cause_groups.brief_form`).

    Parameters
    ----------
    f : Finding

    Returns
    -------
    str
    """
    return f"{element_words(f)}: {brief_form(f)}"


def _departures(findings: Sequence[Finding]) -> str:
    """The three-engine verdicts in a few words: which engine departs (once each), or that all differ."""
    from koenig_check.diagnosis.three_way import verdict_head

    heads = []
    for f in findings:
        if f.kind is Kind.VERDICT:
            head = verdict_head(f)  # "Pinocchio departs", "all three engines differ"
            if head not in heads:
                heads.append(head)
    return ", ".join(heads)


def short_reason(
    label: str, findings: Sequence[Finding], gap: str = "", limit: int = 3, width: int = REASON_WIDTH
) -> str:
    """Why a model fails, in one sentence of at most :data:`REASON_WIDTH` characters.

    The engine that departs first, then at most ``limit`` root causes, the most important first (the same cause
    on several elements is one cause naming them), and how many more (``; and 2 more root causes``), then the
    engines' gap, and last a check asked for and not made, with the engine's own reason (cut at a word when it
    does not fit: the verdict table's row, ``summary.md`` and the report hold it whole, and ``koenig-check
    parity`` the details).  To fit, whole parts go, never half of one: the gap loses its pose, then the gap goes
    (the verdict table shows it), then the causes after the first ("and N more"), then "and N more"; only then is
    the line cut at a word ("…"), never inside a parenthesis.

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
    unable_findings = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    unmade = "; ".join(f.summary for f in unable_findings)  # each summary names its engine and gives its reason
    head = _departures(findings)
    if unmade and not head and not gap:  # MuJoCo and Pinocchio agree: the check not made is the whole reason
        hints = "; ".join(f.hint for f in unable_findings if f.hint)
        text = f"{label}: {unmade}"
        hinted = f"{text}; {hints}" if hints else text
        return hinted if len(hinted) <= width else _closed(f"{label}: ", unmade, width)  # whole: the lines below
    unable = {f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE}  # its causes are in its reason
    groups = cause_groups(f for f in ordered_causes(findings) if f.engine not in unable)
    causes = [g.short() for g in groups]
    gaps = [gap, gap.split(" (pose ")[0]] if " (pose " in gap else [gap]
    if head or causes:  # the gap may go when something else says why (the verdict table shows it)
        gaps.append("")
    room = min(len(unmade) + 2, _UNMADE_ROOM) if unmade else 0  # kept for the check not made, which closes the line
    tries = [(n, g, True) for n in range(min(limit, len(causes)), 0, -1) for g in gaps]
    tries += [(1, "", False)] if causes else [(0, g, False) for g in gaps]
    text = ""
    for n, g, counted in tries:
        said = "; ".join(causes[:n] + ([more_causes(groups[n:])] if counted and len(causes) > n else []))
        parts = [head, f"root cause: {said}" if n else "", g]
        text = f"{label}: " + "; ".join(t for t in parts if t)
        if len(text) + room <= width:
            return _closed(text, unmade, width)
    return _closed(closed_cut(text, width - room), unmade, width)  # the first cause too long: cut at a word


#: The room a reason keeps for a check asked for and not made (the rest of its text is in the verdict table's row).
_UNMADE_ROOM = 80


def _closed(text: str, unmade: str, width: int) -> str:
    """A reason closed by the checks asked for and not made, by whole clauses that fit (whole in the lines below).

    The checks not made are shortened at a clause (``": "`` or ``"; "`` outside parentheses), never inside one;
    the lines after the reason give them whole (:func:`koenig_check.diagnosis.message.finding_lines`).
    """
    if not unmade:
        return text
    joined = f"{text}{'' if text.endswith(': ') else '; '}"
    whole = joined + unmade
    if len(whole) <= width:
        return whole
    from koenig_check.diagnosis.message import clause_ends

    clauses = clause_ends(unmade)
    fitting = [end for end in clauses if len(joined) + end <= width]
    return joined + unmade[: fitting[-1]] if fitting else closed_cut(whole, width)


def rounding_hint(max_relative: float, rtol: float, between: str = "MuJoCo and Pinocchio", cli: bool = False) -> str:
    """A hint when every difference is at the level a written file's rounding explains, else empty.

    A number written with 6 significant digits is rounded by up to 5e-6 of itself, and an energy or a mass
    matrix, quadratic in lengths, by up to about twice that: the hint names the tolerance :data:`ROUNDING_LEVEL`,
    the bound that holds at every pose, never a smaller tolerance that the poses drawn happen to meet.

    Parameters
    ----------
    max_relative : float
        The largest relative difference found (engines' energies, mass matrices or segment quantities).
    rtol : float
        The tolerance it exceeds.
    between : str
        What differs (``"MuJoCo and Pinocchio"``, ``"the original and the export"``).
    cli : bool
        Name the option as the command line spells it (``--rtol 1e-06``); by default as the Python API does
        (``rtol=1e-06``: :func:`koenig_check.compare`, :func:`koenig_check.testing.assert_energy_parity`).

    Returns
    -------
    str
    """
    if not rtol < max_relative <= ROUNDING_LEVEL:
        return ""
    spelt = f"--rtol {ROUNDING_LEVEL:g}" if cli else f"rtol={ROUNDING_LEVEL:g}"
    return (
        f"{between} differ by at most {max_relative:.2g} relative, what a file written with 6 significant "
        f"digits explains (up to 5e-06 per number): {spelt} accepts it"
    )


#: Findings that lead a reason: a check the user asked for that was not made, an engine that departs.
LEADING_KINDS = (Kind.ENGINE_UNABLE, Kind.VERDICT)


_COUNT_WORDS = {3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight", 9: "nine"}


def as_note(finding: Finding) -> str:
    """A finding as a note line: a verdict after the number of engines that voted on it ("three engines: ...").

    Parameters
    ----------
    finding : Finding
        A ``VERDICT`` (its values hold one entry per voting engine) or any other finding (its message alone).

    Returns
    -------
    str
    """
    if finding.kind is not Kind.VERDICT:
        return finding.message()
    voters = len(finding.values)
    return f"{_COUNT_WORDS.get(voters, str(voters))} engines: {finding.message()}"


def lead_line(findings: Sequence[Finding], counted: bool = False) -> str:
    """The head of a one-line reason (empty when none): checks asked for and not made, then the verdicts.

    Parameters
    ----------
    findings : sequence of Finding
    counted : bool
        Each verdict after the number of engines that voted on it (:func:`as_note`), as the report writes it.

    Returns
    -------
    str
    """
    ordered = [f for kind in LEADING_KINDS for f in findings if f.kind is kind]
    return "; ".join(as_note(f) if counted else f.message() for f in ordered)


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
