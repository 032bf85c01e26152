"""MuJoCo Menagerie robots by name: ``menagerie:NAME[:ENTRY]``, through the ``mujoco-menagerie`` package.

The package (extra ``[menagerie]``) ships the registry of robots (name, category, entry points) and resolves a
robot to a local directory: a checkout named by ``MENAGERIE_ROOT``, or a checksummed copy downloaded once into
``MENAGERIE_CACHE_DIR`` (from ``MENAGERIE_BASE_URL``, GitHub by default).  ``menagerie:NAME`` is the robot's
``default_model`` (the robot alone: a scene pulls it in through ``<include>``, which Pinocchio does not read);
``menagerie:NAME:ENTRY`` is any other entry point (``scene``, ``g1_mjx``...).
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

from koenig_check.exceptions import one_line
from koenig_check.sources.errors import ModelSourceError, missing_extra

PREFIX = "menagerie:"
#: What to set when a robot cannot be had locally.
CACHE_HINT = (
    "set MENAGERIE_ROOT to a Menagerie checkout, MENAGERIE_CACHE_DIR to a cache that holds the robot, "
    "or MENAGERIE_BASE_URL to a reachable mirror"
)


def _package(model: str) -> ModuleType:
    try:
        import mujoco_menagerie
    except ImportError:
        raise missing_extra(model, "menagerie", "mujoco-menagerie") from None
    return mujoco_menagerie


def _close(name: str, known: list[str]) -> list[str]:
    """Close names: spelling first, then names that contain the one typed (``g1`` → ``unitree_g1``)."""
    close = difflib.get_close_matches(name, known, n=3, cutoff=0.6)
    close += [k for k in known if name and name in k and k not in close]
    return close[:3]


def parse(model: str) -> tuple[str, str | None]:
    """Split ``menagerie:NAME[:ENTRY]`` into the robot's name and the entry point (``None``: default model).

    Parameters
    ----------
    model : str

    Returns
    -------
    (str, str or None)

    Raises
    ------
    ModelSourceError
        When the name is empty or there are more than three parts.
    """
    parts = model[len(PREFIX) :].split(":")
    if not parts[0] or len(parts) > 2 or (len(parts) == 2 and not parts[1]):
        raise ModelSourceError(f"{model}: expected menagerie:NAME or menagerie:NAME:ENTRY")
    return parts[0], parts[1] if len(parts) == 2 else None


def robot_entry(model: str) -> tuple[Any, Any]:
    """The registry's robot and entry point named by ``menagerie:NAME[:ENTRY]`` (metadata only, no I/O).

    Parameters
    ----------
    model : str

    Returns
    -------
    (mujoco_menagerie.Robot, mujoco_menagerie.EntryPoint)

    Raises
    ------
    ModelSourceError
        The extra is missing, or the robot or the entry point is unknown (with the closest names).
    """
    mm = _package(model)
    name, entry = parse(model)
    try:
        robot = mm.get(name)
    except mm.UnknownRobotError:
        close = _close(name, mm.names())
        hint = f"; did you mean {', '.join(PREFIX + c for c in close)}?" if close else ""
        raise ModelSourceError(
            f"{model}: no Menagerie robot {name!r} (`koenig-check models --menagerie` lists them){hint}"
        ) from None
    try:
        return robot, robot.entry(entry or robot.default_model)
    except mm.UnknownEntryPointError:
        close = _close(str(entry), list(robot.entry_names))
        hint = f"; did you mean {PREFIX}{name}:{close[0]}?" if close else ""
        raise ModelSourceError(
            f"{model}: {name} has no entry point {entry!r}; its entry points: {', '.join(robot.entry_names)}{hint}"
        ) from None


def menagerie_file(model: str) -> Path:
    """The local file of ``menagerie:NAME[:ENTRY]``, downloaded into the cache first if needed.

    Parameters
    ----------
    model : str

    Returns
    -------
    Path
        ``<robot directory>/<entry file>``.

    Raises
    ------
    ModelSourceError
        Missing extra, unknown name or entry, or a robot that is neither under ``MENAGERIE_ROOT`` nor in the
        cache and cannot be downloaded (the message says which variable to set).
    """
    mm = _package(model)
    robot, entry = robot_entry(model)
    try:
        cache = mm.Cache()
        directory = cache.resolve(robot, mm.print_progress)
    except (mm.MenagerieError, OSError) as err:
        reason = one_line(err)
        raise ModelSourceError(
            f"{model}: Menagerie robot {robot.name!r} is not available here ({reason}); {CACHE_HINT}"
        ) from None
    return Path(directory) / entry.file


@dataclass(frozen=True)
class MenagerieRobot:
    """One line of ``koenig-check models --menagerie``.

    Attributes
    ----------
    name : str
        What follows ``menagerie:``.
    category : str
        The registry's category (``arm``, ``humanoid``, ``quadruped``...).
    default_model : str
        The entry ``menagerie:NAME`` means.
    other_entries : tuple of str
        Entries for ``menagerie:NAME:ENTRY``.
    display_name : str
    local : bool
        Whether it is here without a download (under ``MENAGERIE_ROOT`` or in the cache).
    """

    name: str
    category: str
    default_model: str
    other_entries: tuple[str, ...]
    display_name: str
    local: bool


def menagerie_robots() -> list[MenagerieRobot]:
    """Every robot of the installed registry, by category then name.

    Returns
    -------
    list of MenagerieRobot

    Raises
    ------
    ModelSourceError
        If the extra is missing.
    """
    mm = _package("models --menagerie")
    cache = mm.Cache()
    rows = []
    for robot in mm.robots():
        local = (cache.root / robot.name).is_dir() if cache.root else cache.is_cached(robot)
        others = tuple(e for e in robot.entry_names if e != robot.default_model)
        rows.append(MenagerieRobot(robot.name, robot.category, robot.default_model, others, robot.display_name, local))
    return sorted(rows, key=lambda r: (r.category, r.name))


def menagerie_where() -> str:
    """Where robots are read from: the checkout, or the cache and the mirror it downloads from.

    Returns
    -------
    str
    """
    mm = _package("models --menagerie")
    cache = mm.Cache()
    if cache.root:
        return f"MENAGERIE_ROOT={cache.root}"
    return f"cache {cache.dir} (MENAGERIE_CACHE_DIR), downloads from {cache.base_url}"
