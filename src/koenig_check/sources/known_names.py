"""Model arguments checked before any work: a name that is neither a file nor a known model is a usage error.

A command-line model argument is one of

* a model named by its source (``menagerie:NAME``, ``rd:NAME``, ``*.xacro``): checked by
  :func:`koenig_check.sources.external.prepare`;
* an existing file, or a project-relative path such as ``models/gimbal.xml``;
* a path that does not exist (it has a ``/`` or a ``.xml``/``.urdf``/``.mjcf`` suffix): a *missing file*, which
  fails that model alone with a one-line error naming it (a batch keeps its other results);
* a name from ``koenig-check models`` (with its aliases and ``name.xml`` / ``name.urdf``);
* anything else: an unknown name, refused here as a usage error (exit status 2) with the closest known names;
  so is a name that names several models (``anymal``), with the names to type instead.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from koenig_check.sources.errors import ModelSourceError

#: Suffixes that make an argument a file path rather than a model name.
FILE_SUFFIXES = (".xml", ".urdf", ".mjcf")


def looks_like_path(text: str) -> bool:
    """Whether an argument is written as a file path (a directory separator or a model file's suffix).

    Parameters
    ----------
    text : str

    Returns
    -------
    bool
    """
    return "/" in text or os.sep in text or Path(text).suffix.lower() in FILE_SUFFIXES


def unknown_name(model: Any) -> str | None:
    """The one-line reason a plain model name is unknown, or ``None`` when it is a file, a path or a known name.

    Parameters
    ----------
    model : str or path

    Returns
    -------
    str or None
        ``"NAME: no model of that name and no such file; closest: a, b (`koenig-check models` lists them)"``.
    """
    from koenig_check.sources.catalogue import accepted_names, suggest_names
    from koenig_check.sources.external import is_external

    if not isinstance(model, str) or is_external(model):
        return None
    known = accepted_names()
    stems = {name.split("/")[-1] for name in known}  # a stem in two packages: ambiguous, not unknown
    if looks_like_path(model) or Path(model).expanduser().exists() or model in known or model in stems:
        return None
    close = suggest_names(model)
    hint = f"; closest: {', '.join(close)}" if close else ""
    return f"{model}: no model of that name and no such file{hint} (`koenig-check models` lists them)"


def ambiguous_name(model: Any) -> str | None:
    """The one-line reason a plain model name names several models, or ``None`` when it names at most one.

    A stem found in two packages (``anymal``: ``anymal_b_simple/anymal`` and ``anymal_c_simple/anymal``) cannot be
    loaded whatever the run does: the user types one of the qualified names.

    Parameters
    ----------
    model : str or path

    Returns
    -------
    str or None
        ``"NAME: ambiguous model name, it names 2 models: a, b (type one of them)"``.
    """
    from koenig_check.sources.catalogue import accepted_names
    from koenig_check.sources.external import is_external

    if not isinstance(model, str) or is_external(model) or looks_like_path(model) or Path(model).expanduser().exists():
        return None
    known = accepted_names()
    if model in known:
        return None
    hits = sorted(name for name in known if "/" in name and name.split("/")[-1] == model)
    if len(hits) < 2:
        return None
    return f"{model}: ambiguous model name, it names {len(hits)} models: {', '.join(hits)} (type one of them)"


def check_model_names(models: Iterable[Any]) -> None:
    """Refuse the first unknown or ambiguous model name of a batch before any model is loaded.

    Parameters
    ----------
    models : iterable of str or path

    Raises
    ------
    ModelSourceError
        The name and its closest known names, or the models an ambiguous name names, in one line (a usage error:
        exit status 2).
    """
    for model in models:
        reason = unknown_name(model) or ambiguous_name(model)
        if reason is not None:
            raise ModelSourceError(reason)
