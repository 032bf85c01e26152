"""What a cause is: a construct that one engine's parser (or a loading option) reads differently, declared as data.

A :class:`Cause` is declared once, in the subpackage of the engine that departs (``engines/<name>/causes.py``,
``CAUSES = (Cause(...), ...)``); :mod:`koenig_check.causes` gathers them into the catalogue.  A
:class:`~koenig_check.findings.Finding` that a cause explains carries the cause's :attr:`Cause.id`; everything a
user reads about it (the brief form, the hint, the catalogue page) is rendered from the declaration and the
finding's values, never parsed back from a sentence.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

#: How an engine reads the construct of a cause.
READS = ("as written", "differently", "refuses")

#: What a cause can change in the robot an engine builds from the file.
QUANTITIES = ("mass", "com", "inertia", "kinematics", "joints", "armature", "gravity")

#: The formats a cause can concern.
FORMATS = ("mjcf", "urdf")

#: ``<engine>.<format or "any">.<slug>``: lower case, the slug's words joined by hyphens.
_ID = re.compile(r"^[a-z0-9]+\.(mjcf|urdf|any)\.[a-z0-9]+(-[a-z0-9]+)*$")


@dataclass(frozen=True)
class Reading:
    """How one engine reads a cause's construct.

    Parameters
    ----------
    engine : str
        The engine's name (``"pinocchio"``).
    reads : str
        One of :data:`READS`: ``"as written"`` (as the file says), ``"differently"`` or ``"refuses"``.
    how : str
        What it does, for people (``"density × volume of the geom"``); empty for ``"as written"``.
    versions : str
        A PEP 440 specifier of the engine versions this reading holds for (``">=4.0"``); empty: every version.
    measured : str
        The versions it was measured on (``"4.1.0"``).
    """

    engine: str
    reads: str
    how: str = ""
    versions: str = ""
    measured: str = ""

    def __post_init__(self) -> None:
        if self.reads not in READS:
            raise ValueError(f"Reading.reads must be one of {READS}, got {self.reads!r} ({self.engine})")
        if self.reads != "as written" and not self.how:
            raise ValueError(f"Reading of {self.engine}: say how it reads the construct ({self.reads})")


@dataclass(frozen=True)
class Cause:
    """A construct that one engine's parser reads differently from the file and the other engines.

    Parameters
    ----------
    id : str
        Stable and short, ``<engine that departs>.<format>.<slug>`` (``"pinocchio.mjcf.class-geom-mass"``):
        what findings, records and the plugin carry.
    construct : str
        What in the file (``"<default> geom mass"``).
    formats : tuple of str
        The formats it concerns (:data:`FORMATS`).
    readings : tuple of Reading
        How each engine measured reads it; the engine that departs reads it ``"differently"`` or ``"refuses"``.
    quantities : tuple of str
        What it changes (:data:`QUANTITIES`).
    brief : str
        A few words for the short form of a reason (``"geom mass from a default class not applied"``).
    hint : str
        What to change in the file, or which option to pass.
    fixture : str
        File name of a minimal model in ``koenig_check/causes/fixtures/`` that shows it.
    loses_joints : bool
        The engine that departs lacks joints of the file (its findings list them under ``"joints"``).
    twin : str
        File name of the fixture's twin in ``koenig_check/causes/fixtures/`` (empty: none): the same robot written
        by hand without the construct (the masses scaled, the frame folded in, the copies written out), its values
        computed by hand in a comment.  The suite checks the engines that read the fixture as written against
        every engine's reading of the twin, and those that read it differently depart from it: the one engine that
        reads a construct as written is checked even where no other engine does.
    twin_causes : tuple of str
        Ids of the causes the twin itself is subject to (a zero gravity vector written in ``<option>``, which
        Pinocchio does not read): the engines that depart on them are not compared on the twin.
    """

    id: str
    construct: str
    formats: tuple[str, ...]
    readings: tuple[Reading, ...]
    quantities: tuple[str, ...]
    brief: str
    hint: str
    fixture: str
    loses_joints: bool = False
    twin: str = ""
    twin_causes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not _ID.match(self.id):
            raise ValueError(f"cause id {self.id!r}: expected <engine>.<mjcf|urdf|any>.<slug-words>")
        for name, values, allowed in (("formats", self.formats, FORMATS), ("quantities", self.quantities, QUANTITIES)):
            unknown = sorted(set(values) - set(allowed))
            if unknown or not values:
                raise ValueError(f"cause {self.id}: {name} {unknown or '()'} not among {allowed}")
        engines = [r.engine for r in self.readings]
        if len(set(engines)) != len(engines):
            raise ValueError(f"cause {self.id}: one engine read twice ({engines})")
        if self.engine not in engines or self.reading(self.engine).reads == "as written":
            raise ValueError(
                f"cause {self.id}: the engine of its id ({self.engine}) must read it differently or refuse"
            )
        if not self.brief or not self.fixture or not self.construct:
            raise ValueError(f"cause {self.id}: needs a construct, a brief form and a fixture")
        if self.twin_causes and not self.twin:
            raise ValueError(f"cause {self.id}: twin_causes {self.twin_causes} without a twin")

    @property
    def engine(self) -> str:
        """The engine whose reading departs (the first part of the id)."""
        return self.id.split(".", 1)[0]

    def reading(self, engine: str) -> Reading:
        """How one engine reads the construct.

        Parameters
        ----------
        engine : str

        Returns
        -------
        Reading

        Raises
        ------
        KeyError
            The engine's reading of this cause was not measured.
        """
        for r in self.readings:
            if r.engine == engine:
                return r
        measured = ", ".join(r.engine for r in self.readings)
        raise KeyError(f"cause {self.id}: {engine}'s reading not declared (declared: {measured})")

    def as_dict(self) -> dict[str, object]:
        """A JSON-ready dictionary of the declaration (``koenig-check causes --json``).

        Returns
        -------
        dict
        """
        return {
            "id": self.id,
            "construct": self.construct,
            "formats": list(self.formats),
            "engines": {
                r.engine: {"reads": r.reads, "how": r.how, "versions": r.versions, "measured": r.measured}
                for r in self.readings
            },
            "quantities": list(self.quantities),
            "summary": self.brief,
            "hint": self.hint,
            "fixture": self.fixture,
            "loses_joints": self.loses_joints,
            "twin": self.twin,
            "twin_causes": list(self.twin_causes),
        }
