"""A failure as one message: a first line that says which model failed and why, then the whole of it, indented.

The first line is at most 200 characters (:func:`koenig_check.diagnosis.one_line.short_error` makes it); the lines
after it, indented, give what the first line had to leave out, never cut: the error's whole message when the first
line is shorter, the refusing engine's own words as it wrote them (:attr:`KoenigCheckError.engine_texts`), and the
hint.  Every command's errors, the verdict of ``compare``, the pytest plugin and ``assert_energy_parity`` print
failures this way.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from koenig_check.findings import Finding, Kind
from koenig_check.line_width import LINE_LIMIT, fold

#: The indentation of the lines after a message's first line.
INDENT = "    "
#: A keyword's Python spelling in parentheses (``(repair_inertia=True)``), left out on the command line.
_PYTHON_SPELLING = re.compile(r" \(\w+=[^()]*\)")


def error_parts(err: BaseException) -> dict[str, object]:
    """What a failure's message is made of, as plain data (kept by a result after the exception is gone).

    Parameters
    ----------
    err : BaseException

    Returns
    -------
    dict
        ``whole`` (the message on one line), ``engine_texts`` (each refusing engine's label and own words),
        ``hint``, and ``unpaired`` (the engines' joints could not be paired).
    """
    from koenig_check.exceptions import JointMismatch, one_line

    return {
        "whole": one_line(err),
        "engine_texts": tuple(getattr(err, "engine_texts", ())),
        "hint": str(getattr(err, "hint", "") or ""),
        "unpaired": isinstance(err, JointMismatch),
    }


def detail_lines(
    err: BaseException | dict[str, object],
    first: str = "",
    rename: Callable[[str], str] | None = None,
    cli: bool = False,
    width: int = LINE_LIMIT,
) -> list[str]:
    """The indented lines that follow an error's first line: the rest of its message, the engine's words, the hint.

    Parameters
    ----------
    err : BaseException or dict
        The error, or its :func:`error_parts`.
    first : str
        The message's first line as printed: what it already says is not repeated.
    rename : callable, optional
        Applied to the texts (a resolved path written as the user gave it).
    cli : bool
        Options as the command line spells them (a keyword's Python spelling in parentheses left out).
    width : int
        The longest line: a long one is folded at words onto more indented lines, never cut.

    Returns
    -------
    list of str
        Empty when the first line says everything.  ``details:`` the parts of the whole message the first line
        left out; ``<Engine> says:`` the engine's text, line by line as it wrote it; ``hint:`` what would load it.
    """
    parts = err if isinstance(err, dict) else error_parts(err)

    def tidy(text: str) -> str:
        text = rename(text) if rename else text
        return _PYTHON_SPELLING.sub("", text) if cli else text

    said = " ".join(first.split())
    quoted: list[list[str]] = []
    for engine, text in parts.get("engine_texts", ()):  # type: ignore[attr-defined]
        words = [tidy(line.strip()) for line in str(text).splitlines() if line.strip()]
        if words:
            quoted.append([f"{engine} says: {words[0]}", *(f"  {w}" for w in words[1:])])
    hint = tidy(str(parts.get("hint", "")))
    hints = [[f"hint: {hint}"]] if hint and " ".join(hint.split()) not in said else []
    known = " ".join([said, hint, *(" ".join(line.split()) for item in quoted for line in item)])
    known = f"{known} {_unparenthesized(known)}"
    rest = [part for part in _parts(tidy(str(parts.get("whole", "")))) if _bare(part) and _bare(part) not in known]
    items = ([["details: " + "; ".join(rest)]] if rest else []) + quoted + hints
    return _indented(items, width)


def finding_lines(findings: Sequence[Finding], first: str = "", width: int = LINE_LIMIT) -> list[str]:
    """The indented lines after a model's verdict: each check asked for and not made, whole, with its hint.

    An engine the user named that could not check the model (``ENGINE_UNABLE``) gives its own reason in its
    finding; the verdict's first line may hold only the start of it.

    Parameters
    ----------
    findings : sequence of Finding
    first : str
        The verdict's first line as printed.
    width : int

    Returns
    -------
    list of str
    """
    said = " ".join(first.split())
    items = []
    for f in findings:
        if f.kind is not Kind.ENGINE_UNABLE:
            continue
        head, *text = f.summary.splitlines()  # the engine's own text, if any, on the lines after the first
        head = " ".join(head.split())
        shown = _said_part(head, said)
        if shown < len(head):  # the part of the reason the first line did not hold
            items.append([f"{f.engine}: " + (head if shown == 0 else "…" + head[shown:].lstrip(":; "))])
        if text:
            items.append([line[len(INDENT) :] if line.startswith(INDENT) else line.strip() for line in text])
        if f.hint and f.hint not in said:
            items.append([f"hint: {f.hint}"])
    return _indented(items, width)


def _said_part(head: str, said: str) -> int:
    """How much of ``head`` the first line already says: all of it, a part ending at a clause, or none (0)."""
    if head in said:
        return len(head)
    return max((end for end in clause_ends(head) if head[:end] in said), default=0)


def error_message(first: str, err: BaseException, **details: object) -> str:
    """``first`` and the lines of :func:`detail_lines` after it, one string.

    Parameters
    ----------
    first : str
        The first line.
    err : BaseException
    **details
        Passed to :func:`detail_lines` (``rename``, ``cli``, ``width``).

    Returns
    -------
    str
    """
    return "\n".join([first, *detail_lines(err, first, **details)])  # type: ignore[arg-type]


def first_and_rest(text: str, width: int = LINE_LIMIT) -> tuple[str, list[str]]:
    """A one-line message made a first line of whole parts that fit ``width``, and the indented lines of the rest.

    The message is split at its ``"; "`` outside parentheses; the first line keeps the leading parts that fit
    (at least the first), the others follow, whole, indented (``details:``): nothing is cut.

    Parameters
    ----------
    text : str
    width : int

    Returns
    -------
    first : str
    rest : list of str
    """
    parts = _parts(text)
    k = 1
    while k < len(parts) and len("; ".join(parts[: k + 1])) <= width:
        k += 1
    first, rest = "; ".join(parts[:k]), parts[k:]
    if len(first) > width:  # one part too long alone: at its last clause (": " or ", ") that fits
        ends = [i for i in clause_ends(first, (": ", ", ")) if i <= width]
        if ends:
            first, rest = first[: ends[-1]], [first[ends[-1] + 2 :], *rest]
    return first, _indented([["details: " + "; ".join(rest)]], width) if rest else []


def clause_ends(text: str, marks: tuple[str, ...] = (": ", "; ")) -> list[int]:
    """Where the clauses of ``text`` end: before each of ``marks`` outside parentheses and brackets.

    Parameters
    ----------
    text : str
    marks : tuple of str

    Returns
    -------
    list of int
        The index of each mark that ends a clause.
    """
    ends, depth = [], 0
    for i, ch in enumerate(text):
        depth += (ch in "([") - (ch in ")]")
        if depth == 0 and text.startswith(marks, i):
            ends.append(i)
    return ends


def _parts(text: str) -> list[str]:
    """A message's parts: split at each ``"; "`` outside parentheses."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += (ch in "([") - (ch in ")]")
        if depth == 0 and text.startswith("; ", i):
            parts.append(text[start:i])
            start = i + 2
    return [*parts, text[start:]]


def _unparenthesized(text: str) -> str:
    """``text`` without its parentheses (and what they hold), white space made single spaces."""
    out, depth = "", 0
    for ch in text:
        depth += ch == "("
        if depth == 0:
            out += ch
        depth -= ch == ")" and depth > 0
    return " ".join(out.split())


def _bare(part: str) -> str:
    """A part without its parentheses and without the file it opens with: what a shorter line keeps of it."""
    text = _unparenthesized(part)
    head, sep, rest = text.partition(": ")
    return rest if sep and ("/" in head or "." in head) else text


def _indented(items: list[list[str]], width: int) -> list[str]:
    """Each item's lines indented, a line too long folded at words under it."""
    out = []
    for item in items:
        for line in item:
            out += fold(INDENT + line, width, indent=2)
    return out
