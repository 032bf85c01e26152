"""How a model is loaded: one definition shared by the API, every command and the testing helper.

:class:`LoadOptions` is what :func:`koenig_check.engines.load_model` takes; :func:`add_load_arguments`
puts the same options on any sub-command that loads a model and :meth:`LoadOptions.from_namespace`
reads them back, so that a flag a message points to exists wherever a model is loaded.
"""

from __future__ import annotations

import argparse
import os
import warnings
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, fields, replace
from typing import Any

from koenig_check.engines import specs as engine_specs

#: What the deprecated ``allow_coupled`` / ``--allow-coupled`` is told.
ALLOW_COUPLED_DEPRECATION = (
    "allow_coupled (--allow-coupled) is deprecated and does nothing: coupled joints are loaded by default and "
    "recorded as findings"
)


@dataclass(frozen=True)
class LoadOptions:
    """Options that decide how a file becomes a model in both engines.

    Parameters
    ----------
    floating : bool
        Give a fixed-base model a free root joint.
    balance_inertia : bool
        Let MuJoCo load inertias that violate ``A + B >= C`` (``balanceinertia``); recorded per link.
    repair_inertia : bool
        Load masses and inertias MuJoCo refuses (a zero or negative principal moment, a massless
        moving link, ``A + B < C``) with the smallest change MuJoCo accepts, recorded per link;
        Pinocchio keeps the file's values, so the comparison shows the repair's effect.
    pinocchio_model : str or path, optional
        Load Pinocchio from this other file of the same mechanism (e.g. the URDF twin of an MJCF).
    allow_coupled : bool
        Deprecated no-op kept for a while: coupled joints are loaded by default and recorded as findings.
    engines : tuple of str or "all", optional
        The engines to run on every model: ``("mujoco", "pinocchio")`` or ``("mujoco", "pinocchio",
        "drake")``; ``"all"`` (stored as ``("all",)``): per model, every installed engine whose parser reads its
        format, each asked for as if named.  ``None`` (default): MuJoCo and Pinocchio, and Drake as
        tie-breaker on a model where they disagree, when Drake is installed (:mod:`koenig_check.diagnosis.policy`).
    xacro_args : mapping or pairs, optional
        ``$(arg NAME)`` values for a ``.xacro`` model (``{"length": "0.7"}``, ``["length=0.7"]``); the file's
        defaults apply to the others.  Stored as sorted ``(name, value)`` pairs.
    """

    floating: bool = False
    balance_inertia: bool = False
    repair_inertia: bool = False
    pinocchio_model: str | os.PathLike[str] | None = None
    allow_coupled: bool = False
    engines: tuple[str, ...] | None = None
    xacro_args: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "xacro_args", parse_xacro_args(self.xacro_args))
        if self.engines is not None:
            names = (self.engines,) if isinstance(self.engines, str) else tuple(self.engines)
            object.__setattr__(self, "engines", parse_engines(",".join(names)))
        for f in fields(self):
            value = getattr(self, f.name)
            if f.type == "bool" and not isinstance(value, bool):
                raise TypeError(f"LoadOptions.{f.name} must be a bool, got {value!r}")

    @classmethod
    def names(cls) -> tuple[str, ...]:
        """The option names, as keyword arguments.

        Returns
        -------
        tuple of str
        """
        return tuple(f.name for f in fields(cls))

    @classmethod
    def pop_from(cls, options: dict[str, Any]) -> LoadOptions:
        """Take the load options out of a keyword dictionary (the rest stays in it).

        Parameters
        ----------
        options : dict
            Keyword arguments; the load options are removed from it.

        Returns
        -------
        LoadOptions
        """
        return cls(**{name: options.pop(name) for name in cls.names() if name in options})

    def as_overrides(self) -> dict[str, Any]:
        """The options that differ from their defaults, as keyword arguments.

        Returns
        -------
        dict
        """
        default = LoadOptions()
        return {name: getattr(self, name) for name in self.names() if getattr(self, name) != getattr(default, name)}

    @classmethod
    def from_namespace(cls, args: argparse.Namespace) -> LoadOptions:
        """Read the options that :func:`add_load_arguments` put on a parser.

        Parameters
        ----------
        args : argparse.Namespace

        Returns
        -------
        LoadOptions
        """
        return cls(**{name: getattr(args, name) for name in cls.names() if hasattr(args, name)})


