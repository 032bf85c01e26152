"""What each engine is (:class:`EngineSpec`), declared in its own subpackage, and the list of engines found there.

Every subpackage of ``koenig_check.engines`` declares ``SPEC = EngineSpec(...)`` in its ``__init__.py``; that
declaration is the only place an engine's facts are written (its name, how people call it, the Python module it
needs, whether every model is loaded in it, how it is attached, how a file is loaded in it alone, its colour).
:func:`specs` finds the subpackages, so a new engine is one subpackage here (and its line in the package list of
``pyproject.toml``, so that a non-editable install ships it); the registry, the policy, the three-way verdicts,
the reports and the export all iterate over :func:`specs`.

This module imports nothing of koenig_check at import time, so that any module (:mod:`koenig_check.findings`
too) can ask which engines there are.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass

#: The package whose subpackages are the engines.
ENGINES_PACKAGE = "koenig_check.engines"
#: The word that asks for every installed engine whose parser reads a model's format (``--engines all``).
ALL = "all"


@dataclass(frozen=True)
class EngineSpec:
    """One engine's facts, declared once, in its subpackage's ``__init__.py``.

    Parameters
    ----------
    name : str
        The name users type (``--engines mujoco,pinocchio,drake``) and findings carry.
    label : str
        How the engine is named for people (``"Drake"``).
    module : str
        The Python module the engine needs (checked without importing it: ``"pydrake"``).
    required : bool
        Every model is loaded in it (MuJoCo, Pinocchio: the pair whose import parity is checked).  An optional
        engine is attached to a loaded model by :attr:`attach`, on every pose when the user names it, or as a
        tie-breaker where the required engines disagree (:mod:`koenig_check.diagnosis.policy`).
    extra : str
        The optional dependency of koenig-check that installs it (``"drake"``: ``pip install
        'koenig-check[drake]'``), or empty.
    attach : str
        ``"module:function"`` that attaches an optional engine to a loaded model:
        ``function(model) -> (Engine or None, list of Finding)`` (see :func:`koenig_check.engines.registry.attach`).
    load_alone : str
        ``"module:function"`` that loads a file in this engine alone, paired with MuJoCo's model of it (the
        export's proof): ``function(source, mj_model) -> Engine``; empty for MuJoCo, which defines the layout.
    color : str
        Its colour in every figure (a Matplotlib colour).
    distribution : str
        The distribution that installs it (``"pin"`` for Pinocchio), whose version the catalogue's readings are
        checked against; empty: :attr:`module`.
    formats : tuple of str
        The file formats its parser reads (``("urdf",)``); an engine asked for a file of another format refuses it.
    precision : float
        The relative round-off of what it reads and computes (float32 engines about 1e-5): a difference below it
        is never called a difference.
    tie_breaker : bool
        An optional engine consulted, when installed, on a model where the required engines disagree (the
        default policy, :mod:`koenig_check.diagnosis.policy`); otherwise it runs only when the user names it.
    reference : bool
        Its reading of a file is the reference the others are placed against (MuJoCo: it defines the canonical
        layout); one engine declares it.
    mjcf_meshes : tuple of str
        The mesh file suffixes its MJCF parser reads (``(".obj",)``); empty: every format MuJoCo reads.  The
        export writes only these for a proof that includes the engine.
    """

    name: str
    label: str
    module: str
    required: bool = False
    extra: str = ""
    attach: str = ""
    load_alone: str = ""
    color: str = "tab:gray"
    distribution: str = ""
    formats: tuple[str, ...] = ("mjcf", "urdf")
    precision: float = 1e-12
    tie_breaker: bool = False
    reference: bool = False
    mjcf_meshes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not self.distribution:
            object.__setattr__(self, "distribution", self.module)

    @property
    def install_hint(self) -> str:
        """How to install it (``pip install 'koenig-check[drake]'``), or empty for a required engine."""
        if self.required:
            return ""
        return f"pip install 'koenig-check[{self.extra}]'" if self.extra else f"pip install {self.module}"


#: (search path of the engines package, its specs): the specs are found once per search path.
_found: tuple[tuple[str, ...], tuple[EngineSpec, ...]] | None = None


def specs() -> tuple[EngineSpec, ...]:
    """Every engine, in report order: the required engines, then the optional ones, each by name.

    Returns
    -------
    tuple of EngineSpec

    Raises
    ------
    TypeError
        A subpackage of ``koenig_check.engines`` declares no ``SPEC`` (or not an :class:`EngineSpec`).
    ValueError
        Two subpackages declare the same engine name.
    """
    global _found
    package = importlib.import_module(ENGINES_PACKAGE)
    path = tuple(package.__path__)
    if _found is not None and _found[0] == path:
        return _found[1]
    found = []
    for info in pkgutil.iter_modules(list(path)):
        if not info.ispkg:
            continue
        sub = importlib.import_module(f"{ENGINES_PACKAGE}.{info.name}")
        spec = getattr(sub, "SPEC", None)
        if not isinstance(spec, EngineSpec):
            raise TypeError(f"{sub.__name__}: an engine subpackage declares SPEC = EngineSpec(...) in __init__.py")
        found.append(spec)
    names = [s.name for s in found]
    if len(set(names)) != len(names):
        raise ValueError(f"engines: one name declared twice in {ENGINES_PACKAGE}: {sorted(names)}")
    ordered = tuple(sorted(found, key=lambda s: (not s.required, s.name)))
    _found = (path, ordered)
    return ordered


def names() -> tuple[str, ...]:
    """Every engine's name, in report order.

    Returns
    -------
    tuple of str
    """
    return tuple(s.name for s in specs())


def reference() -> str:
    """The engine whose reading of a file is the reference (the one whose spec says ``reference=True``).

    Returns
    -------
    str

    Raises
    ------
    ValueError
        Not exactly one engine declares itself the reference.
    """
    found = [s.name for s in specs() if s.reference]
    if len(found) != 1:
        raise ValueError(f"engines: exactly one spec declares reference=True, found {found}")
    return found[0]


def parity_pair() -> tuple[str, str]:
    """The two required engines whose import parity is checked: the reference first, then the other one.

    Returns
    -------
    tuple of str
        ``(reference, other)`` (MuJoCo, Pinocchio).

    Raises
    ------
    ValueError
        The required engines are not the reference and one other.
    """
    first = reference()
    others = [s.name for s in specs() if s.required and s.name != first]
    if len(others) != 1 or not spec(first).required:
        raise ValueError(f"engines: the import-parity pair is the required reference and one other, found {others}")
    return first, others[0]


def spec(name: str) -> EngineSpec:
    """One engine's spec.

    Parameters
    ----------
    name : str

    Returns
    -------
    EngineSpec

    Raises
    ------
    KeyError
        No engine has that name.
    """
    for s in specs():
        if s.name == name:
            return s
    raise KeyError(f"no engine named {name!r}; engines: {', '.join(names())}")
