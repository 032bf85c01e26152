"""An optional engine (Drake) that departs through a known limit of its MJCF parser: not a disagreement.

When MuJoCo and Pinocchio agree and Drake alone departs, and every cause of its departure is a construct its
MJCF parser is known not to read, Drake did not check the model: it was given another robot.  The policy
(:mod:`koenig_check.diagnosis.policy`) then decides:

* Drake *named* by the user (``--engines mujoco,pinocchio,drake``): the check asked for was not made, so the
  model fails, with an ``ENGINE_UNABLE`` finding saying exactly that ("Drake cannot check this model: its MJCF
  parser ignores armature (joints: ...)"), never a verdict of the formulas or of the engines;
* Drake consulted as tie-breaker only: the departure is not a verdict and never fails the model.

The limits are read from the model's data: a Drake ``ANCHOR`` finding on a joint of a body with several
joints (Drake's parser drops the body's ``pos`` for the first of them, which moves them all), a Drake
``ARMATURE`` finding where Drake has none and MuJoCo has some, a Drake ``IGNORED_CONSTRUCT`` (a ``<frame>``,
an ``<include>``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from koenig_check.engines.registry import LABEL
from koenig_check.findings import Finding, Kind

#: What an engine's MJCF parser does, by the kind of the finding that shows it.
LIMITS = {
    Kind.ANCHOR: "drops the pos of multi-joint bodies",
    Kind.ARMATURE: "ignores armature",
}


def _of_several(mj_model: Any, joint: str) -> bool:
    """Whether ``joint`` is one of several joints of a MuJoCo body."""
    import mujoco

    k = mujoco.mj_name2id(mj_model, mujoco.mjtObj.mjOBJ_JOINT, joint)
    if k < 0:
        return False
    body = int(mj_model.jnt_bodyid[k])
    return int(mj_model.body_jntnum[body]) > 1


def _drake_has_none(finding: Finding) -> bool:
    values = finding.values
    if finding.engine not in values or "mujoco" not in values:
        return False
    return bool(np.all(np.asarray(values[finding.engine], dtype=float) == 0)) and bool(
        np.any(np.asarray(values["mujoco"], dtype=float) != 0)
    )


def parser_limit(finding: Finding, mj_model: Any) -> tuple[str, list[str]] | None:
    """What a finding shows the engine's MJCF parser does not read, and the joints concerned; ``None`` otherwise.

    Parameters
    ----------
    finding : Finding
        A finding of an optional engine.
    mj_model : mujoco.MjModel
        MuJoCo's compiled model (the reference reading of the file).

    Returns
    -------
    (str, list of str) or None
        E.g. ``("ignores armature", ["spin"])``; for a construct that is not a joint's attribute (a
        ``<frame>``), the element itself (``("ignores <frame>", ["frame f in body b"])``).
    """
    tag, _, name = finding.element.partition(" ")
    if finding.kind is Kind.ANCHOR and tag == "joint" and _of_several(mj_model, name):
        return LIMITS[Kind.ANCHOR], [name]
    if finding.kind is Kind.ARMATURE and _drake_has_none(finding):
        return LIMITS[Kind.ARMATURE], [name]
    if finding.kind is Kind.IGNORED_CONSTRUCT:
        joints = finding.values.get("joints")
        if tag == "joint" and name and joints:  # an attribute of joints ("joint armature")
            return f"ignores {name}", [str(j) for j in joints]
        return f"ignores <{tag}>", [finding.element]
    return None


def limited_departures(
    verdicts: Sequence[Finding], findings: Sequence[Finding], mj_model: Any, asked: Sequence[str]
) -> tuple[list[Finding], list[Finding]]:
    """Split off the verdicts in which an optional engine departs only through known limits of its parser.

    Parameters
    ----------
    verdicts : sequence of Finding
        The three-engine verdicts (``VERDICT``: the engine named departs, the other two agree).
    findings : sequence of Finding
        The model's findings (the optional engine's own among them).
    mj_model : mujoco.MjModel
    asked : sequence of str
        The optional engines the user named (:func:`koenig_check.diagnosis.policy.asked_for`).

    Returns
    -------
    (list of Finding, list of Finding)
        The verdicts kept (an engine that departs only through limits of its parser is no verdict), and one
        ``ENGINE_UNABLE`` finding per named engine whose parser does not read a construct the model uses
        (whether or not it departs on the poses compared: ``parity`` compares none).
    """
    kept: list[Finding] = []
    unable: list[Finding] = []
    only_limits: set[str] = set()
    for engine in dict.fromkeys(f.engine for f in findings):
        if engine not in LABEL or engine in ("mujoco", "pinocchio"):
            continue
        own = [f for f in findings if f.engine == engine and f.affects_energy and f.kind not in _NOT_READINGS]
        read = [parser_limit(f, mj_model) for f in own]
        limits = [r for r in read if r is not None]
        if limits and engine in asked:  # named, and its parser does not read what the model uses
            unable.append(unable_finding(engine, limits))
        if own and len(limits) == len(read):
            only_limits.add(engine)
    kept = [v for v in verdicts if v.engine not in only_limits]
    return kept, unable


#: Findings that are not an engine's reading of the file.
_NOT_READINGS = (Kind.VERDICT, Kind.ENGINE_UNABLE, Kind.ENGINE_NOT_USED)


def unable_finding(engine: str, limits: Sequence[tuple[str, list[str]]]) -> Finding:
    """The ``ENGINE_UNABLE`` finding of an engine whose parser does not read what the model uses.

    Parameters
    ----------
    engine : str
    limits : sequence of (str, list of str)
        What the engine's parser does not read and the joints (or elements) concerned, per finding.

    Returns
    -------
    Finding
        ``"Drake cannot check this model: its MJCF parser ignores armature (joints: a, b)"``.
    """
    by_limit: dict[str, list[str]] = {}
    for limit, names in limits:
        known = by_limit.setdefault(limit, [])
        known += [n for n in names if n not in known]
    parts = []
    for limit, names in by_limit.items():
        shown = ", ".join(names[:2]) + (f" and {len(names) - 2} more" if len(names) > 2 else "")
        parts.append(f"{limit} ({'elements' if limit.startswith('ignores <') else 'joints'}: {shown})")
    return Finding(
        Kind.ENGINE_UNABLE,
        engine,
        "model",
        f"{LABEL[engine]} cannot check this model: its MJCF parser " + "; ".join(parts),
        segments=tuple(name for names in by_limit.values() for name in names),
        hint="without Drake: --engines mujoco,pinocchio",
    )
