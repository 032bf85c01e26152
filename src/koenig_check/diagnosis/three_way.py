"""Three engines or more compared: when a majority agrees and the others depart, which, and the construct responsible.

Two engines that disagree cannot say which is right; three can.  For each comparison (rigid-body
energy, reflected-inertia/armature energy, and per segment mass, COM and central inertia) the engines'
values are compared pairwise: when a majority agrees (two of three) and the others depart, a ``VERDICT``
finding per departing engine names it and the construct responsible where one is known (a compiler option
MuJoCo honours alone, a class value or an ``<include>`` Pinocchio ignores alone, an armature Drake's
MJCF parser does not read); when no majority agrees (all three differ), the finding says so (engine
``"all"``).  Reports
and the one-line reason lead with these findings (they are not root causes themselves: the construct a
verdict names is, and the two-engine cause that follows in the reason keeps its place).

When Drake runs (on every pose, or only where MuJoCo and Pinocchio disagree) is the checker's policy
(:mod:`koenig_check.diagnosis.policy`); this module is the pure logic on the engines' values.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from itertools import combinations
from typing import Any

import numpy as np

from koenig_check.diagnosis.cause_effect import by_effect
from koenig_check.engines.registry import label, names, reference, required, spec
from koenig_check.findings import Finding, Kind

#: Default relative tolerance under which two engines "agree".
TIEBREAK_RTOL = 1e-9


def _close(a: np.ndarray, b: np.ndarray, rtol: float, scale: np.ndarray | float | None = None) -> np.ndarray:
    ref = np.maximum(np.abs(a), np.abs(b)) if scale is None else scale
    return np.abs(a - b) <= rtol * np.maximum(ref, 1e-300)


def _pair_rtol(rtol: float, *engines: str) -> float:
    """The tolerance two engines agree within: ``rtol``, or the coarser precision either declares (its spec's)."""
    declared = [spec(e).precision for e in engines if e in names()]
    return max([rtol, *declared])


def _departing(values: dict[str, np.ndarray], rtol: float, scale: Any = None) -> tuple[str, ...] | None:
    """``None`` when all agree; the engines that depart when the others, a majority, agree; ``("all",)`` else.

    Two engines agree within ``rtol`` or the coarser of their declared precisions (PyBullet's diagonalized
    inertias, a float32 engine), so that an engine's round-off is never called a departure.

    The fewest departing engines are looked for first, in report order (of three: the first engine whose two
    others agree).
    """
    engines = list(values)
    agree: dict[frozenset[str], bool] = {
        frozenset((a, b)): bool(np.all(_close(values[a], values[b], _pair_rtol(rtol, a, b), scale)))
        for a, b in combinations(engines, 2)
    }
    if all(agree.values()):
        return None
    for k in range(1, (len(engines) + 1) // 2):  # the others (more than half) must all agree with each other
        for departing in combinations(engines, k):
            rest = [e for e in engines if e not in departing]
            if all(agree[frozenset(pair)] for pair in combinations(rest, 2)):
                return departing
    return ("all",)


def _ordered(engines: Iterable[str]) -> list[str]:
    """Engines in report order (names the registry does not know last, as given)."""
    given = list(engines)
    known = names()
    return [e for e in known if e in given] + [e for e in given if e not in known]


def _listed(engines: Sequence[str]) -> str:
    """``"MuJoCo and Pinocchio"``, ``"MuJoCo, Pinocchio and Drake"``."""
    labels = [label(e) for e in engines]
    return labels[0] if len(labels) == 1 else ", ".join(labels[:-1]) + " and " + labels[-1]


def departure_cause(findings: Sequence[Finding], engine: str, segments: Sequence[str] = ()) -> Finding | None:
    """The known construct responsible for an engine's departure, from the model's findings.

    Root causes that change the energy, about that engine (each cause is built against the engine it concerns:
    a compiler option only MuJoCo applies is MuJoCo's), first those that explain the given segments, ranked as
    the reason ranks them (:func:`koenig_check.diagnosis.cause_effect.by_effect`: the largest measured effect
    first, the others in their place).

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
    if segments:
        hit = [f for f in roots if set(f.segments) & set(segments)]
        roots = hit or roots
    ranked = by_effect(roots)
    return ranked[0] if ranked else None


def _shared_cause(engines: Sequence[str], findings: Sequence[Finding], segments: Sequence[str]) -> Finding | None:
    """A construct every one of ``engines`` skips (the same element named as a cause of each), or None."""
    causes = [departure_cause(findings, e, segments) for e in engines]
    found = [c for c in causes if c is not None]
    if len(found) != len(causes) or len({c.element for c in found}) != 1:
        return None
    return found[0]


def _construct(cause: Finding) -> str:
    """The construct a cause names: ``compiler settotalmass`` rather than the body it altered."""
    if cause.kind is Kind.COMPILER and float(cause.values.get("settotalmass", -1) or -1) > 0:
        return "compiler settotalmass"
    return cause.element


def _verdicts(
    what: str,
    departing: Sequence[str],
    values: dict[str, Any],
    findings: Sequence[Finding],
    segments: Sequence[str] = (),
) -> list[Finding]:
    """``VERDICT`` findings: who departs on ``what`` and why (one per departing engine), or that no majority agrees."""
    if tuple(departing) == ("all",):
        causes = {e: departure_cause(findings, e, segments) for e in values}
        known = "; ".join(f"{label(e)}: {_construct(c)} ({c.kind.value})" for e, c in causes.items() if c is not None)
        head = _no_majority(len(values))
        return [
            Finding(
                Kind.VERDICT,
                "all",
                what,
                head + (f"; constructs: {known}" if known else ""),
                values,
                affects_energy=True,
                segments=tuple(segments),
            )
        ]
    agreeing = [e for e in values if e not in departing]
    return [_departure(what, odd, agreeing, values, findings, segments) for odd in departing]


def _no_majority(voters: int) -> str:
    return "all three engines differ" if voters == 3 else f"no majority of the {voters} engines agrees"


def _departs(engine: str) -> str:
    return f"{label(engine)} departs"


def verdict_head(verdict: Finding) -> str:
    """A ``VERDICT`` in a few words, from its engine and values: ``Pinocchio departs``, ``all three engines differ``.

    Parameters
    ----------
    verdict : Finding
        A finding of kind ``VERDICT`` (its values hold one entry per voting engine).

    Returns
    -------
    str
    """
    return _no_majority(len(verdict.values)) if verdict.engine == "all" else _departs(verdict.engine)


def _departure(
    what: str,
    odd: str,
    agreeing: Sequence[str],
    values: dict[str, Any],
    findings: Sequence[Finding],
    segments: Sequence[str],
) -> Finding:
    """One ``VERDICT`` finding: ``odd`` departs on ``what`` from the engines that agree, and why."""
    others = _listed(agreeing)
    cause = departure_cause(findings, odd, segments)
    summary = f"{_departs(odd)} ({others} agree)"
    if cause is not None:
        summary += f"; construct responsible: {_construct(cause)}"
    else:  # the engines that agree may skip the same construct: then the odd one reads the file as written
        shared = _shared_cause(agreeing, findings, segments)
        if shared is not None:
            cause = shared
            every = "both" if len(agreeing) == 2 else "all"
            summary += f"; {others} {every} skip {_construct(shared)}: {label(odd)} reads the file as written"
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
    """Verdicts of three engines or more on the rigid-body energy and the armature (reflected-inertia) energy.

    Parameters
    ----------
    runs : dict of str to EngineRun
        Each engine's energies (``rigid``, ``armature``): needs the reference engine's
        (:func:`~koenig_check.engines.registry.reference`) and at least two others; otherwise nothing is said.
    findings : sequence of Finding
        The model's findings (causes are looked up there).
    rtol : float

    Returns
    -------
    list of Finding
        Per quantity, one per departing engine (or one saying no majority agrees), with the values at the pose
        of largest spread.
    """
    ref = reference()
    if len(runs) < 3 or ref not in runs:
        return []
    engines = _ordered(runs)
    out = []
    rigid = {e: np.asarray(runs[e].rigid, dtype=float) for e in engines}
    departing = _departing(rigid, rtol)
    if departing is not None:
        k = int(np.argmax(np.ptp(np.stack(list(rigid.values())), axis=0)))
        out += _verdicts("rigid-body energy", departing, {e: float(v[k]) for e, v in rigid.items()}, findings)
    arm = {e: np.asarray(runs[e].armature, dtype=float) for e in engines}
    scale = np.abs(rigid[ref]) + np.abs(arm[ref])  # the reference's whole energy
    departing = _departing(arm, rtol, scale)
    if departing is not None:
        k = int(np.argmax(np.ptp(np.stack(list(arm.values())), axis=0)))
        out += _verdicts("armature energy", departing, {e: float(v[k]) for e, v in arm.items()}, findings)
    return out


def import_verdicts(
    states: dict[str, Any],
    findings: Sequence[Finding],
    rtol: float = TIEBREAK_RTOL,
    labels: Mapping[str, str] | None = None,
) -> list[Finding]:
    """Verdicts of three engines or more on each segment's mass, COM and central inertia (world axes) in one state.

    Frames are not compared (each engine has its own segment frame: a body, a joint frame), only what
    the mass distribution is in the world at the same canonical state.

    Parameters
    ----------
    states : dict of str to SegmentStates
        Each engine's segment states at the same single canonical state (MuJoCo's ``qpos0``): needs the
        required engines' (:func:`~koenig_check.engines.registry.required`) and at least one other; otherwise
        nothing is said.
    findings : sequence of Finding
    rtol : float
    labels : mapping of str to str, optional
        Segment name -> how the user wrote it (``"link forearm (joint elbow)"``).

    Returns
    -------
    list of Finding
        One per quantity and departing engine (segments grouped), with the worst segment's values.
    """
    ref = reference()
    if len(states) < 3 or not {ref, *required()} <= set(states):
        return []
    engines = _ordered(states)
    common = [n for n in states[ref].names if all(n in states[e].names for e in engines)]
    if not common:
        return []
    sel = {e: states[e].select(segments=common) for e in engines}
    world_inertia = {
        e: np.einsum("bij,bjk,blk->bil", s.rotation[0], s.inertia_body, s.rotation[0]) for e, s in sel.items()
    }
    quantities = {
        "mass": ({e: s.mass for e, s in sel.items()}, None),
        "COM": ({e: s.com[0] for e, s in sel.items()}, "length"),
        "inertia": (world_inertia, "inertia"),
    }
    size = max(float(np.abs(sel[ref].com[0]).max()), 1.0)
    about = {e: s.inertia_about_anchor() for e, s in sel.items()}
    grouped: dict[tuple[str, tuple[str, ...]], list[tuple[str, dict[str, Any]]]] = {}
    for quantity, (vals, kind) in quantities.items():
        for b, name in enumerate(common):
            per = {e: np.asarray(v[b], dtype=float) for e, v in vals.items()}
            scale = size if kind == "length" else None
            if kind == "inertia":  # against the inertia about the anchor (what the segment's rotation weighs)
                scale = max(float(about[e][b]) for e in engines)
            departing = _departing(per, rtol, scale)
            if departing is not None:
                shown = {e: _shown(v) for e, v in per.items()}
                grouped.setdefault((quantity, departing), []).append((name, shown))
    out = []
    for (quantity, departing), items in grouped.items():
        segments = [n for n, _ in items]
        what = "principal moments" if quantity == "inertia" else quantity
        first = (labels or {}).get(segments[0], f"segment {segments[0]}")  # the link or body the user wrote
        element = f"{first} {what}" + (f" (+{len(segments) - 1} segments)" if len(segments) > 1 else "")
        out += _verdicts(element, departing, items[0][1], findings, segments)
    return out


def _shown(value: np.ndarray) -> Any:
    """A value for a finding: a float, a point, or an inertia's principal moments."""
    if value.ndim == 0:
        return float(value)
    if value.ndim == 2:
        return np.round(np.linalg.eigvalsh(0.5 * (value + value.T)), 12).tolist()
    return np.round(value, 12).tolist()
