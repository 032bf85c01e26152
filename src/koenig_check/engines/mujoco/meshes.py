"""Meshes MuJoCo cannot read (a missing file, a format it has no decoder for): dropped with their geoms, said so.

A mesh that gives a body its mass (a geom of a body whose inertia MuJoCo derives from its geoms) is never
dropped: the model would be another robot, and MuJoCo would then refuse the body as massless.  It is a
:class:`~koenig_check.engines.errors.ModelLoadError` naming the file, the geom and the body.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import mujoco

from koenig_check.engines.errors import ModelLoadError
from koenig_check.findings import Finding, Kind
from koenig_check.sources.catalogue import ModelSource
from koenig_check.sources.uris import resolve_uri

#: The value of an inertia-only finding listing the mesh files dropped (what identifies the finding).
DROPPED_FILES = "mesh files dropped"

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


def mass_geoms(spec: mujoco.MjSpec, mesh: mujoco.MjsMesh) -> list[tuple[str, str]]:
    """The geoms using a mesh that give their body mass and inertia (MuJoCo's ``inertiafromgeom``).

    Parameters
    ----------
    spec : mujoco.MjSpec
    mesh : mujoco.MjsMesh

    Returns
    -------
    list of (str, str)
        ``(geom, body)`` per such geom; an unnamed geom is ``""``.
    """
    derive = spec.compiler.inertiafromgeom
    if derive == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE:
        return []
    low, high = (int(g) for g in spec.compiler.inertiagrouprange)
    out = []
    for geom in spec.geoms:
        body = geom.parent
        if geom.meshname != mesh.name or body is None or not low <= geom.group <= high:
            continue
        if derive == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE or not body.explicitinertial:
            out.append((geom.name, body.name))
    return out


def mass_mesh_error(path: Path, mesh: mujoco.MjsMesh, reason: str, geoms: list[tuple[str, str]]) -> ModelLoadError:
    """The one-line error of a mesh MuJoCo cannot read that gives a body its mass.

    Parameters
    ----------
    path : Path
        The model file.
    mesh : mujoco.MjsMesh
    reason : str
        Why it cannot be read (``"not found"``, MuJoCo's own message).
    geoms : list of (str, str)
        :func:`mass_geoms` of the mesh (not empty).

    Returns
    -------
    ModelLoadError
    """
    geom, body = geoms[0]
    owner = f"body {body!r}" if body else "an unnamed body"
    named = f"geom {geom!r}" if geom else f"a geom of mesh {mesh.name!r}"
    more = f" (+{len(geoms) - 1} more geom(s))" if len(geoms) > 1 else ""
    file = Path(mesh.file)
    if file.is_absolute() and file.is_relative_to(Path(path).parent):  # as written, beside the model
        file = file.relative_to(Path(path).parent)
    return ModelLoadError(
        f"{path}: mesh file '{file}' {reason}; {named} of {owner}{more} takes its mass and inertia from it"
    )


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
        geoms = mass_geoms(spec, mesh)
        if geoms:
            said = "not found" if resolved is None else f"cannot be read ({reason})"
            raise mass_mesh_error(source.path, mesh, said, geoms)
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
        {DROPPED_FILES: files, "bodies without <inertial>": from_geoms},
        affects_energy=bool(from_geoms),
    )


def dropped_meshes_line(findings: Sequence[Finding], shown: int = 2) -> str:
    """The mesh files dropped with their geoms, in a few words for the verdict table's row (empty when none).

    Parameters
    ----------
    findings : sequence of Finding
    shown : int
        At most this many files are named (the count of the others is given).

    Returns
    -------
    str
    """
    files = [str(f) for x in findings if x.kind is Kind.LOAD for f in x.values.get(DROPPED_FILES, ())]
    if not files:
        return ""
    names = ", ".join(Path(f).name for f in files[:shown])
    names += f" (+{len(files) - shown} more)" if len(files) > shown else ""
    return f"note: {len(files)} unreadable mesh file(s) dropped with their geoms, no mass from them: {names}"
