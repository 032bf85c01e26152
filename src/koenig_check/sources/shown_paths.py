"""A model file named as the user gave it: messages name the resolved absolute path, a line names what was typed.

The loaders put the file's resolved path in their messages (``/home/me/robots/arm.urdf``, or a package's
site-packages path for a catalogue name); a one-line error names it the way the user wrote it (``arm.urdf``,
``../robots/arm.urdf``, ``ur5``) or by its label.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable
from pathlib import Path


def resolved_forms(given: str | os.PathLike[str]) -> list[str]:
    """The spellings of a model's path that messages may carry: resolved, absolute, and a catalogue name's file.

    Parameters
    ----------
    given : str or path
        The model as the user gave it (a path or a name from ``koenig-check models``).

    Returns
    -------
    list of str
        Longest first, never ``given`` itself.
    """
    text = os.fspath(given)
    path = Path(text).expanduser()
    forms = {str(path.absolute()), str(path.resolve())}
    if ":" not in text and not path.exists():  # a catalogue name (``go1``, ``anymal_b_simple/anymal``), not a source
        try:
            from koenig_check.sources.catalogue import resolve_model

            forms.add(str(resolve_model(text).path))
        except Exception:
            pass
    return sorted((f for f in forms if f != text and len(f) > 1), key=len, reverse=True)


def as_given(text: str, models: Iterable[str | os.PathLike[str]], short: bool = False) -> str:
    """``text`` with every resolved path of ``models`` written as the user gave it (or its file name).

    Parameters
    ----------
    text : str
        A message naming files by their resolved path.
    models : iterable of str or path
        The models (and other files) the user gave, as given.
    short : bool
        Name each by its file name instead (``arm.urdf`` for ``/a/long/way/to/arm.urdf``): for a line that would
        not fit otherwise.

    Returns
    -------
    str
    """
    pairs = []
    for given in models:
        shown = Path(os.fspath(given)).name if short else os.fspath(given)
        pairs += [(form, shown) for form in resolved_forms(given)]
        if short and os.fspath(given) != shown:
            pairs.append((os.fspath(given), shown))
    for form, shown in sorted(pairs, key=lambda p: len(p[0]), reverse=True):
        text = text.replace(form, shown)
    for given in models:
        text = _expansion_as_given(text, given, short)
    return text


def _expansion_as_given(text: str, given: str | os.PathLike[str], short: bool) -> str:
    """``text`` with the URDF a ``.xacro`` file expanded to (in the xacro cache) written as that file."""
    name = Path(os.fspath(given)).name
    if not name.endswith(".xacro"):
        return text
    from koenig_check.sources.xacro import cache_dir, expansion_stem

    shown = name if short else os.fspath(given)
    folder = re.escape(str(cache_dir()) + os.sep)
    expanded = folder + re.escape(expansion_stem(name)) + r"-[0-9a-f]{16}\.urdf"
    return re.sub(expanded, lambda _: shown, text)
