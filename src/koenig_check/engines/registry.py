"""The engines koenig-check can run: their names, how people call them, which are optional, how each is attached.

Each engine's facts are declared once, in its own subpackage (``SPEC = EngineSpec(...)`` in
``engines/<name>/__init__.py``, :mod:`koenig_check.engines.specs`); this module answers from those
declarations.  MuJoCo and Pinocchio load every model (:func:`koenig_check.engines.load_model`); an optional
engine is attached to a loaded model by the function its spec names (:func:`attach`).  A new engine is one
subpackage under ``engines/``: nothing here changes.

The tables :data:`LABEL` and :data:`ATTACH` are derived from the specs each time they are read.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from koenig_check.engines.errors import EngineUnavailableError
from koenig_check.engines.specs import ALL, EngineSpec, names, parity_pair, reference, spec, specs
from koenig_check.findings import Finding, Kind

if TYPE_CHECKING:
    from koenig_check.engines.base import Engine


__all__ = [
    "ATTACH",
    "ENGINE_TEXT",
    "LABEL",
    "EngineSpec",
    "attach",
    "check_engines",
    "engines_for",
    "install_hint",
    "installed",
    "label",
    "load_function",
    "mjcf_mesh_formats",
    "names",
    "not_used",
    "optional",
    "parity_pair",
    "reading",
    "reference",
    "required",
    "spec",
    "specs",
]


def required() -> tuple[str, ...]:
    """The engines every model is loaded in, in report order.

    Returns
    -------
    tuple of str
    """
    return tuple(s.name for s in specs() if s.required)


def optional() -> tuple[str, ...]:
    """The engines attached to a loaded model when used, in report order.

    Returns
    -------
    tuple of str
    """
    return tuple(s.name for s in specs() if not s.required)


def label(name: str) -> str:
    """How an engine is named for people (``"MuJoCo"``); an unknown name is returned as it is.

    Parameters
    ----------
    name : str

    Returns
    -------
    str
    """
    try:
        return spec(name).label
    except KeyError:
        return name


class _Table(Mapping[str, str]):
    """A table of earlier versions (engine -> one fact), read from the specs at each look-up."""

    def __init__(self, fact: Callable[[EngineSpec], str]) -> None:
        self._fact = fact

    def _items(self) -> dict[str, str]:
        return {s.name: self._fact(s) for s in specs() if self._fact(s)}

    def __getitem__(self, name: str) -> str:
        return self._items()[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._items())

    def __len__(self) -> int:
        return len(self._items())

    def __repr__(self) -> str:
        return repr(self._items())


#: How engines are named for people (engine -> label).
LABEL: Mapping[str, str] = _Table(lambda s: s.label)
#: Optional engine -> "module:function" that attaches it to a loaded model (see :func:`attach`).
ATTACH: Mapping[str, str] = _Table(lambda s: s.attach)
#: The Python module each engine needs, and how to install an optional one.
_MODULE: Mapping[str, str] = _Table(lambda s: s.module)
_INSTALL: Mapping[str, str] = _Table(lambda s: s.install_hint)


def load_function(path: str) -> Callable[..., Any]:
    """The function a spec names as ``"module:function"``.

    Parameters
    ----------
    path : str

    Returns
    -------
    callable
    """
    module, function = path.split(":")
    found = getattr(importlib.import_module(module), function)
    return found


def installed(name: str) -> bool:
    """Whether an engine's Python module is installed, without importing it (pydrake takes 0.25 s to import).

    Parameters
    ----------
    name : str

    Returns
    -------
    bool
    """
    try:
        return importlib.util.find_spec(spec(name).module) is not None
    except (ImportError, ValueError, KeyError):
        return False


def install_hint(name: str) -> str:
    """How to install an optional engine (``pip install 'koenig-check[drake]'``).

    Parameters
    ----------
    name : str

    Returns
    -------
    str
    """
    return spec(name).install_hint


def check_engines(engines: Sequence[str] | None) -> None:
    """Refuse, before any work, an engine list that names an engine that is not installed.

    Parameters
    ----------
    engines : sequence of str or None

    Raises
    ------
    EngineUnavailableError
    """
    for name in engines or ():
        if name != ALL and name not in required() and not installed(name):
            module = spec(name).module
            raise EngineUnavailableError(
                f"engines: {name} asked for but {module} is not installed ({install_hint(name)})", engine=name
            )


def reading(fmt: str, *, installed_only: bool = False) -> tuple[str, ...]:
    """The engines whose parser reads files of a format (their spec's ``formats``), in report order.

    The one answer to "which engines read this file": ``--engines all`` (:func:`engines_for`) and the export's
    proof (:func:`koenig_check.export.proof.prove`) both ask it.

    Parameters
    ----------
    fmt : str
        ``"mjcf"`` or ``"urdf"`` (:attr:`koenig_check.engines.ModelSource.format`).
    installed_only : bool
        Only the installed ones (the required engines always are).

    Returns
    -------
    tuple of str
    """
    return tuple(
        s.name for s in specs() if fmt in s.formats and (not installed_only or s.required or installed(s.name))
    )


def engines_for(engines: Sequence[str] | None, fmt: str) -> tuple[tuple[str, ...] | None, list[Finding]]:
    """The engines a model of a format runs in: ``engines`` as named, or for ``("all",)`` those that read it.

    Parameters
    ----------
    engines : sequence of str or None
        As :attr:`koenig_check.engines.LoadOptions.engines`; ``("all",)`` (``--engines all``) asks for every
        installed engine whose parser reads ``fmt``.
    fmt : str
        The model's format.

    Returns
    -------
    engines : tuple of str or None
        ``engines`` unchanged, or for ``("all",)`` the installed engines that read ``fmt``, in report order: each
        is then asked for as if named (one that cannot check the model fails it with its own reason).
    left_out : list of Finding
        For ``("all",)``, per installed engine that does not read ``fmt``, the ``ENGINE_NOT_USED`` finding saying
        so (values: ``format``, the file's, and ``reads``, the engine's); otherwise empty.
    """
    if engines is None or tuple(engines) != (ALL,):
        return (None if engines is None else tuple(engines)), []
    chosen = reading(fmt, installed_only=True)
    left_out = [
        not_used(
            n, "--engines all: its parser does not read the file's format", format=fmt, reads="/".join(spec(n).formats)
        )
        for n in optional()
        if n not in chosen and installed(n)
    ]
    return chosen, left_out


def mjcf_mesh_formats(engines: Sequence[str]) -> dict[str, tuple[str, ...]]:
    """The mesh formats the MJCF parsers of some engines read, for those that read only some.

    Parameters
    ----------
    engines : sequence of str
        The engines that will read a file (unknown names are ignored).

    Returns
    -------
    dict of str to tuple of str
        Engine -> the mesh suffixes its MJCF parser reads (:attr:`EngineSpec.mjcf_meshes`); an engine that
        reads every mesh MuJoCo reads is left out.
    """
    known = set(names())
    return {e: spec(e).mjcf_meshes for e in engines if e in known and spec(e).mjcf_meshes}


#: The key of a refusal's value holding the engine's own text, whole, as it raised it (the summary says the refusal
#: in a few words; the lines under a verdict give this text indented).
ENGINE_TEXT = "engine's text"


def not_used(name: str, why: str, **values: Any) -> Finding:
    """The finding that an optional engine was not run on a model, and why.

    Parameters
    ----------
    name : str
    why : str
    **values
        Values the finding carries (``asked=True`` when the user named the engine).

    Returns
    -------
    Finding
    """
    return Finding(Kind.ENGINE_NOT_USED, name, "model", f"{label(name)} not used: {why}", values)


def attach(name: str, model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load an optional engine on a model already loaded in MuJoCo and Pinocchio.

    Parameters
    ----------
    name : str
        An optional engine (its spec's :attr:`~koenig_check.engines.specs.EngineSpec.attach`).
    model : koenig_check.engines.LoadedModel

    Returns
    -------
    engine : Engine or None
        None when the engine cannot check this model.
    findings : list of Finding
        The engine's load findings and the constructs its parser is known to read differently, or one
        ``ENGINE_NOT_USED`` finding with the engine's own whole reason.
    """
    if not installed(name):
        return None, [not_used(name, f"not installed ({install_hint(name)})")]
    attach_engine: Callable[[Any], tuple[Engine | None, list[Finding]]] = load_function(spec(name).attach)
    return attach_engine(model)
