"""The engines koenig-check can run: their names, how people call them, which are optional, how each is attached.

MuJoCo and Pinocchio load every model (:func:`koenig_check.engines.load_model`); an optional engine is
attached to a loaded model by the function :data:`ATTACH` names for it.  A new engine is one subpackage
under ``engines/`` and one line in each table here.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from koenig_check.engines.errors import EngineUnavailableError
from koenig_check.findings import Finding, Kind

if TYPE_CHECKING:
    from koenig_check.engines.base import Engine

#: Every engine, in report order.
ENGINE_NAMES = ("mujoco", "pinocchio", "drake")
#: The engines every model is loaded in.
REQUIRED = ("mujoco", "pinocchio")
#: How engines are named for people.
LABEL = {"mujoco": "MuJoCo", "pinocchio": "Pinocchio", "drake": "Drake"}
#: The Python module each engine needs, and how to install an optional one.
_MODULE = {"mujoco": "mujoco", "pinocchio": "pinocchio", "drake": "pydrake"}
_INSTALL = {"drake": "pip install 'koenig-check[drake]'"}
#: Optional engine -> "module:function" that attaches it to a loaded model (see :func:`attach`).
ATTACH = {"drake": "koenig_check.engines.drake.attach:attach"}


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
        return importlib.util.find_spec(_MODULE[name]) is not None
    except (ImportError, ValueError):
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
    return _INSTALL.get(name, "")


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
        if name not in REQUIRED and not installed(name):
            raise EngineUnavailableError(
                f"engines: {name} asked for but {_MODULE[name]} is not installed ({install_hint(name)})", engine=name
            )


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
    return Finding(Kind.ENGINE_NOT_USED, name, "model", f"{LABEL[name]} not used: {why}", values)


def attach(name: str, model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load an optional engine on a model already loaded in MuJoCo and Pinocchio.

    Parameters
    ----------
    name : str
        An optional engine (a key of :data:`ATTACH`).
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
    module, function = ATTACH[name].split(":")
    attach_engine: Callable[[Any], tuple[Engine | None, list[Finding]]] = getattr(
        importlib.import_module(module), function
    )
    return attach_engine(model)
