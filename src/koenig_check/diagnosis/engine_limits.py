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

The limits are read from the model's data: a Drake ``ANCHOR`` finding on a joint of a body with several
joints (Drake's parser drops the body's ``pos`` for the first of them, which moves them all), a Drake
``ARMATURE`` finding where Drake has none and MuJoCo has some, a Drake ``IGNORED_CONSTRUCT`` (a ``<frame>``,
an ``<include>``), a Drake ``INERTIA`` finding on a link whose mass or inertia its URDF parser replaced (a
massless link with a rotational inertia becomes a 1 kg body: Drake cannot re-express it about its COM).
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
    Kind.INERTIA: "replaces inertias it judges unphysical",
}

#: What the names after a limit are, by the limit (joints otherwise).
_NAMED = {LIMITS[Kind.INERTIA]: "links"}


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
    if finding.kind is Kind.INERTIA and f"mass in {LABEL.get(finding.engine, finding.engine)}" in finding.values:
        return LIMITS[Kind.INERTIA], [name]  # the link whose <inertial> the parser replaced by its own
    if finding.kind is Kind.IGNORED_CONSTRUCT:
        joints = finding.values.get("joints")
        if tag == "joint" and name and joints:  # an attribute of joints ("joint armature")
            return f"ignores {name}", [str(j) for j in joints]
        return f"ignores <{tag}>", [finding.element]
    return None


def limited_engines(findings: Sequence[Finding], mj_model: Any) -> dict[str, list[tuple[str, list[str]]]]:
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
    dict of str to list of (str, list of str)
        Engine -> its limits on this model (:func:`parser_limit`), in report order; engines without any are
        left out.
    """
    out: dict[str, list[tuple[str, list[str]]]] = {}
    for f in findings:
        if f.engine not in LABEL or f.engine in ("mujoco", "pinocchio"):
            continue
        if not f.affects_energy or f.kind in _NOT_READINGS:
            continue
        limit = parser_limit(f, mj_model)
        if limit is not None:
            out.setdefault(f.engine, []).append(limit)
    return out


def unable_findings(
    limits: dict[str, list[tuple[str, list[str]]]], asked: Sequence[str], parser: str = "MJCF"
) -> list[Finding]:
    """One ``ENGINE_UNABLE`` finding per engine the user named whose parser does not read what the model uses.

    Said whether or not the engine departs on the poses compared (``parity`` compares none).

    Parameters
    ----------
    limits : dict of str to list of (str, list of str)
        As :func:`limited_engines` returns.
    asked : sequence of str
        The optional engines the user named (:func:`koenig_check.diagnosis.policy.asked_for`).
    parser : str
        The file's format, as the parser is called (``"MJCF"``, ``"URDF"``).

    Returns
    -------
    list of Finding
    """
    return [unable_finding(engine, found, parser) for engine, found in limits.items() if engine in asked]


#: Findings that are not an engine's reading of the file.
_NOT_READINGS = (Kind.VERDICT, Kind.ENGINE_UNABLE, Kind.ENGINE_NOT_USED)


def unable_finding(engine: str, limits: Sequence[tuple[str, list[str]]], parser: str = "MJCF") -> Finding:
    """The ``ENGINE_UNABLE`` finding of an engine whose parser does not read what the model uses.

    Parameters
    ----------
    engine : str
    limits : sequence of (str, list of str)
        What the engine's parser does not read and the joints (or elements, links) concerned, per finding.
    parser : str
        The file's format (``"MJCF"``, ``"URDF"``).

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
        noun = "elements" if limit.startswith("ignores <") else _NAMED.get(limit, "joints")
        parts.append(f"{limit} ({noun}: {shown})")
    return Finding(
        Kind.ENGINE_UNABLE,
        engine,
        "model",
        f"{LABEL[engine]} cannot check this model: its {parser} parser " + "; ".join(parts),
        segments=tuple(name for names in by_limit.values() for name in names),
        hint=f"without {LABEL[engine]}: --engines mujoco,pinocchio",
    )
