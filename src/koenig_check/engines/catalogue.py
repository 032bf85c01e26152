"""The catalogue: every cause declared by the engine subpackages, found once, looked up by id.

An engine subpackage declares the causes it is subject to in ``engines/<name>/causes.py`` as ``CAUSES``; a new
engine brings its causes with it (and their fixtures, in ``engines/<name>/fixtures/`` or the shared
``koenig_check/causes/fixtures/``) and nothing here changes.
"""

from __future__ import annotations

import difflib
import importlib
import importlib.metadata
import importlib.resources
import importlib.util
from functools import cache
from pathlib import Path
from types import ModuleType

from packaging.specifiers import SpecifierSet
from packaging.version import InvalidVersion, Version

from koenig_check.engines.cause import Cause
from koenig_check.engines.specs import ENGINES_PACKAGE, EngineSpec, spec, specs


def catalogue() -> tuple[Cause, ...]:
    """Every declared cause, ordered by id.

    Returns
    -------
    tuple of Cause

    Raises
    ------
    ValueError
        Two declarations share an id, a cause is declared by a subpackage other than its engine's, or a
        reading names an engine that does not exist.
    """
    return _collected(specs())


def cause_modules(declared: tuple[EngineSpec, ...]) -> list[tuple[EngineSpec, ModuleType]]:
    """Each declared engine's ``engines/<name>/causes.py``, imported; engines without one are left out.

    Parameters
    ----------
    declared : tuple of EngineSpec

    Returns
    -------
    list of (EngineSpec, module)
    """
    names = [(s, f"{ENGINES_PACKAGE}.{s.name}.causes") for s in declared]
    return [(s, importlib.import_module(m)) for s, m in names if importlib.util.find_spec(m) is not None]


@cache
def _collected(declared: tuple[EngineSpec, ...]) -> tuple[Cause, ...]:
    """The causes of the engines declared (found once per set of engines: a test may add one)."""
    found: list[Cause] = []
    engines = {s.name for s in declared}
    for s, module in cause_modules(declared):
        for c in module.CAUSES:
            if c.engine != s.name:
                raise ValueError(f"{module.__name__}: cause {c.id} belongs to engine {c.engine}, not {s.name}")
            unknown = sorted({r.engine for r in c.readings} - engines)
            if unknown:
                raise ValueError(f"cause {c.id}: readings of unknown engines {unknown}")
            found.append(c)
    ids = [c.id for c in found]
    unknown_twin = sorted({t for c in found for t in c.twin_causes} - set(ids))
    if unknown_twin:
        raise ValueError(f"twin_causes name unknown causes: {', '.join(unknown_twin)}")
    twice = sorted({i for i in ids if ids.count(i) > 1})
    if twice:
        raise ValueError(f"causes declared twice: {', '.join(twice)}")
    return tuple(sorted(found, key=lambda c: c.id))


def cause(cause_id: str) -> Cause:
    """One cause by its id.

    Parameters
    ----------
    cause_id : str

    Returns
    -------
    Cause

    Raises
    ------
    KeyError
        No cause has that id; the message names the closest ids.
    """
    for c in catalogue():
        if c.id == cause_id:
            return c
    close = difflib.get_close_matches(cause_id, [c.id for c in catalogue()], n=3, cutoff=0.5)
    raise KeyError(f"no cause {cause_id!r}" + (f"; did you mean {', '.join(close)}?" if close else ""))


def fixture_path(c: Cause) -> Path:
    """The cause's minimal model file, shipped with the package.

    In its engine's subpackage (``engines/<name>/fixtures/``) when there, else in
    ``koenig_check/causes/fixtures/``.

    Parameters
    ----------
    c : Cause

    Returns
    -------
    pathlib.Path
    """
    return _shipped(c, c.fixture)


def twin_path(c: Cause) -> Path | None:
    """The fixture's twin (the same robot written without the construct), found as :func:`fixture_path` finds it.

    Parameters
    ----------
    c : Cause

    Returns
    -------
    pathlib.Path or None
        None where the cause declares no twin.
    """
    return _shipped(c, c.twin) if c.twin else None


def _shipped(c: Cause, name: str) -> Path:
    """A file shipped for a cause: in its engine's ``fixtures/`` when there, else in the shared one."""
    own = Path(str(importlib.resources.files(f"{ENGINES_PACKAGE}.{c.engine}").joinpath("fixtures", name)))
    if own.is_file():
        return own
    return Path(str(importlib.resources.files("koenig_check.causes").joinpath("fixtures", name)))


@cache
def installed_version(engine: str) -> Version | None:
    """The installed version of an engine's distribution, or None where it is not installed.

    Parameters
    ----------
    engine : str

    Returns
    -------
    packaging.version.Version or None
    """
    try:
        return Version(importlib.metadata.version(spec(engine).distribution))
    except (importlib.metadata.PackageNotFoundError, InvalidVersion):
        return None


def applies(cause_id: str, engine: str | None = None) -> bool:
    """Whether a cause's declared reading holds for the installed version of an engine.

    A reading whose ``versions`` do not contain the installed version says nothing about it: detection must not
    fire there.

    Parameters
    ----------
    cause_id : str
    engine : str, optional
        The engine (default: the one the cause's id names).

    Returns
    -------
    bool
    """
    c = cause(cause_id)
    reading = c.reading(engine or c.engine)
    if not reading.versions:
        return True
    version = installed_version(reading.engine)
    return version is None or version in SpecifierSet(reading.versions)
