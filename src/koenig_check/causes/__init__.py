"""The catalogue of causes: constructs one engine reads differently from the file (stand-in until issue 26's core).

Each engine subpackage declares its causes in ``engines/<name>/causes.py`` as ``CAUSES = (Cause(...), ...)``;
:func:`catalogue` collects them, :func:`cause` finds one by id.  Fixtures are in ``causes/fixtures/``.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from pathlib import Path

from koenig_check.engines import specs

#: Where the fixtures are.
FIXTURES = Path(__file__).parent / "fixtures"


@dataclass(frozen=True)
class Reading:
    """How one engine reads a construct.

    Parameters
    ----------
    engine : str
    reads : {"as written", "differently", "refuses"}
    how : str
    versions : str
        PEP 440 specifier of the engine versions the reading applies to ("" = all).
    measured : str
        The versions it was measured on.
    """

    engine: str
    reads: str
    how: str
    versions: str = ""
    measured: str = ""


@dataclass(frozen=True)
class Cause:
    """A construct one engine's parser reads differently from the file and from the other engines.

    Parameters
    ----------
    id : str
        ``<engine that departs>.<format>.<slug>``.
    construct : str
    formats : tuple of str
    readings : tuple of Reading
    quantities : tuple of str
        Subset of mass, com, inertia, kinematics, joints, armature, gravity.
    brief : str
    hint : str
    fixture : str
        File name of a minimal model in :data:`FIXTURES`.
    loses_joints : bool
    """

    id: str
    construct: str
    formats: tuple[str, ...]
    readings: tuple[Reading, ...]
    quantities: tuple[str, ...]
    brief: str
    hint: str = ""
    fixture: str = ""
    loses_joints: bool = False


def catalogue() -> tuple[Cause, ...]:
    """Every engine subpackage's causes.

    Returns
    -------
    tuple of Cause
    """
    out: list[Cause] = []
    for name in specs.names():
        try:
            module = importlib.import_module(f"koenig_check.engines.{name}.causes")
        except ModuleNotFoundError:
            continue
        out += getattr(module, "CAUSES", ())
    return tuple(out)


def cause(id: str) -> Cause:
    """The cause with this id.

    Parameters
    ----------
    id : str

    Returns
    -------
    Cause

    Raises
    ------
    KeyError
        No cause has that id.
    """
    for c in catalogue():
        if c.id == id:
            return c
    raise KeyError(id)
