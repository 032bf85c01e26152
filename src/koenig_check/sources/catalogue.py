"""Find model files by name or path: project models, example-robot-data robots, plain paths.

Names
-----
* Project models live in the repository's ``models/`` directory, installed with the package as
  the package data ``koenig_check.models``.  The environment variable ``KOENIG_CHECK_MODELS``
  overrides the location.  Their name is the file stem; the same mechanism usually exists as ``.xml`` (MJCF) and
  ``.urdf``: ``"name.xml"`` and ``"name.urdf"`` pick one, and the bare name means the MJCF file
  (:data:`DEFAULT_FORMAT`).  A relative path such as ``models/gimbal.xml`` that does not exist where the
  caller runs is read from the project's root.
* example-robot-data (version 6 installs its robots as data files under its install prefix, with no
  Python loader) is located through ``importlib.metadata``.  A robot's name is its file stem
  (``ur5_robot``, ``panda``, ``talos_reduced``...).  When a stem occurs in several packages, or
  clashes with a project model, the name becomes ``"<package>/<stem>"`` where ``<package>`` is the
  package directory without its ``_description``/``_data`` suffix (``anymal_b_simple/anymal``).
  The qualified form is accepted for every robot.  Aliases: a stem without its ``_robot`` suffix
  (``ur5`` for ``ur5_robot``) and a few historical loader names (``talos`` for ``talos_reduced``).

The listing of these names is :mod:`koenig_check.sources.model_names`; mesh URIs inside a file are resolved by
:mod:`koenig_check.sources.uris`.
"""

from __future__ import annotations

import difflib
import importlib.metadata
import importlib.resources
import os
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from koenig_check.exceptions import ModelLoadError
from koenig_check.modelfile.validate import ModelFileError, preflight
from koenig_check.sources.uris import resolve_uri

__all__ = [
    "DEFAULT_FORMAT",
    "ModelSource",
    "accepted_names",
    "detect_format",
    "example_robot_data_dirs",
    "list_models",
    "project_models_dir",
    "resolve_model",
    "resolve_uri",
    "suggest_names",
    "typed_name",
]

#: Names the historical example-robot-data loaders used for files whose stem differs.
LEGACY_ALIASES = {"talos": "talos_reduced", "talos_full": "talos_full_v2", "talos_arm": "talos_left_arm"}
_ERD_DIST = "example-robot-data"
_ERD_ROBOTS = "share/example-robot-data/robots"
_SUFFIX_FORMAT = {".urdf": "urdf", ".mjcf": "mjcf"}


@dataclass(frozen=True)
class ModelSource:
    """One loadable model file.

    Parameters
    ----------
    name : str
        Short name accepted by :func:`resolve_model`.
    path : Path
        Absolute path of the file.
    format : str
        ``"mjcf"`` or ``"urdf"``.
    origin : str
        ``"project"``, ``"example-robot-data"``, ``"file"``, or where an external model came from
        (``"menagerie"``, ``"robot_descriptions"``, ``"xacro"``: :mod:`koenig_check.sources`).
    aliases : tuple of str
        Other names that resolve to this file.
    package_dirs : tuple of Path
        Directories searched for ``package://`` mesh URIs.
    """

    name: str
    path: Path
    format: str
    origin: str
    aliases: tuple[str, ...] = ()
    package_dirs: tuple[Path, ...] = field(default=(), compare=False)


def detect_format(path: Path) -> str:
    """Return ``"mjcf"`` or ``"urdf"`` for a model file.

    Parameters
    ----------
    path : Path

    Returns
    -------
    str

    Raises
    ------
    ModelLoadError
        If the root element is neither ``<mujoco>`` nor ``<robot>``.
    """
    path = Path(path)
    if path.suffix.lower() in _SUFFIX_FORMAT:
        return _SUFFIX_FORMAT[path.suffix.lower()]
    try:
        return preflight(path)
    except ModelFileError as exc:
        raise ModelLoadError(str(exc)) from None


def project_models_dir() -> Path | None:
    """Return the directory of the project's own models, or ``None`` if not found.

    Returns
    -------
    Path or None
        ``$KOENIG_CHECK_MODELS`` if set, else the package data ``koenig_check.models`` (the
        repository's ``models/`` directory, shipped with the package by ``pyproject.toml`` and
        mapped to it in an editable install).
    """
    env = os.environ.get("KOENIG_CHECK_MODELS")
    if env:
        return Path(env).resolve()
    try:
        root = Path(str(importlib.resources.files("koenig_check.models")))
    except ModuleNotFoundError:
        return None
    return root if root.is_dir() else None


