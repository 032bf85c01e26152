"""Meshes MuJoCo cannot read (a missing file, a format it has no decoder for): dropped with their geoms, said so."""

from __future__ import annotations

from pathlib import Path

import mujoco

from koenig_check.findings import Finding, Kind
from koenig_check.sources.catalogue import ModelSource
from koenig_check.sources.uris import resolve_uri

#: Mesh formats MuJoCo has no decoder for (the geoms using them are dropped: inertia-only).
UNDECODABLE_MESH_SUFFIXES = frozenset({".dae"})


def drop_mesh(spec: mujoco.MjSpec, mesh: mujoco.MjsMesh) -> list[str]:
    """Delete a mesh and the geoms using it; return the names of the bodies that lost a geom."""
    bodies = []
    for geom in list(spec.geoms):
        if geom.meshname == mesh.name:
            parent = geom.parent
            bodies.append(parent.name if parent is not None else "")
            spec.delete(geom)
    spec.delete(mesh)
    return bodies


def fix_meshes(spec: mujoco.MjSpec, source: ModelSource, notes: list[Finding]) -> None:
    """Point every mesh at its file; drop (with a finding) those MuJoCo cannot read."""
    meshdir = spec.compiler.meshdir or spec.meshdir or ""
    base = source.path.parent / meshdir
    dropped: dict[str, list[str]] = {}
    losers: dict[str, list[str]] = {}
    rewritten = False
    for mesh in list(spec.meshes):
        if not mesh.file:
            continue
        resolved = resolve_uri(mesh.file, base, source.package_dirs)
        if resolved is None:
            reason = "missing file"
        elif resolved.suffix.lower() in UNDECODABLE_MESH_SUFFIXES:
            reason = f"no MuJoCo decoder for {resolved.suffix}"
        else:
            if str(resolved) != mesh.file:
                mesh.file = str(resolved)
                rewritten = True
            continue
        dropped.setdefault(reason, []).append(mesh.file)
        losers.setdefault(reason, []).extend(drop_mesh(spec, mesh))
    if rewritten:
        spec.strippath = False
    for reason, names in dropped.items():
        notes.append(inertia_only(spec, reason, names, losers[reason]))


def inertia_only(spec: mujoco.MjSpec, reason: str, files: list[str], bodies: list[str]) -> Finding:
    """A LOAD finding for meshes dropped with their geoms; it changes the energy where a body has no <inertial>."""
    explicit = {b.name: bool(b.explicitinertial) for b in spec.bodies}
    from_geoms = sorted({b for b in bodies if not explicit.get(b, True)})
    return Finding(
        Kind.LOAD,
        "mujoco",
        "mesh " + ", ".join(Path(f).name for f in files[:5]) + (f" (+{len(files) - 5})" if len(files) > 5 else ""),
        f"inertia-only: {len(files)} mesh file(s) dropped with their geoms ({reason})",
        {"files": files, "bodies without <inertial>": from_geoms},
        affects_energy=bool(from_geoms),
    )
