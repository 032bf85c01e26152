"""Three engines compared: when two agree and the third departs, which one, and the construct responsible.

Two engines that disagree cannot say which is right; three can.  For each comparison (rigid-body
energy, reflected-inertia/armature energy, and per segment mass, COM and central inertia) the three
engines' values are compared pairwise: when two agree and the third departs, a ``VERDICT`` finding
names the engine that departs and the construct responsible where one is known (a compiler option
MuJoCo honours alone, a class value or an ``<include>`` Pinocchio ignores alone, an armature Drake's
MJCF parser does not read); when all three differ, the finding says so (engine ``"all"``).  Reports
and the one-line reason lead with these findings (they are not root causes themselves: the construct a
verdict names is, and the two-engine cause that follows in the reason keeps its place).

When Drake runs (on every pose, or only where MuJoCo and Pinocchio disagree) is the checker's policy
(:mod:`koenig_check.diagnosis.policy`); this module is the pure logic on the engines' values.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from koenig_check.engines.registry import ENGINE_NAMES, LABEL
from koenig_check.findings import Finding, Kind

#: Default relative tolerance under which two engines "agree".
TIEBREAK_RTOL = 1e-9


def _close(a: np.ndarray, b: np.ndarray, rtol: float, scale: np.ndarray | float | None = None) -> np.ndarray:
    ref = np.maximum(np.abs(a), np.abs(b)) if scale is None else scale
    return np.abs(a - b) <= rtol * np.maximum(ref, 1e-300)


def _odd_one_out(values: dict[str, np.ndarray], rtol: float, scale: Any = None) -> str | None:
    """``None`` when all agree, the engine that departs when two agree, ``"all"`` when all differ."""
    names = list(values)
    agree: dict[tuple[str, ...], bool] = {
        (a, b): bool(np.all(_close(values[a], values[b], rtol, scale)))
        for i, a in enumerate(names)
        for b in names[i + 1 :]
    }
    if all(agree.values()):
        return None
    for odd in names:
        rest = [n for n in names if n != odd]
        if agree[tuple(rest)] if tuple(rest) in agree else agree[(rest[1], rest[0])]:
            return odd
    return "all"


def departure_cause(findings: Sequence[Finding], engine: str, segments: Sequence[str] = ()) -> Finding | None:
    """The known construct responsible for an engine's departure, from the model's findings.

    Root causes that change the energy, about that engine, first those that explain the given segments;
    for MuJoCo, first a compiler option (``compiler settotalmass``), which the two-engine parity may have
    recorded against Pinocchio ("Pinocchio does not rescale"): with three engines, MuJoCo is the one that
    applies it alone.

    Parameters
    ----------
    findings : sequence of Finding
    engine : str
    segments : sequence of str
        Segments whose values depart (empty: any).

    Returns
    -------
    Finding or None
    """
    own = [f for f in findings if f.engine == engine and f.affects_energy and f.kind is not Kind.VERDICT]
    roots = [f for f in own if f.root_cause] or [f for f in own if f.kind in (Kind.COMPILER, Kind.IGNORED_CONSTRUCT)]
    if engine == "mujoco":  # a compiler option only MuJoCo applies, whichever engine the pair's finding blamed
        options = [
            f for f in findings if f.kind is Kind.COMPILER and f.affects_energy and f.element.startswith("compiler ")
        ]
        roots = options + [f for f in roots if f not in options]
    if segments:
        hit = [f for f in roots if set(f.segments) & set(segments)]
        roots = hit or roots
    return roots[0] if roots else None


def _shared_cause(engines: Sequence[str], findings: Sequence[Finding], segments: Sequence[str]) -> Finding | None:
    """A construct every one of ``engines`` skips (the same element named as a cause of each), or None."""
    causes = [departure_cause(findings, e, segments) for e in engines]
    found = [c for c in causes if c is not None]
    if len(found) != len(causes) or len({c.element for c in found}) != 1:
        return None
    return found[0]


def _construct(cause: Finding) -> str:
    """The construct a cause names: ``compiler settotalmass`` rather than the body it altered."""
    if cause.kind is Kind.COMPILER and cause.engine == "mujoco":
        if float(cause.values.get("settotalmass", -1) or -1) > 0:
            return "compiler settotalmass"
    return cause.element


def _verdict(
    what: str, odd: str, values: dict[str, float], findings: Sequence[Finding], segments: Sequence[str] = ()
) -> Finding:
    """A ``VERDICT`` finding: who departs on ``what`` and why, or that all three differ."""
    if odd == "all":
        causes = {e: departure_cause(findings, e, segments) for e in values}
        known = "; ".join(f"{LABEL[e]}: {_construct(c)} ({c.kind.value})" for e, c in causes.items() if c is not None)
        return Finding(
            Kind.VERDICT,
            "all",
            what,
            "all three engines differ" + (f"; constructs: {known}" if known else ""),
            values,
            affects_energy=True,
            segments=tuple(segments),
        )
    others = " and ".join(LABEL[e] for e in values if e != odd)
    cause = departure_cause(findings, odd, segments)
    summary = f"{LABEL[odd]} departs ({others} agree)"
    if cause is not None:
        summary += f"; construct responsible: {_construct(cause)}"
    else:  # the two that agree may skip the same construct: then the odd one reads the file as written
        shared = _shared_cause([e for e in values if e != odd], findings, segments)
        if shared is not None:
            cause = shared
            summary += f"; {others} both skip {_construct(shared)}: {LABEL[odd]} reads the file as written"
    return Finding(
        Kind.VERDICT,
        odd,
        what,
        summary,
        values,
        affects_energy=True,
        segments=tuple(segments) or tuple(cause.segments if cause else ()),
        hint=cause.summary if cause is not None else "cause unknown",
    )


def energy_verdicts(runs: dict[str, Any], findings: Sequence[Finding], rtol: float = TIEBREAK_RTOL) -> list[Finding]:
    """Three-way verdicts on the rigid-body energy and the armature (reflected-inertia) energy.

    Parameters
    ----------
    runs : dict of str to EngineRun
        Needs ``"mujoco"``, ``"pinocchio"`` and ``"drake"``; otherwise nothing is said.
    findings : sequence of Finding
        The model's findings (causes are looked up there).
    rtol : float

    Returns
    -------
    list of Finding
        At most one per quantity, with the values at the pose of largest spread.
    """
    if not all(e in runs for e in ENGINE_NAMES):
        return []
    out = []
    rigid = {e: np.asarray(runs[e].rigid, dtype=float) for e in ENGINE_NAMES}
    odd = _odd_one_out(rigid, rtol)
    if odd is not None:
        k = int(np.argmax(np.ptp(np.stack(list(rigid.values())), axis=0)))
        out.append(_verdict("rigid-body energy", odd, {e: float(v[k]) for e, v in rigid.items()}, findings))
    arm = {e: np.asarray(runs[e].armature, dtype=float) for e in ENGINE_NAMES}
    scale = np.abs(rigid["mujoco"]) + np.abs(arm["mujoco"])
    odd = _odd_one_out(arm, rtol, scale)
    if odd is not None:
        k = int(np.argmax(np.ptp(np.stack(list(arm.values())), axis=0)))
        out.append(_verdict("armature energy", odd, {e: float(v[k]) for e, v in arm.items()}, findings))
    return out


def import_verdicts(
    states: dict[str, Any],
    findings: Sequence[Finding],
    rtol: float = TIEBREAK_RTOL,
    labels: Mapping[str, str] | None = None,
) -> list[Finding]:
    """Three-way verdicts on each segment's mass, COM and central inertia (world axes) in one state.

    Frames are not compared (each engine has its own segment frame: a body, a joint frame), only what
    the mass distribution is in the world at the same canonical state.

    Parameters
    ----------
    states : dict of str to SegmentStates
        Each engine's segment states at the same single canonical state (MuJoCo's ``qpos0``).
    findings : sequence of Finding
    rtol : float
    labels : mapping of str to str, optional
        Segment name -> how the user wrote it (``"link forearm (joint elbow)"``).

    Returns
    -------
    list of Finding
        One per quantity and departing engine (segments grouped), with the worst segment's values.
    """
    if not all(e in states for e in ENGINE_NAMES):
        return []
    common = [n for n in states["mujoco"].names if all(n in states[e].names for e in ENGINE_NAMES)]
    if not common:
        return []
    sel = {e: states[e].select(segments=common) for e in ENGINE_NAMES}
    world_inertia = {
        e: np.einsum("bij,bjk,blk->bil", s.rotation[0], s.inertia_body, s.rotation[0]) for e, s in sel.items()
    }
    quantities = {
        "mass": ({e: s.mass for e, s in sel.items()}, None),
        "COM": ({e: s.com[0] for e, s in sel.items()}, "length"),
        "inertia": (world_inertia, "inertia"),
    }
    size = max(float(np.abs(sel["mujoco"].com[0]).max()), 1.0)
    grouped: dict[tuple[str, str], list[tuple[str, dict[str, Any]]]] = {}
    for label, (vals, kind) in quantities.items():
        for b, name in enumerate(common):
            per = {e: np.asarray(v[b], dtype=float) for e, v in vals.items()}
            scale = size if kind == "length" else None
            if kind == "inertia":
                scale = max(float(np.abs(per["mujoco"]).max()), float(np.abs(per["pinocchio"]).max()))
            odd = _odd_one_out(per, rtol, scale)
            if odd is not None:
                shown = {e: _shown(v) for e, v in per.items()}
                grouped.setdefault((label, odd), []).append((name, shown))
    out = []
    for (label, odd), items in grouped.items():
        segments = [n for n, _ in items]
        what = "principal moments" if label == "inertia" else label
        first = (labels or {}).get(segments[0], f"segment {segments[0]}")  # the link or body the user wrote
        element = f"{first} {what}" + (f" (+{len(segments) - 1} segments)" if len(segments) > 1 else "")
        out.append(_verdict(element, odd, items[0][1], findings, segments))
    return out


def _shown(value: np.ndarray) -> Any:
    """A value for a finding: a float, a point, or an inertia's principal moments."""
    if value.ndim == 0:
        return float(value)
    if value.ndim == 2:
        return np.round(np.linalg.eigvalsh(0.5 * (value + value.T)), 12).tolist()
    return np.round(value, 12).tolist()