def parse_engines(text: str) -> tuple[str, ...]:
    """Read an engine list such as ``"mujoco,pinocchio,drake"``.

    Parameters
    ----------
    text : str
        Comma-separated engine names; MuJoCo and Pinocchio are always run.  ``"all"``, alone: every installed
        engine whose parser reads each model's format (resolved per model by
        :func:`koenig_check.engines.registry.engines_for`).

    Returns
    -------
    tuple of str
        In report order (:func:`koenig_check.engines.specs.names`), or ``("all",)``.

    Raises
    ------
    ValueError
        On an unknown name, a list without MuJoCo and Pinocchio, or ``all`` in a list.
    """
    asked = [n.strip().lower() for n in text.split(",") if n.strip()]
    if engine_specs.ALL in asked:
        if asked != [engine_specs.ALL]:
            raise ValueError(
                f"engines: {engine_specs.ALL!r} stands alone (every installed engine that reads the "
                f"file's format), not in a list: {text!r}"
            )
        return (engine_specs.ALL,)
    known = engine_specs.names()
    unknown = [n for n in asked if n not in known]
    if unknown:
        raise ValueError(f"engines: unknown {unknown}; choose among {list(known)}, or {engine_specs.ALL!r} alone")
    required = [s.name for s in engine_specs.specs() if s.required]
    if not set(required) <= set(asked):
        whole = ",".join(n for n in known if n in {*asked, *required})
        raise ValueError(f"engines: {' and '.join(required)} are always run and named: write {whole!r}, not {text!r}")
    return tuple(n for n in known if n in asked)


def parse_xacro_args(value: Mapping[str, Any] | Iterable[Any] | None) -> tuple[tuple[str, str], ...]:
    """Read xacro arguments: a mapping, ``"NAME=VALUE"`` strings or ``(name, value)`` pairs.

    Parameters
    ----------
    value : mapping, iterable or None

    Returns
    -------
    tuple of (str, str)
        Sorted by name; numbers written as text, booleans as ``true``/``false`` (xacro's spelling).

    Raises
    ------
    TypeError
        On a value that is none of these.
    ValueError
        On a string without ``=`` or an empty name.
    """
    if value is None:
        return ()
    if isinstance(value, str):
        value = [value]
    items = value.items() if isinstance(value, Mapping) else value
    pairs: dict[str, str] = {}
    for item in items:
        if isinstance(item, str):
            name, sep, text = item.partition("=")
            if not sep:
                raise ValueError(f"xacro_args: expected NAME=VALUE, got {item!r}")
        elif isinstance(item, tuple | list) and len(item) == 2:
            name, raw = item
            text = ("true" if raw else "false") if isinstance(raw, bool) else str(raw)
        else:
            raise TypeError(f"xacro_args: expected NAME=VALUE strings, (name, value) pairs or a mapping, got {item!r}")
        name = str(name).strip()
        if not name:
            raise ValueError(f"xacro_args: empty argument name in {item!r}")
        pairs[name] = text
    return tuple(sorted(pairs.items()))


def _xacro_argument(text: str) -> tuple[str, str]:
    try:
        return parse_xacro_args([text])[0]
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err).replace("xacro_args: ", "")) from None


def _engines_argument(text: str) -> tuple[str, ...]:
    try:
        return parse_engines(text)
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


def add_load_arguments(parser: argparse.ArgumentParser) -> None:
    """Add every load option to a sub-command's parser.

    Parameters
    ----------
    parser : argparse.ArgumentParser
    """
    group = parser.add_argument_group("how the model is loaded")
    group.add_argument("--floating", action="store_true", help="give a fixed-base model a free-floating base")
    group.add_argument(
        "--balance-inertia", action="store_true", help="let MuJoCo balance inertias with A + B < C (recorded per link)"
    )
    group.add_argument(
        "--repair-inertia",
        action="store_true",
        help="load masses and inertias MuJoCo refuses with the smallest change it accepts (recorded per link; "
        "Pinocchio keeps the file's values)",
    )
    group.add_argument(
        "--pinocchio-model", help="load Pinocchio from this file instead (e.g. the URDF twin of an MJCF)"
    )
    group.add_argument("--allow-coupled", action="store_true", help=argparse.SUPPRESS)
    group.add_argument(
        "--engines",
        type=_engines_argument,
        default=None,
        metavar="LIST",
        help="engines to run on every model, e.g. mujoco,pinocchio,drake, or all: every installed engine that "
        "reads each model's format (default: Drake only as tie-breaker where MuJoCo and Pinocchio disagree, when "
        "installed)",
    )
    group.add_argument(
        "--xacro-arg",
        dest="xacro_args",
        action="append",
        type=_xacro_argument,
        default=None,
        metavar="NAME=VALUE",
        help="set $(arg NAME) of a .xacro model (repeat for several; the file's defaults apply to the others)",
    )


def load_options_from(base: LoadOptions | None, overrides: dict[str, Any]) -> LoadOptions:
    """The load options: ``base`` (defaults when None) with keyword overrides.

    ``allow_coupled=True`` warns (:class:`DeprecationWarning`) and is dropped: it does nothing.

    Parameters
    ----------
    base : LoadOptions, optional
    overrides : dict
        Load options by name.

    Returns
    -------
    LoadOptions

    Raises
    ------
    TypeError
        On a keyword that is not a load option.
    """
    unknown = sorted(set(overrides) - set(LoadOptions.names()))
    if unknown:
        raise TypeError(f"unknown option(s) {unknown}; load options are {list(LoadOptions.names())}")
    options = replace(base or LoadOptions(), **overrides)
    if options.allow_coupled:
        warnings.warn(ALLOW_COUPLED_DEPRECATION, DeprecationWarning, stacklevel=3)
        options = replace(options, allow_coupled=False)
    return options
