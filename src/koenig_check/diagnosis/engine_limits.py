"""An optional engine (Drake) whose parser does not read what the model uses: it checks another robot, no vote.

When Drake's parser is known not to read a construct the model uses (it drops, ignores or replaces it), Drake
was given another robot than the file's.  The rule, the same for every quantity and whatever the values say:

* such an engine does not vote: the three-engine verdicts are made among the engines that read the file as
  written, so with three engines none is given, and the two-engine causes (MuJoCo's and Pinocchio's) keep their
  place.  Why not keep its vote on the quantities it happens to read alike: a limit moves or changes a part of
  the robot (a body's pos, an armature, a link's mass), and what that changes downstream (every descendant's
  COM, the energy of the whole tree) is not known from the finding; an agreement of a misread robot with one
  engine would be a coincidence, and "MuJoCo departs" next to "Drake cannot check this model" would give the
  user two competing explanations of one model;
* Drake *named* by the user (``--engines mujoco,pinocchio,drake``): the check asked for was not made, so the
  model fails, with an ``ENGINE_UNABLE`` finding saying exactly that ("Drake cannot check this model: its MJCF
  parser ignores armature (joints: ...)"), never a verdict of the formulas or of the engines;
* Drake consulted as tie-breaker only: it breaks no tie, and never fails the model (its own findings stay, as
  data, in ``koenig-check parity``).

The limits are declared by each engine in its subpackage (``engines/<name>/limits.py``,
:class:`~koenig_check.engines.limit.ParserLimit`: Drake's are an ``ANCHOR`` finding on a joint of a body with
several joints, an ``ARMATURE`` finding where Drake has none and MuJoCo has some, an ``INERTIA`` finding on a
link whose mass or inertia its URDF parser replaced) and read from the model's findings by their kind, cause id
and values; an ``IGNORED_CONSTRUCT`` finding of any optional engine (a ``<frame>``, an ``<include>``, a joint
attribute) is one too.  Nothing here names an engine.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

from koenig_check.engines.catalogue import cause
from koenig_check.engines.cause import QUANTITIES
from koenig_check.engines.cross_readings import departing_reading
from koenig_check.engines.limit import limits
from koenig_check.engines.registry import label, optional, required
from koenig_check.findings import Finding, Kind


class Limit(NamedTuple):
    """What an engine's parser does not read on a model, and where."""

    says: str
    """What the parser does (``"ignores armature"``, ``"ignores <frame>"``)."""
    names: list[str]
    """The joints, links or elements concerned."""
    noun: str = "joints"
    """What :attr:`names` are."""
    cause: str = ""
    """The id of the catalogued cause the finding carries (empty: none)."""


def parser_limit(finding: Finding, mj_model: Any) -> Limit | None:
    """What a finding shows the engine's parser does not read, and the joints concerned; ``None`` otherwise.

    Parameters
    ----------
    finding : Finding
        A finding of an optional engine.
    mj_model : mujoco.MjModel
        MuJoCo's compiled model (the reference reading of the file).

    Returns
    -------
    Limit or None
        E.g. ``Limit("ignores armature", ["spin"])``; for a construct that is not a joint's attribute (a
        ``<frame>``), the element itself (``Limit("ignores <frame>", ["frame f in body b"], "elements")``).
    """
    for declared in limits(finding.engine):
        if declared.shown_by(finding, mj_model):
            return Limit(declared.says, [finding.name or finding.element], declared.names, finding.cause)
    catalogued = departing_reading(finding.cause, finding.engine) if finding.cause else None
    if catalogued is not None:  # another engine's cause that the catalogue says this engine misreads too
        c = catalogued[0]
        return Limit(f"reads {c.construct} differently", [finding.element], "elements", c.id)
    if finding.kind is Kind.IGNORED_CONSTRUCT:
        joints = finding.values.get("joints")
        if finding.tag == "joint" and joints:  # an attribute of joints ("joint armature")
            return Limit(f"ignores {finding.name}", [str(j) for j in joints], cause=finding.cause)
        what = f"<{finding.tag}>" if finding.tag else finding.element
        return Limit(f"ignores {what}", [finding.element], "elements", finding.cause)
    return None


