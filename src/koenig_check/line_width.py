"""Lines that fit a screen: every line the command line prints is at most :data:`LINE_LIMIT` characters.

A message's first line (an error, a reason) is made shorter by whole parts, the rest given whole on indented lines
after it (:mod:`koenig_check.diagnosis.message`); detail views and tables fold a long line at words onto indented
continuation lines (:func:`fold`, :func:`fold_text`).  :func:`cut` is the last resort of a single part too long.
"""

from __future__ import annotations

import re
import textwrap

#: The longest line the command line prints (a single word longer than this, e.g. a path the user typed, is
#: the only exception: it is never cut).
LINE_LIMIT = 200


def fold(line: str, width: int = LINE_LIMIT, indent: int = 4) -> list[str]:
    """A line over ``width`` folded at words, the continuation lines indented ``indent`` more than the line.

    Parameters
    ----------
    line : str
    width : int
    indent : int

    Returns
    -------
    list of str
        ``[line]`` when it fits; words are never cut (a word too long for its indented line is indented less, one
        longer than ``width`` stays whole on a line of its own).
    """
    if len(line) <= width:
        return [line]
    text = line.lstrip(" ")
    lead = " " * (len(line) - len(text))
    more = " " * min(len(lead) + indent, width // 2)
    lines = textwrap.wrap(
        text,
        width=width,
        initial_indent=lead,
        subsequent_indent=more,
        break_long_words=False,
        break_on_hyphens=False,
    )
    return [_unindented(line, width) for line in lines]


def _unindented(line: str, width: int) -> str:
    """A line holding one long word (a path): indented less, or not at all, so that it fits if it can."""
    if len(line) <= width or " " in line.strip():
        return line
    word = line.strip()
    return " " * max(width - len(word), 0) + word if len(word) < width else word


def fold_text(text: str, width: int = LINE_LIMIT, indent: int = 4) -> str:
    """Every line of ``text`` folded with :func:`fold`.

    Parameters
    ----------
    text : str
    width, indent : int

    Returns
    -------
    str
    """
    return "\n".join(part for line in text.split("\n") for part in fold(line, width, indent))


def hanging(cells: str, text: str, width: int = LINE_LIMIT) -> list[str]:
    """A table row: its ``cells``, then ``text`` folded at words under its own column when the row is too long.

    Parameters
    ----------
    cells : str
        The row up to the last column (padded).
    text : str
        The last column (a verdict, a cause, the worst entry).
    width : int

    Returns
    -------
    list of str
    """
    if len(cells) + len(text) <= width:
        return [cells + text]
    first, *rest = fold(" " * len(cells) + text, width, indent=0)
    return [cells + first[len(cells) :], *rest]


def elided_paths(text: str, width: int = LINE_LIMIT) -> str:
    """``text`` with its long paths shortened to ``…/parent/name``, longest first, until it fits ``width``.

    For a one-line message that names a path the user typed and cannot fit it whole (the name and the folder
    it is in stay).

    Parameters
    ----------
    text : str
    width : int

    Returns
    -------
    str
    """
    paths = sorted(set(re.findall(r"/[^\s'\"]+/[^\s'\"]+/[^\s'\"]+", text)), key=len, reverse=True)
    for path in paths:
        if len(text) <= width:
            break
        parts = path.rstrip("/").split("/")
        text = text.replace(path, "…/" + "/".join(parts[-2:]))
    return text


def cut(text: str, width: int) -> str:
    """``text`` when it fits ``width``, else cut at the last word that fits, with ``…``.

    Parameters
    ----------
    text : str
    width : int

    Returns
    -------
    str
    """
    if len(text) <= width:
        return text
    kept = text[: width - 1].rsplit(" ", 1)[0].rstrip(" ;,:(")
    return f"{kept}…"


def closed_cut(text: str, width: int) -> str:
    """``text`` cut at a word to fit ``width`` (``…``), never inside a parenthesis or bracket it opens.

    Parameters
    ----------
    text : str
    width : int

    Returns
    -------
    str
    """
    if len(text) <= width:
        return text
    kept = cut(text, width)[:-1]
    pairs = {"(": ")", "[": "]", "{": "}"}
    while True:
        opened: list[int] = []
        for i, ch in enumerate(kept):
            if ch in pairs:
                opened.append(i)
            elif ch in pairs.values() and opened:
                opened.pop()
        if not opened:
            return kept.rstrip(" ;,:") + "…"
        kept = kept[: opened[0]].rstrip(" ;,:(")
