"""Why an engine's gravity terms differ from MuJoCo's: a catalogued cause, a mass cause already found, or none.

Rules, engine by engine, for an engine whose ``g(q)`` or ``dV`` differs:

1. Its gravity *vector* differs from MuJoCo's: a file construct read differently.  MJCF's
   ``<flag gravity="disable"/>`` (MuJoCo applies none, the engine some) gives ``<engine>.mjcf.flag-gravity-disable``;
   ``<option gravity>`` away from the default with the engine at the default gives ``<engine>.mjcf.option-gravity``.
   The cause's id, brief and hint come from the catalogue; a reading no entry describes is still a root cause,
   with both vectors and no id.
2. The vectors agree and the engine dropped a welded root body's pose (a ``FRAME`` root cause of that engine):
   ``<engine>.mjcf.welded-root-pose``, which only gravity sees; or the file has joints whose defaults come through
   a class without ``<joint>`` and the engine declares ``<engine>.mjcf.class-joint-default`` (a lost joint axis).
3. The vectors agree and a root cause already found for that engine changes its masses, COMs or kinematics (or,
   without one, an import difference of those): that cause explains ``g(q)``; the gravity finding refers to it
   (its element under ``"explained by"``, its id under ``"explained by cause"``) and is no root cause and carries
   no cause id itself (the cause is named once).
4. Otherwise the difference is reported without a cause.

URDF carries no gravity: a note says every engine applied its default.  Springs are never gravity: an engine
that counts spring energy gets a note with its size.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from koenig_check.engines import registry
from koenig_check.engines.catalogue import applies, catalogue
from koenig_check.findings import Finding, Kind
from koenig_check.roundoff import ROUNDOFF

if TYPE_CHECKING:
    from koenig_check.gravity.parity import GravityParity

#: MuJoCo's default gravity: what a parser that ignores ``<option>`` keeps.
DEFAULT_GRAVITY = np.array([0.0, 0.0, -9.81])

#: Kinds of root causes that change g(q) through the masses, COMs or kinematics.
_EXPLAINING = (Kind.MASS, Kind.COM, Kind.SEGMENTS, Kind.AXIS, Kind.ANCHOR, Kind.COMPILER, Kind.IGNORED_CONSTRUCT)


def _default(vector: np.ndarray) -> bool:
    """Whether a gravity vector is MuJoCo's default, to round-off."""
    return bool(np.abs(vector - DEFAULT_GRAVITY).max() <= ROUNDOFF)


def _vec(x: np.ndarray) -> tuple[float, ...]:
    return tuple(round(float(v), 12) + 0.0 for v in np.ravel(x))


def gravity_findings(parity: GravityParity, mj_model: Any, path: str, fmt: str, known: list[Finding]) -> list[Finding]:
    """The findings that explain (or note) the gravity verdict of one model.

    Parameters
    ----------
    parity : GravityParity
        Readings and gaps (its ``findings`` are not read).
    mj_model : mujoco.MjModel
        MuJoCo's model (its ``opt.gravity`` and disable flag are the file's as written).
    path : str
        The model file (its default classes are read for the joint-default cause).
    fmt : {"mjcf", "urdf"}
    known : list of Finding
        What is already known about the model.

    Returns
    -------
    list of Finding
        One per engine whose gap exceeds the tolerance (why it differs), after URDF's note; the springs'
        notes are :func:`springs`.
    """
    from koenig_check.engines.mujoco.gravity import gravity_disabled

    ids = {c.id: c for c in catalogue() if applies(c.id)}  # a reading declared for other versions does not fire
    reference = registry.reference()
    ref = parity.readings[reference].vector
    out: list[Finding] = []
    if fmt == "urdf":
        out.append(
            Finding(
                Kind.GRAVITY,
                "file",
                "model",
                "URDF carries no gravity: each engine applied its default",
                {e: v for e, v in parity.vectors().items()},
            )
        )
    differing = sorted({g.engine for g in parity.gaps if g.relative > parity.rtol})
    for engine in differing:
        vector = parity.readings[engine].vector
        values = {reference: _vec(ref), engine: _vec(vector)}
        if not np.allclose(vector, ref, rtol=parity.rtol, atol=parity.rtol * max(np.abs(ref).max(), 1.0)):
            if fmt == "mjcf" and gravity_disabled(mj_model) and np.any(vector):
                key, element = f"{engine}.mjcf.flag-gravity-disable", "flag gravity"
            elif fmt == "mjcf" and _default(vector) and not _default(ref):
                key, element = f"{engine}.mjcf.option-gravity", "option gravity"
            else:
                key, element = "", "option gravity"
            entry = ids.get(key)
            summary = entry.brief if entry else "gravity vector read differently from the file"
            out.append(
                Finding(
                    Kind.GRAVITY,
                    engine,
                    element,
                    summary,
                    values,
                    root_cause=True,
                    hint=entry.hint if entry else "",
                    cause=entry.id if entry else "",
                )
            )
            continue
        out.append(_same_vector(engine, parity, known, ids, path if fmt == "mjcf" else ""))
    return out


