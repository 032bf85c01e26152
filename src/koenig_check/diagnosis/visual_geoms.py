"""Geoms with ``contype="0" conaffinity="0"``: MuJoCo weighs them, Pinocchio's MJCF parser reads them as visual only.

MuJoCo computes a body's mass and inertia from every geom (of the groups in ``inertiagrouprange``), whether it
collides or not.  Pinocchio 4.1's MJCF parser classes a geom whose resolved ``contype`` and ``conaffinity`` are
both 0 as visual only and leaves it out of the body's inertia (verified on a small file: a capsule with
``density="1000"`` under ``<default><geom contype="0" conaffinity="0"/></default>`` weighs 35.6 kg in MuJoCo and
nothing in Pinocchio; Gymnasium's swimmer is built that way and is massless in Pinocchio).  The cause is reported
when the engines' masses of a segment differ and MuJoCo, compiling the same file with those geoms' mass set to
zero, gets Pinocchio's mass there.
"""

from __future__ import annotations

from typing import Any

import mujoco

from koenig_check.diagnosis.segment_masses import compiled, mujoco_segment_masses, pinocchio_segment_masses
from koenig_check.engines.canonical import segment_of_body
from koenig_check.engines.catalogue import cause
from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind, shown_names

#: The catalogued cause of geoms read as visual only.
VISUAL_GEOMS = "pinocchio.mjcf.visual-geoms"

#: Relative mass difference (of the model's total mass) under which two masses are the same.
RTOL = 1e-9

#: The least mass and inertia MuJoCo accepts on a moving body (above its mjMINVAL, 1e-15), so that a body whose
#: geoms are all visual compiles without them; far under RTOL of any robot's mass.
_BOUND = 1e-14


def _visual(geom: Any) -> bool:
    return int(geom.contype) == 0 and int(geom.conaffinity) == 0


def visual_geom_causes(pair: Any) -> list[Finding]:
    """The visual-only geoms that weigh in MuJoCo and not in Pinocchio, when they explain a mass difference.

    Parameters
    ----------
    pair : LoadedModel
        MuJoCo and Pinocchio loaded from the same MJCF file.

    Returns
    -------
    list of Finding
        At most one ``MASS`` finding (engine ``pinocchio``, element ``geom NAMES``): the geoms Pinocchio leaves
        out, the segments they weigh on, and those segments' mass in MuJoCo, in Pinocchio and in MuJoCo without
        the geoms; empty when no segment's difference is explained by them.
    """
    try:
        spec = mujoco.MjSpec.from_file(str(pair.mujoco.path))
    except Exception:
        return []
    visual = [g for g in spec.geoms if _visual(g) and g.parent.name != "world"]
    pinocchio = pinocchio_segment_masses(pair)
    loaded = mujoco_segment_masses(pair.mujoco.model)
    scale = RTOL * max(sum(loaded.values()), sum(pinocchio.values()), 1e-300)
    if not visual or all(abs(m - pinocchio.get(s, m)) <= scale for s, m in loaded.items()):
        return []  # no geom Pinocchio reads as visual, or no mass differs: nothing to explain (and no compiling)
    as_file = compiled(spec)
    if as_file is None:
        return []
    mujoco_mass, seg_of = mujoco_segment_masses(as_file), segment_of_body(as_file)
    del as_file  # one compiled model at a time (a mesh-heavy file's weigh on the suite's memory)
    for geom in visual:
        geom.mass = 0.0  # an explicit mass overrides the density, for primitives and meshes alike
    spec.compiler.boundmass = max(float(spec.compiler.boundmass), _BOUND)
    spec.compiler.boundinertia = max(float(spec.compiler.boundinertia), _BOUND)
    without = compiled(spec)
    if without is None:
        return []
    without_mass = mujoco_segment_masses(without)
    del without
    segments = [
        s
        for s, m in mujoco_mass.items()
        if s in pinocchio and abs(m - pinocchio[s]) > scale and abs(without_mass.get(s, m) - pinocchio[s]) <= scale
    ]
    if not segments:
        return []
    geoms = [
        g.name or f"{g.parent.name}/geom{list(g.parent.geoms).index(g)}"
        for g in visual
        if seg_of.get(g.parent.name) in segments
    ]
    ignores = cause(VISUAL_GEOMS).engine  # leaves their mass out
    return [
        Finding(
            Kind.MASS,
            ignores,
            f"geom {shown_names(geoms)}",
            "contype=0 and conaffinity=0: Pinocchio's MJCF parser reads these geoms as visual only and leaves "
            "their mass out; MuJoCo weighs every geom",
            values={
                "geoms": tuple(geoms),
                reference(): float(sum(mujoco_mass[s] for s in segments)),
                ignores: float(sum(pinocchio[s] for s in segments)),
                "mujoco, visual geoms left out": float(sum(without_mass[s] for s in segments)),
            },
            affects_energy=True,
            root_cause=True,
            segments=tuple(segments),
            cause=VISUAL_GEOMS,
            tag="geom",
        )
    ]
