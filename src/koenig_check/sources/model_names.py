"""The lines of ``koenig-check models``: each file once, with the name to type and the other names it answers to."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from koenig_check.sources.catalogue import DEFAULT_FORMAT, ModelSource, list_models, typed_name


@dataclass(frozen=True)
class ModelName:
    """One line of ``koenig-check models``: the name to type, the other names of the same file, where from.

    Attributes
    ----------
    name : str
        The unambiguous name (``gimbal.xml``, ``ur5_robot``, ``anymal_b_simple/anymal``).
    aliases : tuple of str
        Other names :func:`resolve_model` accepts for the same file (``gimbal``, ``ur5``, ``talos``).
    format : str
    source : str
        ``project`` or ``example-robot-data`` (the package is in the qualified alias ``<package>/<stem>``).
    path : Path
    """

    name: str
    aliases: tuple[str, ...]
    format: str
    source: str
    path: Path


def model_names() -> list[ModelName]:
    """Every model name and alias :func:`resolve_model` accepts, one entry per file.

    Returns
    -------
    list of ModelName
        Project models first, then example-robot-data, by name.
    """
    entries = []
    for s in list_models():
        if s.origin == "project":
            aliases = (s.name,) if s.format == DEFAULT_FORMAT or not _has_twin(s) else ()
            entries.append(ModelName(typed_name(s), aliases, s.format, "project", s.path))
            continue
        entries.append(ModelName(s.name, s.aliases, s.format, s.origin, s.path))
    return entries


def _has_twin(source: ModelSource) -> bool:
    return any(s.name == source.name and s.format != source.format for s in list_models("project"))
