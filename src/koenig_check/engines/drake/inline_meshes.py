"""Meshes given by their vertices in an MJCF file (no ``file=``), which Drake's MJCF parser ignores with their geoms.

Drake 1.51 warns that the ``vertex`` attribute is unsupported, that the mesh asset without a file will be ignored,
and that each geom using it "specified unknown mesh ... and will be ignored": the body is built without those
geoms' mass.  Read from the file as MuJoCo parses it (:class:`mujoco.MjSpec`), never from Drake's warnings: the
catalogued cause ``drake.mjcf.inline-mesh``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from koenig_check.engines.canonical import segment_of_body
from koenig_check.engines.drake.ignored_geoms import geom_mass
from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind, shown_names

#: The catalogued cause (declared in :mod:`koenig_check.engines.drake.causes`).
INLINE_MESH = "drake.mjcf.inline-mesh"


def inline_mesh_causes(path: Path, mj_model: Any) -> list[Finding]:
    """The geoms that use a mesh given by its vertices in the file: one root cause naming them, when they weigh.

    Parameters
    ----------
    path : Path
        The MJCF file.
    mj_model : mujoco.MjModel
        MuJoCo's compiled model (which segment each body moves with).

    Returns
    -------
    list of Finding
        At most one ``IGNORED_CONSTRUCT`` finding (engine ``drake``): the geoms, their meshes, and their mass in
        MuJoCo (what Drake's bodies lack; "not known" where removing a geom leaves MuJoCo a massless body), a root
        cause when they move and weigh (or their mass is not known).
    """
    import mujoco

    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except Exception:  # MuJoCo refuses the raw file (the loader's repairs): said by the loader
        return []
    inline = {m.name for m in spec.meshes if not m.file and len(m.uservert)}
    if not inline:
        return []
    seg_of = segment_of_body(mj_model)
    geoms, meshes, segments, masses = [], [], [], []
    for body in spec.bodies:
        for k, g in enumerate(body.geoms):
            if g.meshname not in inline:
                continue
            masses.append(geom_mass(path, g.name) if g.name else None)  # None: not known (a body left massless)
            geoms.append(g.name or f"{body.name}/geom{k}")
            meshes.append(g.meshname)
            if seg_of.get(body.name):
                segments.append(seg_of[body.name])
    if not geoms:
        return []
    known = None if None in masses else float(sum(m for m in masses if m is not None))
    moving = bool(segments) and known != 0.0  # a geom whose mass is not known is taken to weigh
    return [
        Finding(
            Kind.IGNORED_CONSTRUCT,
            "drake",
            f"geom {shown_names(geoms)}",
            "mesh given by its vertices in the file: Drake's MJCF parser ignores the mesh and the geoms that use it",
            {
                "geoms": tuple(geoms),
                "meshes": tuple(dict.fromkeys(meshes)),
                reference(): "not known" if known is None else known,
                "drake": 0.0,
            },
            affects_energy=moving,
            root_cause=moving,
            segments=tuple(dict.fromkeys(segments)),
            cause=INLINE_MESH,
            tag="geom",
        )
    ]