def limited_engines(findings: Sequence[Finding], mj_model: Any) -> dict[str, list[Limit]]:
    """The optional engines whose parser does not read a construct the model uses, each with what it does not read.

    Such an engine checks another robot than the file's: it does not vote in the three-engine verdicts (see the
    module's docstring for why, on every quantity).

    Parameters
    ----------
    findings : sequence of Finding
        The model's findings (the optional engines' own among them).
    mj_model : mujoco.MjModel
        MuJoCo's compiled model (the reference reading of the file).

    Returns
    -------
    dict of str to list of Limit
        Engine -> its limits on this model (:func:`parser_limit`), in report order; engines without any are
        left out.
    """
    out: dict[str, list[Limit]] = {}
    engines = optional()
    for f in findings:
        if f.engine not in engines:
            continue
        if not f.affects_energy or f.kind in _NOT_READINGS:
            continue
        limit = parser_limit(f, mj_model)
        if limit is not None:
            out.setdefault(f.engine, []).append(limit)
    return out


def unable_findings(limits: dict[str, list[Limit]], asked: Sequence[str], parser: str = "MJCF") -> list[Finding]:
    """One ``ENGINE_UNABLE`` finding per engine the user named whose parser does not read what the model uses.

    Said whether or not the engine departs on the poses compared (``parity`` compares none).

    Parameters
    ----------
    limits : dict of str to list of Limit
        As :func:`limited_engines` returns.
    asked : sequence of str
        The optional engines the user named (:func:`koenig_check.diagnosis.policy.asked_for`).
    parser : str
        The file's format, as the parser is called (``"MJCF"``, ``"URDF"``).

    Returns
    -------
    list of Finding
    """
    return [unable_finding(engine, found, parser, asked) for engine, found in limits.items() if engine in asked]


#: Findings that are not an engine's reading of the file.
_NOT_READINGS = (Kind.VERDICT, Kind.ENGINE_UNABLE, Kind.ENGINE_NOT_USED)


def unable_finding(engine: str, limits: Sequence[Limit], parser: str = "MJCF", asked: Sequence[str] = ()) -> Finding:
    """The ``ENGINE_UNABLE`` finding of an engine whose parser does not read what the model uses.

    Parameters
    ----------
    engine : str
    limits : sequence of Limit
        What the engine's parser does not read and the joints (or elements, links) concerned, per finding.
    parser : str
        The file's format (``"MJCF"``, ``"URDF"``).
    asked : sequence of str
        The optional engines the user named: the hint keeps the others.

    Returns
    -------
    Finding
        ``"Drake cannot check this model: its MJCF parser ignores armature (joints: a, b)"``, with the hint
        ``"without Drake: --engines mujoco,pinocchio"``; its values name the catalogued causes the limits carry
        (``causes``) and the quantities they change (``quantities``), on which the engine abstains.
    """
    by_limit: dict[tuple[str, str], list[str]] = {}
    for limit in limits:
        known = by_limit.setdefault((limit.says, limit.noun), [])
        known += [n for n in limit.names if n not in known]
    parts = []
    for (says, noun), names in by_limit.items():
        shown = ", ".join(names[:2]) + (f" and {len(names) - 2} more" if len(names) > 2 else "")
        parts.append(f"{says} ({noun}: {shown})")
    others = [*required(), *(e for e in asked if e != engine)]
    ids = tuple(dict.fromkeys(limit.cause for limit in limits if limit.cause))
    quantities = tuple(q for q in QUANTITIES if any(q in cause(i).quantities for i in ids))
    return Finding(
        Kind.ENGINE_UNABLE,
        engine,
        "model",
        f"{label(engine)} cannot check this model: its {parser} parser " + "; ".join(parts),
        {"causes": ids, "quantities": quantities} if ids else {},
        segments=tuple(name for names in by_limit.values() for name in names),
        hint=f"without {label(engine)}: --engines {','.join(others)}",
    )