def _same_vector(engine: str, parity: GravityParity, known: list[Finding], ids: dict[str, Any], path: str) -> Finding:
    """The finding for an engine whose g(q) differs under the same gravity vector."""
    from koenig_check.modelfile.joint_classes import inherited_through_jointless_class

    gaps = {g.quantity: g for g in parity.gaps if g.engine == engine}
    values = {"g(q) relative": gaps["g(q)"].relative, "dV relative": gaps["dV"].relative, "pose": gaps["g(q)"].pose}
    frame = [f for f in known if f.kind is Kind.FRAME and f.root_cause and f.engine == engine]
    entry = ids.get(f"{engine}.mjcf.welded-root-pose")
    if frame and entry is not None:
        return Finding(
            Kind.GRAVITY,
            engine,
            frame[0].element,
            entry.brief,
            {**values, **frame[0].values},
            root_cause=True,
            hint=entry.hint,
            cause=entry.id,
        )
    entry = ids.get(f"{engine}.mjcf.class-joint-default")
    joints = inherited_through_jointless_class(path) if entry is not None and path else ()
    if entry is not None and joints:
        return Finding(
            Kind.GRAVITY,
            engine,
            f"joint {joints[0]}",
            entry.brief,
            {**values, "joints": joints},
            root_cause=True,
            hint=entry.hint,
            cause=entry.id,
        )
    concerned = (engine, "both", registry.reference())  # the reference's own departure (settotalmass) moves every gap
    concerning = [f for f in known if f.affects_energy and f.kind in _EXPLAINING and f.engine in concerned]
    explaining = [f for f in concerning if f.root_cause] or concerning  # a root cause, else the symptom found
    if explaining:
        by = explaining[0]
        return Finding(  # a symptom: the cause keeps its element, named once; this one refers to it
            Kind.GRAVITY,
            engine,
            "model",
            f"g(q) differs: explained by the {by.kind.value} difference of {by.element}",
            {**values, "explained by": by.element, "explained by cause": by.cause},
        )  # no cause= of its own: the id is the explaining finding's, carried by it alone
    return Finding(Kind.GRAVITY, engine, "model", "g(q) differs under the same gravity vector: no cause found", values)


def springs(parity: GravityParity) -> list[Finding]:
    """A note per engine that counts spring energy: kept apart, never compared as gravity.

    Parameters
    ----------
    parity : GravityParity

    Returns
    -------
    list of Finding
    """
    out = []
    for engine, r in parity.readings.items():
        size = float(np.abs(r.dv_springs).max(initial=0.0))
        scale = max(1.0, float(np.abs(r.v_gravity).max(initial=0.0)))  # Drake's springs are V minus -m g·c
        if size > ROUNDOFF * scale:
            out.append(
                Finding(
                    Kind.GRAVITY,
                    engine,
                    "springs",
                    "spring energy counted in its potential energy: kept apart, not compared as gravity",
                    {"max |dV springs|": size},
                )
            )
    return out
