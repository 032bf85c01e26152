"""Lines that fit a screen: every line the command line prints is at most :data:`LINE_LIMIT` characters.

One-line messages (errors, reasons) are made shorter, never folded (:func:`cut` is their last resort); detail
views and tables fold a long line at words onto indented continuation lines (:func:`fold`, :func:`fold_text`).
"""

from __future__ import annotations

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
        ``[line]`` when it fits; words are never cut (a word longer than ``width`` stays whole on its line).
    """
    if len(line) <= width:
        return [line]
    text = line.lstrip(" ")
    lead = " " * (len(line) - len(text))
    more = " " * min(len(lead) + indent, width // 2)
    return textwrap.wrap(
        text,
        width=width,
        initial_indent=lead,
        subsequent_indent=more,
        break_long_words=False,
        break_on_hyphens=False,
    )


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
