"""A model's one-line reason, built once: the engine that departs, its root causes, the gap, the checks not made.

The verdict table's row shows it whole, the command line's error within 200 characters (:class:`Reason`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from koenig_check.diagnosis.cause_groups import cause_groups, more_causes
from koenig_check.diagnosis.reason import REASON_WIDTH, ordered_causes
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

    The verdict table's row shows it whole (:meth:`whole`), the command line's error within
    :data:`REASON_WIDTH` characters (:meth:`line`): one rendering, the checks asked for and not made apart, so that
    only they are cut (at a word) to fit the line.

    Attributes
    ----------
    label : str
        The model's label.
    sentence : str
        ``"<label>: <engine that departs>; root cause: ...; <gap>"``, chosen to leave room for :attr:`unmade`
        within :data:`REASON_WIDTH`; only ``"<label>: "`` when nothing but a check not made is said.
    unmade : str
        The checks asked for and not made, each naming its engine with the engine's whole reason (empty: none).
    hints : str
        What to do about them, when they are the whole reason (empty otherwise).
    """

    label: str
    sentence: str
    unmade: str = ""
    hints: str = ""

    def whole(self) -> str:
        """The reason with every part whole (the verdict table's row, folded under its column).

        Returns
        -------
        str
        """
        if self.hints:
            return f"{self.sentence}{self.unmade}; {self.hints}"
        return _joined(self.sentence, self.unmade)

    def line(self, width: int = REASON_WIDTH) -> str:
        """The reason in at most ``width`` characters: the hints go, then the checks not made are cut at a word.

        Parameters
        ----------
        width : int

        Returns
        -------
        str
        """
        text = self.whole()
        if len(text) <= width:
            return text
        return closed_cut(_joined(self.sentence, self.unmade), width)


def _joined(sentence: str, unmade: str) -> str:
    """A sentence closed by the checks asked for and not made."""
    if not unmade:
        return sentence
    return f"{sentence}{'' if sentence.endswith(': ') else '; '}{unmade}"


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
    return model_reason(label, findings, gap, limit, width).line(width)


def model_reason(
    label: str, findings: Sequence[Finding], gap: str = "", limit: int = 3, width: int = REASON_WIDTH
) -> Reason:
    """Why a model fails: the engine that departs, the root causes, the gap and the checks not made (a :class:`Reason`).

    The engine that departs first, then at most ``limit`` root causes, the most important first (the same cause
    on several elements is one cause naming them), and how many more (``; and 2 more root causes``), then the
    engines' gap, and last a check asked for and not made, with the engine's own reason (whole in
    :meth:`Reason.whole`; cut at a word in :meth:`Reason.line` when it does not fit: ``koenig-check parity`` gives
    the details).  To fit ``width`` with room for the check not made, whole parts go, never half of one: the gap
    loses its pose, then the gap goes (the verdict table shows it), then the causes after the first ("and N
    more"), then "and N more"; only then is the sentence cut at a word ("…"), never inside a parenthesis.

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
    Reason
    """
    unable_findings = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    unmade = "; ".join(f.summary for f in unable_findings)  # each summary names its engine and gives its reason
    head = _departures(findings)
    if unmade and not head and not gap:  # MuJoCo and Pinocchio agree: the check not made is the whole reason
        hints = "; ".join(f.hint for f in unable_findings if f.hint)
        return Reason(label, f"{label}: ", unmade, hints)
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
            return Reason(label, text, unmade)
    return Reason(label, closed_cut(text, width - room), unmade)  # the first cause too long: cut at a word


#: The room a reason keeps for a check asked for and not made (the rest of its text is in the verdict table's row).
_UNMADE_ROOM = 80
