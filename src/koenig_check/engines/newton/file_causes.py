"""The catalogued Newton causes that apply to the user's file, as findings with their ids and their effect here.

Called when Newton is attached to a model: each cause is looked for in the file (its construct) or in Newton's
model (what ``finalize()`` changed), and sized on this robot with Newton's own arrays
(:mod:`koenig_check.engines.newton.departures`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from koenig_check.engines.newton import PRECISION
from koenig_check.engines.newton import causes as ids
from koenig_check.engines.newton.departures import (
    BodyChange,
    collision_masses,
    joints_lost,
    option_effect,
    validation_changes,
    welded_massive_bodies,
)
from koenig_check.findings import Finding, Kind


def _changed_bodies(cause: str, changes: list[BodyChange], segment_of: dict[str, str], effect: float) -> Finding:
    """An ``INERTIA`` root cause: the bodies whose mass properties Newton changed, with Newton's and the file's."""
    names = [c.body for c in changes]
    segments = tuple(dict.fromkeys(s for label, s in segment_of.items() if label.rsplit("/", 1)[-1] in names))
    first = changes[0]
    return Finding(
        Kind.INERTIA,
        "newton",
        f"link {first.body}" + (f" (+{len(changes) - 1} links)" if len(changes) > 1 else ""),
        f"Newton changes the mass properties the file gives (M changes by {effect:.3g} relative on this robot)",
        {
            "links": names,
            "mass in Newton": [c.newton_mass for c in changes],
            "mass in the file": [c.read_mass for c in changes],
            "inertia in Newton": [c.newton_inertia for c in changes],
            "inertia in the file": [c.read_inertia for c in changes],
            "M change": effect,
        },
        affects_energy=True,
        root_cause=True,
        segments=segments,
        cause=cause,
    )


def anchor_findings(mj_model: Any, model: Any, pairs: list[Any], segment_of_joint: dict[str, str]) -> list[Finding]:
    """One ``ANCHOR`` root cause per MuJoCo joint that Newton turns about another point (a multi-joint body's D6).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    model : newton.Model
    pairs : list of NewtonJointPair
    segment_of_joint : dict of str to str
        MuJoCo joint -> the segment it moves.

    Returns
    -------
    list of Finding
    """
    from koenig_check.engines.newton.departures import moved_anchors
    from koenig_check.engines.specs import reference

    return [
        Finding(
            Kind.ANCHOR,
            "newton",
            f"joint {name}",
            "Newton turns the joint about another point than MuJoCo (one D6 joint for the body's joints, anchored "
            "at the first joint's pos)",
            {reference(): mine, "newton": theirs},
            affects_energy=True,
            root_cause=True,
            segments=(segment_of_joint.get(name, name),),
            cause=ids.MULTI_JOINT_POS,
        )
        for name, mine, theirs in moved_anchors(mj_model, model, pairs)
    ]


def attach_causes(
    path: Path, fmt: str, load: Callable[..., Any], model: Any, segment_of: dict[str, str]
) -> list[Finding]:
    """The catalogued causes that apply to a file Newton loaded, each with its effect on this robot.

    Parameters
    ----------
    path : Path
    fmt : str
        ``"mjcf"`` or ``"urdf"``.
    load : callable
        ``load(finalize=..., options=...) -> (newton.Model, warnings)``: the same file in Newton, one world.
    model : newton.Model
        The file as Newton's users load it.
    segment_of : dict of str to str
        Newton body label -> segment (:meth:`NewtonEngine.segment_of_body`).

    Returns
    -------
    list of Finding
    """
    out = []
    if fmt == "urdf":
        bare = collision_masses(path, model)
        if bare:
            effect = _effect_without(load, model, [c.body for c in bare])
            out.append(_changed_bodies(ids.NO_INERTIAL, bare, segment_of, effect))
    raw, _ = load(finalize={"skip_validation_inertia": True})
    changed = validation_changes(raw, model)
    if changed:
        out.append(_changed_bodies(ids.VALIDATION, changed, segment_of, option_effect(raw, model)))
    del raw  # one model of the file at a time besides the one checked
    # a change within Newton's round-off is not a difference: said, as a loading fact, not a departure
    out = [f if f.values.get("M change", 1.0) > PRECISION else _below_precision(f) for f in out]
    welded = welded_massive_bodies(model)
    if welded:
        collapsed, _ = load(options={"collapse_fixed_joints": True})
        effect = option_effect(model, collapsed)
        if effect > PRECISION:
            out.append(
                Finding(
                    Kind.LOAD,
                    "newton",
                    "option collapse_fixed_joints",
                    f"Newton's collapse_fixed_joints=True would change M by {effect:.3g} relative on this robot",
                    {"links merged": welded, "M change": effect},
                    cause=ids.COLLAPSE,
                )
            )
    if fmt == "mjcf":
        fixed, _ = load(options={"floating": False})
        lost = joints_lost(model, fixed)
        if lost:
            out.append(
                Finding(
                    Kind.LOAD,
                    "newton",
                    "option floating=False",
                    "Newton's add_mjcf(floating=False) would replace the root body's own joints by a fixed joint",
                    {"joints": lost},
                    cause=ids.FLOATING_FALSE,
                )
            )
    return out


def _effect_without(load: Callable[..., Any], model: Any, links: list[str]) -> float:
    """M's change from what Newton gave the links without ``<inertial>``: a second load with their mass zeroed."""
    import numpy as np

    from koenig_check.engines.newton.state_map import short_name

    other, _ = load()
    bare = [k for k, label in enumerate(other.body_label) if short_name(label) in links]
    mass, inertia = other.body_mass.numpy(), other.body_inertia.numpy()
    mass[bare], inertia[bare] = 0.0, 0.0
    other.body_mass.assign(mass)
    other.body_inertia.assign(inertia)
    return option_effect(other, model) if np.any(mass > 0) else float("nan")


def _below_precision(finding: Finding) -> Finding:
    """A change of Newton's within its precision: kept as a loading fact (kind ``LOAD``), not a root cause."""
    from dataclasses import replace

    return replace(finding, kind=Kind.LOAD, affects_energy=False, root_cause=False)
