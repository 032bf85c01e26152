"""``compiler inertiagrouprange``: geoms MuJoCo leaves out of the inertia and Pinocchio's MJCF parser counts.

MuJoCo computes a body's mass and inertia from its geoms of the groups in ``inertiagrouprange`` only (default
``0 5``, every group); Pinocchio 4.1's and Drake 1.51's MJCF parsers ignore the option and count every geom
(verified on a small file: a sphere of group 3 under ``inertiagrouprange="0 2"`` weighs in both, not in
MuJoCo).  The cause is reported when the engines' masses of a segment differ and MuJoCo, compiling the same
file with every group counted, gets Pinocchio's mass there.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from koenig_check.diagnosis.segment_masses import compiled, mujoco_segment_masses, pinocchio_segment_masses
from koenig_check.engines.canonical import segment_of_body
from koenig_check.engines.catalogue import cause
from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind, shown_names

#: The catalogued cause of a compiler inertiagrouprange.
INERTIA_GROUPS = "pinocchio.mjcf.inertiagrouprange"

#: Relative mass difference under which two masses are the same.
RTOL = 1e-9


def _same(a: float, b: float) -> bool:
    return abs(a - b) <= RTOL * max(abs(a), abs(b), 1e-300)


def inertia_group_causes(pair: Any) -> list[Finding]:
    """The ``compiler inertiagrouprange`` cause of a mass difference, when the file narrows the range.

    Parameters
    ----------
    pair : LoadedModel
        MuJoCo and Pinocchio loaded from the same MJCF file.

    Returns
    -------
    list of Finding
        At most one ``COMPILER`` finding (engine ``pinocchio``, the cause's; element ``compiler inertiagrouprange``):
        the geoms left out, the segments they weigh on, and their mass in MuJoCo, in Pinocchio and in MuJoCo with every
        group counted; empty when the option keeps every group or explains no difference.
    """
    try:
        spec = mujoco.MjSpec.from_file(str(pair.mujoco.path))
    except Exception:
        return []
    low, high = (int(x) for x in spec.compiler.inertiagrouprange)
    if low <= 0 and high >= mujoco.mjNGROUP - 1:
        return []
    narrow = compiled(spec)
    if narrow is None:
        return []
    as_file, seg_of = mujoco_segment_masses(narrow), segment_of_body(narrow)
    groups, bodies = np.asarray(narrow.geom_group), [narrow.body(int(b)).name for b in narrow.geom_bodyid]
    outside = [  # the geoms the file's range leaves out, with the body each is in
        (narrow.geom(g).name or f"{bodies[g]}/geom{g}", bodies[g])
        for g in range(narrow.ngeom)
        if not low <= int(groups[g]) <= high
    ]
    del narrow  # one compiled model at a time (a mesh-heavy file's weigh on the suite's memory)
    spec.compiler.inertiagrouprange = [0, mujoco.mjNGROUP - 1]
    every = compiled(spec)
    if every is None:
        return []
    all_groups = mujoco_segment_masses(every)
    del every
    pinocchio = pinocchio_segment_masses(pair)
    segments = [
        s
        for s, m in as_file.items()
        if s in pinocchio and not _same(m, pinocchio[s]) and _same(all_groups.get(s, m), pinocchio[s])
    ]
    if not segments:
        return []
    left_out = [name for name, body in outside if seg_of.get(body) in segments]
    ignores = cause(INERTIA_GROUPS).engine  # counts every geom
    return [
        Finding(
            Kind.COMPILER,
            ignores,  # the engine that departs from the file: it counts every geom (Drake does too)
            "compiler inertiagrouprange",
            f"MuJoCo counts only geoms of groups {low} to {high} (geoms {shown_names(left_out)} left out), "
            "Pinocchio counts every geom",
            values={
                "geoms": tuple(left_out),
                reference(): float(sum(as_file[s] for s in segments)),
                ignores: float(sum(pinocchio[s] for s in segments)),
                "mujoco, every group": float(sum(all_groups[s] for s in segments)),
            },
            affects_energy=True,
            root_cause=True,
            segments=tuple(segments),
            cause=INERTIA_GROUPS,
            tag="compiler",
        )
    ]
