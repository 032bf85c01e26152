"""One entry point for models named by where they live: ``menagerie:NAME[:ENTRY]``, ``rd:NAME``, ``*.xacro``.

:func:`resolve_external` turns such a name into a local model file with a label saying where it came from;
:func:`prepare` does the part that can fail for want of an extra, a known name or a network (downloads and
clones) for a whole batch, before any model is loaded.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from koenig_check.sources import descriptions, menagerie
from koenig_check.sources.xacro import expand_xacro, xacro_available

#: The origins of external models, as :class:`koenig_check.sources.catalogue.ModelSource` records them.
ORIGINS = ("menagerie", "robot_descriptions", "xacro")


@dataclass(frozen=True)
class ExternalModel:
    """A model file found through its source.

    Attributes
    ----------
    label : str
        Where it came from, for reports (``menagerie:unitree_g1``, ``rd:ur5e_description``,
        ``arm.urdf.xacro [length=0.7]``).
    path : Path
        The local MJCF or URDF file (for xacro: the expanded URDF).
    origin : str
        One of :data:`ORIGINS`.
    package_dirs : tuple of Path
        Directories searched for ``package://`` URIs.
    """

    label: str
    path: Path
    origin: str
    package_dirs: tuple[Path, ...] = ()


def kind_of(model: Any) -> str | None:
    """Which source a model name belongs to, from its spelling alone.

    Parameters
    ----------
    model : str or path

    Returns
    -------
    str or None
        ``"menagerie"``, ``"robot_descriptions"``, ``"xacro"``, or ``None`` for any other name or path.
    """
    if not isinstance(model, str | os.PathLike):
        return None
    text = os.fspath(model)
    if text.startswith(menagerie.PREFIX):
        return "menagerie"
    if text.startswith(descriptions.PREFIX):
        return "robot_descriptions"
    if text.lower().endswith(".xacro"):
        return "xacro"
    return None


def is_external(model: Any) -> bool:
    """Whether :func:`resolve_external` handles this name.

    Parameters
    ----------
    model : str or path

    Returns
    -------
    bool
    """
    return kind_of(model) is not None


def source_label(model: Any, xacro_args: Sequence[tuple[str, str]] = ()) -> str | None:
    """The label of an external model, or ``None`` for other names.

    Parameters
    ----------
    model : str or path
    xacro_args : pairs
        Shown after a xacro file's name (they make another robot of the same file).

    Returns
    -------
    str or None
    """
    kind = kind_of(model)
    if kind is None:
        return None
    text = os.fspath(model)
    if kind == "xacro" or (kind == "robot_descriptions" and xacro_args):
        name = Path(text).name if kind == "xacro" else text
        return f"{name} [{', '.join(f'{k}={v}' for k, v in xacro_args)}]" if xacro_args else name
    return text


def resolve_external(model: Any, xacro_args: Sequence[tuple[str, str]] = ()) -> ExternalModel | None:
    """The local file of an external model (downloading, cloning or expanding it as needed).

    Parameters
    ----------
    model : str or path
        ``menagerie:NAME[:ENTRY]``, ``rd:NAME`` or a ``.xacro`` file; anything else gives ``None``.
    xacro_args : pairs
        ``$(arg)`` values for a xacro file (or a description's xacro file).

    Returns
    -------
    ExternalModel or None

    Raises
    ------
    koenig_check.sources.errors.ModelSourceError
        A missing extra, an unknown name (with the closest ones), a download or clone that cannot happen.
    koenig_check.exceptions.ModelLoadError
        A xacro file that is missing or does not expand.
    """
    kind = kind_of(model)
    if kind is None:
        return None
    text = os.fspath(model)
    label = source_label(model, xacro_args) or text
    if kind == "menagerie":
        path = menagerie.menagerie_file(text)
        return ExternalModel(label, path, kind, (path.parent, *path.parents[:3]))
    if kind == "robot_descriptions":
        path, dirs = descriptions.description_file(text, dict(xacro_args))
        return ExternalModel(label, path, kind, (*dirs, *path.parents[:4]))
    source = Path(text).expanduser()
    urdf = expand_xacro(source, xacro_args, label=label)
    return ExternalModel(label, urdf, kind, tuple(source.resolve().parents[:4]))


def prepare(models: Iterable[Any]) -> None:
    """Check and fetch every external model of a batch before any of them is loaded.

    Extras installed, names known, Menagerie robots downloaded and descriptions cloned (once: the files stay
    in their caches); xacro files are expanded later, model by model, so that a bad file costs only itself.

    Parameters
    ----------
    models : iterable of str or path
        Any model names; those that are not external are skipped.

    Raises
    ------
    koenig_check.sources.errors.ModelSourceError
        The first model that cannot be had, in one line saying what to install or set.
    """
    for model in models:
        kind = kind_of(model)
        text = os.fspath(model) if kind else ""
        if kind == "menagerie":
            menagerie.menagerie_file(text)
        elif kind == "robot_descriptions":
            module = descriptions.description_module(text)
            if not any(getattr(module, a, None) for a in descriptions.FILE_ATTRIBUTES):
                xacro_available(text)
        elif kind == "xacro":
            xacro_available(text)
