"""An error in one sentence: its message and its root causes, shortened by whole parts, cut only as a last resort.

A one-line error names what failed, what to do, and the root causes, each in a few words.  When the line is too
long, whole parts go (a keyword's Python spelling, the causes after the first, each cause's explanation, the
engine's own detail in parentheses), never half of one; a line is cut at a word only when nothing else is left
to drop, and never inside a parenthesis it opens.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from koenig_check.diagnosis.cause_groups import CauseGroup, cause_groups, more_causes
from koenig_check.line_width import LINE_LIMIT, closed_cut

#: The longest one-line message (characters): with the command line's ``koenig-check: `` before it, 200.
WIDTH = LINE_LIMIT - len("koenig-check: ")


def short_error(
    err: BaseException, width: int = WIDTH, rename: Callable[[str], str] | None = None, limit: int = 3
) -> str:
    """An error in one sentence of at most ``width`` characters: its message, then at most ``limit`` root causes.

    The message is the error's brief form when it has one (:attr:`KoenigCheckError.brief`), else its message
    without the root causes appended to it; the root causes follow, those that change the energy first (the
    others only when none does), each once (the same cause on several elements is one cause naming them), in a
    few words each, never one the message already says.  To fit, whole parts go, never half of one: a keyword's
    Python spelling in parentheses (``(repair_inertia=True)``), then the causes after the first ("; and N more
    root causes"), then the joints each cause loses, then the engine's own detail in
    parentheses (its verbatim reason), the last first, then "and N more", then the first cause naming only its first
    element ("includes a.xml (+2 more)"), then the causes (counted); only then are the last parts left out (whole:
    the lines after a message's first line give them), and only a first part too long alone is cut at a word
    (``…``), never inside a parenthesis.  The whole message stays ``str(err)`` (the report's
    failures, ``--debug``).

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

    def tidy(text: str) -> str:
        text = " ".join(text.split())
        return rename(text) if rename else text

    found = list(getattr(err, "causes", ()))
    energy = [c for c in found if c.affects_energy]
    head = tidy(getattr(err, "brief", "") or (getattr(err, "head", "") if found else "") or one_line(err))
    groups = [g for g in cause_groups(energy or found) if not _said(g, err)]
    shorts = [tidy(g.short(joints=not any(j in head for j in g.lost_joints()))) for g in groups]
    plain = _PYTHON_SPELLING.sub("", head)
    heads = (plain, *_without_details(plain))
    briefs = [tidy(g.short(joints=not any(j in head for j in g.lost_joints()), brief=True)) for g in groups]
    n = min(limit, len(shorts))
    counts = range(n, 0, -1)
    tries = [(h, k, True, shorts) for h in dict.fromkeys((head, plain)) for k in counts]  # causes -> "and N more"
    tries += [(plain, k, True, briefs) for k in counts]  # then without the joints each cause loses
    tries += [(h, 1, True, said) for h in heads[1:] for said in (shorts, briefs)]  # then the engine's detail
    tries += [(h, min(n, 1), False, briefs) for h in heads]  # then "and N more"
    firsts = [tidy(g.short(joints=False, brief=True, shown=1)) for g in groups]  # one element, "(+N more)"
    tries += [(h, 1, False, firsts) for h in heads]  # then the first cause naming its first element only
    tries += [(plain, 0, True, shorts)] if shorts else []  # what to do kept whole, the causes counted
    if not shorts:  # no cause: the message, then without its details
        tries = [(h, 0, False, shorts) for h in dict.fromkeys((head, *heads))]
    for h, k, counted, said_as in tries:
        said = said_as[:k] + ([more_causes(groups[k:])] if counted and len(shorts) > k else [])
        text = h + ("; root cause: " + "; ".join(said) if k else "")
        if not k and shorts:
            text += f"; {len(shorts)} root cause{'s' if len(shorts) > 1 else ''} not shown"
        if len(text) <= width:
            return text
    return _whole_parts(heads[-1] + ("; root cause: " + briefs[0] if briefs else ""), width)  # the last resort


def _whole_parts(text: str, width: int) -> str:
    """The leading parts of ``text`` (split at ``"; "`` outside parentheses) that fit ``width``, none cut.

    The parts left out are in the lines that follow a message's first line
    (:func:`koenig_check.diagnosis.message.detail_lines`); only a first part longer than ``width`` is cut at a word.
    """
    from koenig_check.diagnosis.message import first_and_rest

    first, _ = first_and_rest(text, width)
    return first if len(first) <= width else closed_cut(first, width)


def _said(group: CauseGroup, err: BaseException) -> bool:
    """Whether an error already says a cause: a model without a joint, which its error is about."""
    from koenig_check.exceptions import NoMovingSegmentError
    from koenig_check.findings import Kind

    return group.findings[0].kind is Kind.NOTHING_MOVES and isinstance(err, NoMovingSegmentError)


#: A parenthesis holding a keyword's Python spelling (``(repair_inertia=True)``, ``(pinocchio_model=...)``).
_PYTHON_SPELLING = re.compile(r" \(\w+=[^()]*\)")


def _groups(text: str) -> list[tuple[int, int]]:
    """The outermost parentheses of ``text`` (start, end), the last first."""
    spans, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch == "(":
            if depth == 0:
                start = i
            depth += 1
        elif ch == ")" and depth:
            depth -= 1
            if depth == 0:
                spans.append((start, i + 1))
    return spans[::-1]


def _without_details(head: str) -> list[str]:
    """An error's message without its parentheses (the engine's verbatim detail), one more gone each, last first."""
    heads = []
    for start, end in _groups(head):  # the last first: the engine's detail follows what it refused
        cut_from = start - 1 if start and head[start - 1] == " " else start
        head = head[:cut_from] + head[end:]
        heads.append(head)
    return heads