@cache
def example_robot_data_dirs() -> tuple[Path, Path] | None:
    """Locate example-robot-data's installed robots.

    Returns
    -------
    (share, robots) or None
        ``share`` holds the ``example-robot-data`` package directory (for ``package://`` URIs),
        ``robots`` the robot packages.  ``None`` if the distribution is not installed.
    """
    try:
        dist = importlib.metadata.distribution(_ERD_DIST)
    except importlib.metadata.PackageNotFoundError:
        return None
    for f in dist.files or []:
        parts = Path(str(f)).parts
        for i in range(len(parts) - 3):
            if parts[i : i + 3] == ("share", "example-robot-data", "robots"):
                robots = Path(str(dist.locate_file(Path(*parts[: i + 3])))).resolve()
                return robots.parent.parent, robots
    return None


def _package_short(pkg: str) -> str:
    for suffix in ("_description", "_data"):
        if pkg.endswith(suffix):
            return pkg[: -len(suffix)]
    return pkg


def _erd_package_dirs() -> tuple[Path, ...]:
    dirs = example_robot_data_dirs()
    return () if dirs is None else (dirs[0], dirs[1])


@cache
def _catalogue() -> tuple[ModelSource, ...]:
    entries: list[ModelSource] = []
    project = project_models_dir()
    project_names: set[str] = set()
    if project is not None and project.is_dir():
        for path in sorted(project.iterdir()):
            if path.suffix.lower() not in (".xml", ".urdf", ".mjcf"):
                continue
            try:
                fmt = detect_format(path)
            except ModelLoadError:
                continue
            entries.append(ModelSource(path.stem, path, fmt, "project", (), (project,)))
            project_names.add(path.stem)
    dirs = example_robot_data_dirs()
    if dirs is not None:
        share, robots = dirs
        files = sorted(robots.glob("*/**/*.urdf"))
        stems = [p.stem for p in files]
        taken = set(project_names)
        for path in files:
            pkg = path.relative_to(robots).parts[0]
            qualified = f"{_package_short(pkg)}/{path.stem}"
            unique = stems.count(path.stem) == 1 and path.stem not in project_names
            name = path.stem if unique else qualified
            aliases: list[str] = []
            if unique:
                aliases.append(qualified)
            if unique and path.stem.endswith("_robot"):
                aliases.append(path.stem[: -len("_robot")])
            aliases += [alias for alias, target in LEGACY_ALIASES.items() if unique and target == path.stem]
            aliases = [a for a in aliases if a not in taken and a not in stems]
            taken.update([name, *aliases])
            entries.append(ModelSource(name, path, "urdf", "example-robot-data", tuple(aliases), (share, robots)))
    return tuple(entries)


def list_models(origin: str | None = None) -> list[ModelSource]:
    """Return every model found by name: the project's models and example-robot-data's URDFs.

    Parameters
    ----------
    origin : str, optional
        Keep only ``"project"`` or ``"example-robot-data"`` entries.

    Returns
    -------
    list of ModelSource
        Sorted by origin then name.  Whether a model loads in both engines is decided by
        :func:`koenig_check.engines.load_model`, not here.
    """
    items = [s for s in _catalogue() if origin is None or s.origin == origin]
    return sorted(items, key=lambda s: (s.origin != "project", s.name, s.format))


