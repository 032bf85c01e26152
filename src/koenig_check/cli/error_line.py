"""The message of an error that stops a command: a short first line naming the file as the user gave it, then more.

The lines after the first, indented, give the rest of the error whole: the engine's own words and the hint.
"""

from __future__ import annotations

import argparse

from koenig_check.line_width import LINE_LIMIT

#: What starts the line.
PREFIX = "koenig-check: error: "


def given_files(args: argparse.Namespace) -> list[str]:
    """The model files and names the user gave a command (models, the Pinocchio model, a pose file).

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    list of str
    """
    found: list[str] = []
    for name in ("model", "models", "check_only", "pinocchio_model", "pose_file"):
        value = getattr(args, name, None)
        values = value if isinstance(value, list | tuple) else [value]
        found += [str(v) for v in values if v]
    return found


def error_line(args: argparse.Namespace, err: BaseException) -> str:
    """``koenig-check: error: <error>`` in at most :data:`LINE_LIMIT` characters.

    The file is named as the user gave it, or by its file name when the path as given takes more than half the
    line and the line would not fit otherwise; the error's root causes are named in a few words each, at most
    three (:func:`short_error`).

    Parameters
    ----------
    args : argparse.Namespace
    err : BaseException

    Returns
    -------
    str
    """
    from koenig_check.diagnosis.reason import short_error
    from koenig_check.sources.shown_paths import as_given

    files = given_files(args)
    width = LINE_LIMIT - len(PREFIX)
    line = short_error(err, width, lambda text: as_given(text, files))
    whole = short_error(err, 10**6, lambda text: as_given(text, files))
    named = [f for f in files if f in whole]
    cut = line.endswith("…")  # its first part alone is too long with the paths as given: the files by their names
    if not cut and (len(whole) <= width or max(map(len, named), default=0) <= width // 2):  # the file as given
        return PREFIX + line
    return PREFIX + short_error(err, width, lambda text: as_given(text, files, short=True))


def error_lines(args: argparse.Namespace, err: BaseException, first: str) -> list[str]:
    """The indented lines after an error's first line: its whole message, the engine's own words, the hint.

    Parameters
    ----------
    args : argparse.Namespace
    err : BaseException
    first : str
        The first line (:func:`error_line`).

    Returns
    -------
    list of str
    """
    from koenig_check.diagnosis.message import detail_lines
    from koenig_check.sources.shown_paths import as_given

    files = given_files(args)
    return detail_lines(err, first, lambda text: as_given(text, files), cli=True)
