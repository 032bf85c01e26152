"""``rd:NAME``: a robot of the ``robot_descriptions`` package (extra ``[descriptions]``).

A description is a module (``ur5e_description``, ``go2_mj_description``; ``rd:ur5e`` is accepted for
``rd:ur5e_description``) whose import clones its repository into ``ROBOT_DESCRIPTIONS_CACHE`` (once) and exposes
``MJCF_PATH``, ``URDF_PATH`` or ``XACRO_PATH`` (expanded with its ``XACRO_ARGS`` and any ``--xacro-arg``).
"""

from __future__ import annotations

import difflib
import importlib
import importlib.util
import pkgutil
from collections.abc import Mapping
from pathlib import Path
from types import ModuleType

from koenig_check.exceptions import one_line
from koenig_check.sources.errors import ModelSourceError, missing_extra

PREFIX = "rd:"
CLONE_HINT = (
    "set ROBOT_DESCRIPTIONS_CACHE to a directory that holds its clone (robot_descriptions clones it there "
    "where GitHub is reachable)"
)
#: Module attributes naming a ready file, in order of preference.
FILE_ATTRIBUTES = ("MJCF_PATH", "URDF_PATH")


def _package(model: str) -> ModuleType:
    try:
        import robot_descriptions
    except ImportError:
        raise missing_extra(model, "descriptions", "robot_descriptions") from None
    return robot_descriptions


def known_names(package: ModuleType) -> list[str]:
    """The description modules of the installed package (no import of any of them: importing clones).

    Parameters
    ----------
    package : module
        ``robot_descriptions``.

    Returns
    -------
    list of str
    """
    listed = getattr(package, "DESCRIPTIONS", None)
    if isinstance(listed, Mapping):
        return sorted(listed)
    return sorted(m.name for m in pkgutil.iter_modules(package.__path__) if not m.name.startswith("_"))


def module_name(model: str) -> str:
    """The description module ``rd:NAME`` names (``NAME`` or ``NAME_description``).

    Parameters
    ----------
    model : str

    Returns
    -------
    str

    Raises
    ------
    ModelSourceError
        Missing extra, or no such description (with the closest names).
    """
    package = _package(model)
    name = model[len(PREFIX) :]
    known = known_names(package)
    for candidate in (name, f"{name}_description"):
        if candidate and (candidate in known or importlib.util.find_spec(f"robot_descriptions.{candidate}")):
            return candidate
    close = difflib.get_close_matches(name, known, n=3, cutoff=0.6)
    close += [k for k in known if name and k.startswith(name) and k not in close]
    hint = f"; did you mean {', '.join(PREFIX + c for c in close[:3])}?" if close else ""
    raise ModelSourceError(f"{model}: robot_descriptions has no description {name!r}{hint}")


def description_module(model: str) -> ModuleType:
    """Import the description module (its import clones the repository the first time).

    Parameters
    ----------
    model : str

    Returns
    -------
    module

    Raises
    ------
    ModelSourceError
        When the module cannot be imported: the clone cannot happen here.
    """
    name = module_name(model)
    try:
        return importlib.import_module(f"robot_descriptions.{name}")
    except Exception as err:  # a clone that cannot happen (no network, no git): one line, what to set
        reason = one_line(err)
        raise ModelSourceError(
            f"{model}: robot_descriptions cannot provide {name} here ({reason}); {CLONE_HINT}"
        ) from None


def description_file(model: str, xacro_args: Mapping[str, str] | None = None) -> tuple[Path, tuple[Path, ...]]:
    """The model file of ``rd:NAME`` and the directories its ``package://`` URIs are looked up in.

    Parameters
    ----------
    model : str
    xacro_args : mapping, optional
        Override the module's ``XACRO_ARGS`` when it exposes a xacro file.

    Returns
    -------
    (Path, tuple of Path)

    Raises
    ------
    ModelSourceError
        Missing extra, unknown name, a clone that cannot happen, or a module without a model file.
    """
    module = description_module(model)
    dirs = tuple(
        Path(str(getattr(module, a)))
        for a in ("PACKAGE_PATH", "REPOSITORY_PATH", "XACRO_PACKAGE_PATH")
        if getattr(module, a, None)
    )
    package_dirs = tuple(dict.fromkeys(d for p in dirs for d in (p, p.parent)))
    for attribute in FILE_ATTRIBUTES:
        if getattr(module, attribute, None):
            return Path(str(getattr(module, attribute))), package_dirs
    if getattr(module, "XACRO_PATH", None):
        from koenig_check.sources.xacro import expand_xacro

        args = {**dict(getattr(module, "XACRO_ARGS", None) or {}), **dict(xacro_args or {})}
        return expand_xacro(Path(str(module.XACRO_PATH)), args, dirs, label=model), package_dirs
    raise ModelSourceError(f"{model}: {module.__name__} exposes no MJCF_PATH, URDF_PATH or XACRO_PATH")
