"""A model's one-line reason, built once: the engine that departs, its root causes, the gap, the checks not made.

The verdict table's row shows it whole, the command line's error within 200 characters (:class:`Reason`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from koenig_check.diagnosis.cause_groups import CauseGroup, cause_groups, more_causes
from koenig_check.diagnosis.reason import REASON_WIDTH, ordered_causes
from koenig_check.engines.registry import ENGINE_TEXT
from koenig_check.findings import Finding, Kind
from koenig_check.line_width import closed_cut


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


@dataclass(frozen=True)
class Reason:
    """Why a model fails, built once from its findings: its parts, shown whole or within one line.

    The parts are chosen and ordered once (the engine that departs, the root causes grouped and ranked, the gap,
    the checks not made); the verdict table's row shows them whole (:meth:`whole`), the command line's error
    within :data:`REASON_WIDTH` characters (:meth:`line`).

    Attributes
    ----------
    label : str
        The model's label.
    head : str
        The engines that depart (``"Pinocchio departs"``), or empty.
    groups : tuple of CauseGroup
        The root causes, the most important first.
    gap : str
        The engines' disagreement in a few words (empty when they agree).
    unmade : str
        The checks asked for and not made, each naming its engine with the engine's whole reason (empty: none).
    hints : str
        What to do about them (said when they are the whole reason).
    limit : int
        At most this many causes are named.
    unmade_whole : str
        The checks not made with each engine's own text after its reason, on one line (the verdict table's row);
        empty: the same as ``unmade``.
    """

    label: str
    head: str = ""
    groups: tuple[CauseGroup, ...] = ()
    gap: str = ""
    unmade: str = ""
    hints: str = ""
    limit: int = 3
    unmade_whole: str = ""

    def whole(self) -> str:
        """The verdict table's row: the sentence as :meth:`line` fits it, then the checks not made whole.

        No room is kept in the sentence for the checks not made: the row holds them whole after it.

        Returns
        -------
        str
        """
        unmade = self.unmade_whole or self.unmade
        if unmade and not self.head and not self.gap:  # the check not made is the whole reason
            return f"{self.label}: {unmade}" + (f"; {self.hints}" if self.hints else "")
        text = self._sentence(REASON_WIDTH, 0)
        return f"{text}{'' if text.endswith(': ') else '; '}{unmade}" if unmade else text

    def line(self, width: int = REASON_WIDTH) -> str:
        """The reason in at most ``width`` characters, whole parts dropped to fit, cut at a word only at last.

        To fit ``width`` with room for the check not made, whole parts go, never half of one: the gap loses its
        pose, then the gap goes (the verdict table shows it), then the causes after the first ("and N more"),
        then "and N more"; only then is the sentence cut at a word ("…"), never inside a parenthesis; the check not
        made closes the line, cut at a word when it does not fit.

        Parameters
        ----------
        width : int

        Returns
        -------
        str
        """
        unmade = self.unmade
        if unmade and not self.head and not self.gap:  # the check not made is the whole reason
            text = f"{self.label}: {unmade}"
            hinted = f"{text}; {self.hints}" if self.hints else text
            return hinted if len(hinted) <= width else _closed(f"{self.label}: ", unmade, width)  # whole: below
        room = min(len(unmade) + 2, _UNMADE_ROOM) if unmade else 0  # kept for the check not made
        return _closed(self._sentence(width, room), unmade, width)

    def _sentence(self, width: int, room: int) -> str:
        """The label, the engines that depart, the causes and the gap, within ``width`` less ``room``."""
        causes = [g.short() for g in self.groups]
        gap = self.gap
        gaps = [gap, gap.split(" (pose ")[0]] if " (pose " in gap else [gap]
        if self.head or causes:  # the gap may go when something else says why (the verdict table shows it)
            gaps.append("")
        tries = [(n, g, True) for n in range(min(self.limit, len(causes)), 0, -1) for g in gaps]
        tries += [(1, "", False)] if causes else [(0, g, False) for g in gaps]
        text = ""
        for n, g, counted in tries:
            said = "; ".join(causes[:n] + ([more_causes(self.groups[n:])] if counted and len(causes) > n else []))
            parts = [self.head, f"root cause: {said}" if n else "", g]
            text = f"{self.label}: " + "; ".join(t for t in parts if t)
            if len(text) + room <= width:
                return text
        return closed_cut(text, width - room)  # the first cause too long: cut at a word


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

    fitting = [end for end in clause_ends(unmade) if len(joined) + end <= width]
    return joined + unmade[: fitting[-1]] if fitting else closed_cut(whole, width)


def short_reason(
    label: str, findings: Sequence[Finding], gap: str = "", limit: int = 3, width: int = REASON_WIDTH
) -> str:
    """Why a model fails, in one sentence of at most ``width`` characters: :func:`model_reason`'s line.

    Parameters
    ----------
    label : str
        The model's label.
    findings : sequence of Finding
    gap : str
        The engines' disagreement in a few words (empty when they agree).
    limit : int
    width : int

    Returns
    -------
    str
    """
    return model_reason(label, findings, gap, limit).line(width)


def model_reason(label: str, findings: Sequence[Finding], gap: str = "", limit: int = 3) -> Reason:
    """Why a model fails: the engine that departs, the root causes, the gap and the checks not made (a :class:`Reason`).

    The engine that departs first, then at most ``limit`` root causes, the most important first (the same cause
    on several elements is one cause naming them), and how many more (``; and 2 more root causes``), then the
    engines' gap, and last a check asked for and not made, with the engine's own reason.

    Parameters
    ----------
    label : str
        The model's label.
    findings : sequence of Finding
    gap : str
        The engines' disagreement in a few words (empty when they agree).
    limit : int

    Returns
    -------
    Reason
    """
    unable_findings = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    # Each summary names its engine and gives its reason; the engine's own text, if it gave one, is a value: the
    # lines under the one-line reason give it whole, the verdict table's row after the summary, on one line.
    unmade = "; ".join(f.summary for f in unable_findings)
    unmade_whole = "; ".join(_with_engine_text(f) for f in unable_findings)
    hints = "; ".join(dict.fromkeys(f.hint for f in unable_findings if f.hint))  # two engines, one cause: one hint
    unable = {f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE}  # its causes are in its reason
    groups = cause_groups(f for f in ordered_causes(findings) if f.engine not in unable)
    return Reason(label, _departures(findings), tuple(groups), gap, unmade, hints, limit, unmade_whole)


#: The room a reason keeps for a check asked for and not made (the rest of its text is in the verdict table's row).
_UNMADE_ROOM = 80


def _with_engine_text(finding: Finding) -> str:
    """A check not made: its summary, then the engine's own text on the same line (white space made one space)."""
    text = " ".join(str(finding.values.get(ENGINE_TEXT, "")).split())
    return f"{finding.summary}: {text}" if text else finding.summary
