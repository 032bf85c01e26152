"""Findings: everything the tool learns about a model, as one typed record.

A finding is data — what kind of thing was found, by or about which engine, on which element of the
model, the values on each side, and whether it changes the kinetic energy — never a sentence that
is filtered later by substring.  The one-line reason, the parity report, the summary, the API and
:func:`koenig_check.testing.assert_energy_parity` all read these records; :meth:`Finding.message`
renders one for people.

A *root cause* (Pinocchio ignored an ``<include>``, dropped a root body's pose, used density × volume
instead of a geom's mass) is one finding that explains many per-segment symptoms; the report leads
with root causes (:attr:`Finding.root_cause`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from enum import Enum
from types import MappingProxyType
from typing import Any

from koenig_check.engines import specs
from koenig_check.exceptions import KoenigCheckError as KoenigCheckError  # its old import path
from koenig_check.roundoff import fmt, side_by_side

#: What a finding can concern besides one engine.  ``both`` is a finding about the pair (a joint mapping, a
#: coupling both engines ignore); ``all`` is a three-engine verdict where every engine differs; ``file`` is a
#: construct of the file itself.
NOT_ONE_ENGINE = ("both", "all", "file")


def concerned() -> tuple[str, ...]:
    """What a finding can concern: every engine (:func:`~koenig_check.engines.specs.names`), both, all, file.

    Returns
    -------
    tuple of str
    """
    return (*specs.names(), *NOT_ONE_ENGINE)


class Kind(str, Enum):
    """What a finding is about.

    The value is the stable identifier used in JSON output and tests.
    """

    # What was done to load the model (the user asked for it, or a documented engine limitation).
    ENGINE_NOT_USED = "engine_not_used"  # an optional engine was not run on the model, and why
    ENGINE_UNABLE = "engine_unable"  # an engine the user asked for could not check the model: the check was not made
    LOAD = "load"  # a loading decision: inertia-only meshes, keyframes skipped, a file loaded for one engine
    REPAIR = "repair"  # a mass property changed so that an engine accepts the model (--repair-inertia)
    COUPLING = "coupling"  # joints coupled by the file (mimic, equality, tendon, weld/connect)
    # Import differences: the engines were given, or built, different mechanisms from one file.
    MASS = "mass"
    COM = "com"
    INERTIA = "inertia"
    AXIS = "axis"
    ANCHOR = "anchor"
    ARMATURE = "armature"
    SEGMENTS = "segments"  # a segment one engine has and the other lacks, or gives no mass
    FRAME = "frame"  # a constant world transform between the engines (a dropped root pose)
    COMPILER = "compiler"  # a compiler option that one engine honours and the other ignores
    IGNORED_CONSTRUCT = "ignored_construct"  # a file construct one engine's parser ignores
    # An engine disagreeing with itself (energy against ½ q̇ᵀ M q̇, RNEA against M q̈).
    SELF_CONSISTENCY = "self_consistency"
    # Three engines compared: which one departs (koenig_check.diagnosis.three_way).
    VERDICT = "verdict"
    # Nothing to compare.
    NOTHING_MOVES = "nothing_moves"


@dataclass(frozen=True)
class Finding:
    """One thing learned about a model.

    Parameters
    ----------
    kind : Kind
        What it is about.
    engine : str
        One of :func:`concerned`: the engine concerned (the one that departs, ignores or was changed).
    element : str
        What in the model it concerns, as ``"<tag> <name>"`` (``"geom pole"``, ``"link base"``,
        ``"joint hip"``, ``"include arm.xml"``, ``"compiler settotalmass"``), or ``"model"``.
    summary : str
        A few words saying what was found, without the values (``"geom mass from default class
        'pole' ignored; density × volume used"``).
    values : mapping of str to Any, optional
        The values on each side (``{"mujoco": 0.1, "pinocchio": 6.74}``), or what changed.
    affects_energy : bool
        Whether it changes the kinetic energy one engine computes for the same state.
    root_cause : bool
        Whether it is a root cause that explains per-segment symptoms (reports lead with these).
    segments : tuple of str
        Segments whose symptoms it explains (empty when none or unknown).
    hint : str
        What the user can do about it (an option, a file to load instead), or empty.
    cause : str
        The id of the catalogued cause it is an instance of (:func:`koenig_check.causes.cause`), or empty.
    brief : str
        For a finding without a cause: its few words in a one-line reason (``"inertia changed so that MuJoCo
        accepts it"``); empty: the summary.  A cause's brief form is its declaration's
        (:attr:`koenig_check.causes.Cause.brief`).  Not a record's key (the summary says it whole).
    """

    kind: Kind
    engine: str
    element: str
    summary: str
    values: Mapping[str, Any] = field(default_factory=dict)
    affects_energy: bool = False
    root_cause: bool = False
    segments: tuple[str, ...] = ()
    hint: str = ""
    cause: str = ""
    brief: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.kind, Kind):
            object.__setattr__(self, "kind", Kind(self.kind))
        if self.engine not in concerned():
            raise ValueError(f"Finding.engine must be one of {concerned()}, got {self.engine!r}")
        if not self.element or not self.summary:
            raise ValueError("Finding needs an element and a summary")
        object.__setattr__(self, "values", MappingProxyType(dict(self.values)))
        object.__setattr__(self, "segments", tuple(self.segments))
        if self.cause:
            from koenig_check.engines.catalogue import cause  # it reads the engines, which read findings

            cause(self.cause)  # an unknown id is a programming error: KeyError names the closest ids

    def message(self) -> str:
        """One line for people: engine, element, summary, values and hint.

        Returns
        -------
        str
        """
        text = f"{self.engine}: {self.element}: {self.summary}"
        shown = {k: v for k, v in self.values.items() if not _empty(v)}  # an empty list says nothing
        if shown:
            whole = self.kind in _WHOLE_VALUE_KINDS
            paired = _before_after(self.values)  # a value before and after a change, with digits that differ
            text += " (" + ", ".join(f"{k} {paired.get(k) or value_text(v, whole)}" for k, v in shown.items()) + ")"
        if self.hint:
            text += f"; {self.hint}"
        return text

    def as_dict(self) -> dict[str, Any]:
        """A JSON-ready dictionary of the record.

        Returns
        -------
        dict
        """
        return {
            "kind": self.kind.value,
            "engine": self.engine,
            "element": self.element,
            "summary": self.summary,
            "values": {k: _jsonable(v) for k, v in self.values.items()},
            "affects_energy": self.affects_energy,
            "root_cause": self.root_cause,
            "segments": list(self.segments),
            "hint": self.hint,
            "cause": self.cause,
        }


def root_causes(findings: Iterable[Finding]) -> list[Finding]:
    """The root causes among findings, those that change the energy first.

    Parameters
    ----------
    findings : iterable of Finding

    Returns
    -------
    list of Finding
    """
    roots = [f for f in findings if f.root_cause]
    return sorted(roots, key=lambda f: not f.affects_energy)


#: A sequence value longer than this is shown by its first items and a count (the record keeps all).
SHOWN_ITEMS = 6


#: Kinds whose values are physical quantities set on purpose below the round-off threshold, printed whole: a
#: repair raises a mass to MuJoCo's bound 1e-15 (moments 1e-14), which "mass before 0, mass after 0" would hide.
_WHOLE_VALUE_KINDS = frozenset({Kind.REPAIR})


def _empty(value: Any) -> bool:
    """A value that says nothing: an empty sequence or mapping, an empty string."""
    return isinstance(value, (tuple, list, dict, set, frozenset, str)) and not value


def value_text(value: Any, whole: bool = False) -> str:
    """A value for people: 6 significant digits; names listed ``a, b, c`` (never a Python repr).

    Parameters
    ----------
    value : Any
        A number, a vector of numbers, names, or anything else (its ``str``).
    whole : bool
        Print a number below the round-off threshold as it is, not as 0.

    Returns
    -------
    str
    """
    if isinstance(value, float):  # round-off printed as 0, as everywhere else (as_dict keeps the value)
        return format(value, ".6g") if whole else fmt(value, ".6g")
    if isinstance(value, (tuple, list)) and value and all(isinstance(v, float) for v in value):
        inner = ", ".join(value_text(v, whole) for v in value)  # a vector: 6 significant digits, as a single number
        return f"[{inner}]" if isinstance(value, list) else f"({inner})"
    if isinstance(value, (tuple, list, set, frozenset)):  # names (joints, bodies), line numbers: a plain list
        items = list(value)
        if len(items) > SHOWN_ITEMS:
            head = ", ".join(value_text(v, whole) for v in items[: SHOWN_ITEMS - 2])
            return f"{head} (+{len(items) - SHOWN_ITEMS + 2} more)"
        return ", ".join(value_text(v, whole) for v in items)
    return str(value)


def _before_after(values: Mapping[str, Any]) -> dict[str, str]:
    """``X before`` and ``X after`` numbers printed side by side (:func:`~koenig_check.roundoff.side_by_side`).

    ``mass before 0.0096, mass after 0.0096`` hid a change below the 6th digit.
    """
    out = {}
    for key, before in values.items():
        stem = key.removesuffix(" before")
        after = values.get(f"{stem} after")
        if stem == key or after is None:
            continue
        if isinstance(before, float) and isinstance(after, float):
            out[key], out[f"{stem} after"] = side_by_side([before, after])
        elif _floats(before) and _floats(after) and len(before) == len(after) <= SHOWN_ITEMS:
            pairs = [side_by_side([b, a]) for b, a in zip(before, after, strict=True)]
            out[key] = "[" + ", ".join(p[0] for p in pairs) + "]"
            out[f"{stem} after"] = "[" + ", ".join(p[1] for p in pairs) + "]"
    return out


def _floats(value: Any) -> bool:
    return isinstance(value, (list, tuple)) and bool(value) and all(isinstance(v, float) for v in value)


def _jsonable(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    return value


#: Names listed in one element before "+N more".
_SHOWN = 4


def shown_names(items: list[str] | tuple[str, ...], limit: int = _SHOWN) -> str:
    """Names for a finding's element: the first ``limit``, then how many more.

    Parameters
    ----------
    items : sequence of str
    limit : int

    Returns
    -------
    str
    """
    shown = ", ".join(items[:limit])
    return shown + (f" (+{len(items) - limit} more)" if len(items) > limit else "")