def resolve_model(
    name_or_path: str | os.PathLike[str], fmt: str | None = None, *, xacro_args: tuple[tuple[str, str], ...] = ()
) -> ModelSource:
    """Turn a short name or a path into a :class:`ModelSource`.

    Parameters
    ----------
    name_or_path : str or path
        An existing file, a name from :func:`list_models`, an alias, or ``"name.urdf"`` /
        ``"name.xml"`` to pick the format of a project model; or a model named by its source,
        ``menagerie:NAME[:ENTRY]``, ``rd:NAME`` or a ``.xacro`` file (:mod:`koenig_check.sources`).
    fmt : str, optional
        ``"mjcf"`` or ``"urdf"`` to disambiguate a name.
    xacro_args : tuple of (str, str)
        ``$(arg)`` values of a xacro model (:attr:`LoadOptions.xacro_args`).

    Returns
    -------
    ModelSource

    Raises
    ------
    ModelLoadError
        If the name is unknown or ambiguous, or a xacro file does not expand.
    koenig_check.sources.ModelSourceError
        If a source's extra is missing, its name unknown, or its download cannot happen.
    """
    if fmt not in (None, "mjcf", "urdf"):
        raise ValueError(f"fmt must be 'mjcf', 'urdf' or None, got {fmt!r}")
    text = os.fspath(name_or_path)
    from koenig_check.sources.external import resolve_external

    external = resolve_external(text, xacro_args)
    if external is not None:
        kind = preflight(external.path)
        return ModelSource(external.label, external.path, kind, external.origin, (), external.package_dirs)
    path = Path(text).expanduser()
    if not (path.is_file() or path.is_absolute() or path.is_dir()):
        path = _project_relative(path) or path
    if path.is_file() or path.is_absolute() or path.is_dir():
        path = path.resolve()
        dirs = tuple(path.parents[:4]) + _erd_package_dirs()
        fmt_found = preflight(path)  # missing, empty, not XML, DOCTYPE...: a one-line ModelFileError
        return ModelSource(path.stem, path, fmt_found, "file", (), dirs)
    name = text
    suffix = Path(text).suffix.lower()
    if suffix in (".xml", ".mjcf", ".urdf"):
        name = text[: -len(suffix)]
        fmt = fmt or ("urdf" if suffix == ".urdf" else "mjcf")
    catalogue = _catalogue()
    hits = [s for s in catalogue if s.name == name or name in s.aliases]
    if fmt is not None:
        hits = [s for s in hits if s.format == fmt]
    if len(hits) > 1 and fmt is None and {s.origin for s in hits} == {"project"}:
        hits = [s for s in hits if s.format == DEFAULT_FORMAT]  # a project model in both formats: MJCF
    if len(hits) == 1:
        return hits[0]
    if not hits and fmt is None:  # a stem that only exists qualified (anymal: two packages)
        hits = [s for s in catalogue if s.origin == "example-robot-data" and s.name.split("/")[-1] == name]
    if len(hits) > 1:
        options = sorted(typed_name(s) for s in hits)
        raise ModelLoadError(f"{text}: ambiguous model name, it names {len(hits)} models: {', '.join(options)}")
    if len(hits) == 1:
        return hits[0]
    looks_like_file = bool(suffix) or "/" in text or os.sep in text
    close = suggest_names(name, strict=looks_like_file)
    hint = f"; did you mean {' or '.join(close)}?" if close else ""
    what = "no such file" if looks_like_file else "no such file and no model of that name"
    raise ModelLoadError(f"{text}: {what} (`koenig-check models` lists every name){hint}")


#: The format a bare project-model name means when the model exists in both (``gimbal`` = ``gimbal.xml``).
DEFAULT_FORMAT = "mjcf"


def typed_name(source: ModelSource) -> str:
    """The name to type for a model: a project model with its suffix (``gimbal.xml``), else its name.

    Parameters
    ----------
    source : ModelSource

    Returns
    -------
    str
    """
    if source.origin == "project":
        return f"{source.name}.{'urdf' if source.format == 'urdf' else 'xml'}"
    return source.name


def _project_relative(path: Path) -> Path | None:
    """A relative path such as ``models/gimbal.xml`` read from the project's root, wherever the caller runs."""
    project = project_models_dir()
    if project is None or path.is_absolute() or not path.parts:
        return None
    candidate = project.parent / path
    return candidate if candidate.is_file() else None


def accepted_names() -> list[str]:
    """Every spelling :func:`resolve_model` accepts by name: names, aliases and ``name.xml``/``name.urdf``.

    Returns
    -------
    list of str
    """
    names: set[str] = set()
    for s in _catalogue():
        names.add(s.name)
        names.update(s.aliases)
        if s.origin == "project":
            names.add(typed_name(s))
    return sorted(names)


def suggest_names(name: str, strict: bool = False) -> list[str]:
    """Close names from :func:`accepted_names` only (at most five).

    Parameters
    ----------
    name : str
        The name asked for (without a ``.xml``/``.urdf`` suffix).
    strict : bool
        The input looked like a file path: suggest only very close names.

    Returns
    -------
    list of str
    """
    known = accepted_names()
    stem = Path(name).name
    close = difflib.get_close_matches(stem, known, n=5, cutoff=0.85 if strict else 0.6)
    if not strict:
        close += [k for k in known if stem and stem in k.split("/")[-1] and k not in close]
    return close[:5]
