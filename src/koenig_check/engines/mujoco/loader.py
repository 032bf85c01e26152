"""Build a MuJoCo ``MjModel`` from an MJCF or URDF file through ``MjSpec``.

What this module changes in the spec, and records as findings (:class:`~koenig_check.findings.Finding`):

* URDF: ``compiler.inertiafromgeom`` is set to *false*.  The importer's default (*auto*) gives a
  link without ``<inertial>`` a mass computed from its collision geometry, whereas Pinocchio gives
  it none; links with an ``<inertial>`` keep it either way.
* Mesh files: ``package://`` and ``file://`` URIs are resolved to absolute paths.  A mesh that is
  missing, that MuJoCo has no decoder for (``.dae``) or that MuJoCo refuses to compile (ASCII STL,
  degenerate volume) is dropped together with its geoms: the model loads inertia-only for those
  geoms.  A mesh that gives its body mass and inertia (MJCF, inertia from geoms) is not dropped: a
  :class:`ModelLoadError` names the file, the geom and the body.
* ``floating=True`` adds a free joint named :data:`ROOT_JOINT_NAME` to the single top-level body.
* Inertia rejected by MuJoCo raises :class:`InertiaError` naming the link and its principal
  moments, unless ``balance_inertia=True`` (MuJoCo's ``compiler.balanceinertia``), in which case the
  findings record by how much each offending link's principal moments were changed.
* Static bodies that the compiler fused into their parent (``compiler.fusestatic``, on by default
  for URDF) are listed.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.catalogue import cause
from koenig_check.engines.errors import InertiaError, ModelLoadError, NotFloatableError
from koenig_check.engines.mujoco.compiling import (
    MAX_REPAIR_TRIES,
    REPAIR_HINT,
    captured_warnings,
    compile_spec,
    mujoco_reason,
)
from koenig_check.engines.mujoco.mass_changes import BodyFinding, altered_by_compiler, balance_findings
from koenig_check.engines.mujoco.meshes import fix_meshes
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.urdf_links import undeclared_links
from koenig_check.segments import principal_moments
from koenig_check.sources.catalogue import ModelSource

__all__ = ["MAX_REPAIR_TRIES", "REPAIR_HINT", "ROOT_JOINT_NAME", "BodyFinding", "load_mujoco", "root_free_joint"]

#: The catalogued cause of a compiler settotalmass (MuJoCo applies it as the file asks; Pinocchio departs).
SETTOTALMASS = "pinocchio.mjcf.settotalmass"
#: Name given to the free joint added for a floating base, in both engines (Pinocchio's default).
ROOT_JOINT_NAME = "root_joint"


def _spec_inertia(body: mujoco.MjsBody) -> np.ndarray:
    """Return the inertia tensor a spec body declares, in its inertial frame."""
    full = np.asarray(body.fullinertia, dtype=float)
    if not np.isnan(full[0]):
        xx, yy, zz, xy, xz, yz = full
        return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    return np.diag(np.asarray(body.inertia, dtype=float))


def _prepend_free_joint_to_keys(spec: mujoco.MjSpec, top: mujoco.MjsBody) -> None:
    """Give each keyframe the coordinates of the free joint about to be added on the top body.

    MuJoCo does not shift a keyframe written for the fixed base when a free joint is added in
    front of the tree: the keyframe's first values would become the base's position.  The body's
    own pose (``pos``, ``quat``) and a zero twist are put in front instead.
    """
    pose = [*np.asarray(top.pos, dtype=float), *np.asarray(top.quat, dtype=float)]
    for key in spec.keys:
        if len(key.qpos):
            key.qpos = pose + list(key.qpos)
        if len(key.qvel):
            key.qvel = [0.0] * 6 + list(key.qvel)


def load_mujoco(
    source: ModelSource, floating: bool = False, balance_inertia: bool = False, repair_inertia: bool = False
) -> tuple[mujoco.MjModel, list[Finding], list[BodyFinding]]:
    """Compile a model file into MuJoCo.

    Parameters
    ----------
    source : ModelSource
        The file and the directories its ``package://`` URIs refer to.
    floating : bool
        Add a free joint named :data:`ROOT_JOINT_NAME` on the single top-level body (unless that
        body already has one).
    balance_inertia : bool
        Load inertias violating ``A + B >= C`` with MuJoCo's ``balanceinertia``.
    repair_inertia : bool
        Change each body whose mass or inertia MuJoCo refuses by the smallest amount MuJoCo accepts
        (:mod:`koenig_check.engines.mujoco.inertia_repair`); a ``REPAIR`` finding per body says by how much.

    Returns
    -------
    model : mujoco.MjModel
    findings : list of Finding
        What was changed or noticed while loading that concerns no body in particular.
    body_findings : list of (str, Finding)
        ``(body, finding)``: a compiled body whose mass properties MuJoCo changed with respect to
        the file (so Pinocchio, which keeps the file's values, will differ there).

    Raises
    ------
    ModelLoadError, InertiaError
        With a one-line message naming the file and the element.
    """
    notes: list[Finding] = []
    with captured_warnings(notes):
        return _load(source, floating, balance_inertia, notes, repair_inertia)


def _load(
    source: ModelSource, floating: bool, balance_inertia: bool, notes: list[Finding], repair_inertia: bool = False
) -> tuple[mujoco.MjModel, list[Finding], list[BodyFinding]]:
    path = Path(source.path)
    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except ValueError as exc:
        reason = mujoco_reason(exc)
        missing = undeclared_links(path) if source.format == "urdf" else ""
        error = ModelLoadError(
            f"{path}: MuJoCo cannot parse the file: {reason}" + (f"; root cause: {missing}" * bool(missing))
        )
        if missing:  # the one-line form keeps the cause whole, MuJoCo's words first to go
            error.brief = f"{path}: MuJoCo cannot parse the file ({reason}); root cause: {missing}"
        raise error from exc
    what = "link" if source.format == "urdf" else "body"
    if source.format == "urdf":
        spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
        without = [b.name for b in spec.bodies if b.name != "world" and not b.explicitinertial]
        if without:
            notes.append(
                Finding(
                    Kind.LOAD,
                    "mujoco",
                    "links without <inertial>",
                    "no mass (inertiafromgeom=false; MuJoCo's default would derive one from collision geometry, "
                    "Pinocchio gives none)",
                    {"links": without},
                )
            )
    elif spec.compiler.inertiafromgeom == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE:
        notes.append(
            Finding(
                Kind.COMPILER,
                "mujoco",
                "compiler inertiafromgeom",
                "inertiafromgeom=true: every body's inertia comes from its geoms",
                tag="compiler",
            )
        )
    file_inertia = {
        b.name: (float(b.mass), _spec_inertia(b)) for b in spec.bodies if b.name != "world" and b.explicitinertial
    }
    for name, (mass, inertia) in file_inertia.items():
        if not (np.isfinite(mass) and np.all(np.isfinite(inertia))):
            entries = " ".join(f"{inertia[i, j]:g}" for i, j in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)))
            value = f"mass {mass:g} kg" if not np.isfinite(mass) else f"inertia (ixx iyy izz ixy ixz iyz) {entries}"
            raise InertiaError(f"{path}: {what} {name!r}: {value} is not finite (NaN or inf) in the file")
        if mass < 0:
            raise InertiaError(f"{path}: {what} {name!r}: mass {mass:g} kg is negative")
    fix_meshes(spec, source, notes)
    if floating:
        tops = list(spec.worldbody.bodies)
        joints = list(tops[0].joints) if len(tops) == 1 else []
        already = len(joints) == 1 and joints[0].type == mujoco.mjtJoint.mjJNT_FREE
        if len(tops) != 1 or (joints and not already):
            raise NotFloatableError(
                f"{path}: --floating (floating=True): {_not_floatable(tops, what)}", [b.name for b in tops]
            )
        if already:
            notes.append(
                Finding(
                    Kind.LOAD, "mujoco", f"{what} {tops[0].name}", "floating=True: already has a free joint, none added"
                )
            )
        else:
            _prepend_free_joint_to_keys(spec, tops[0])
            tops[0].add_freejoint(name=ROOT_JOINT_NAME)
    spec.compiler.balanceinertia = bool(balance_inertia)
    names_before = [b.name for b in spec.bodies]
    parent_of = {b.name: (b.parent.name if b.parent is not None else "") for b in spec.bodies}
    spec_before = spec.copy() if balance_inertia else None
    model, refused, repaired = compile_spec(spec, source, notes, file_inertia, repair=repair_inertia)
    fused = [n for n in names_before if n and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n) < 0]
    if fused:
        notes.append(
            Finding(
                Kind.LOAD,
                "mujoco",
                f"{what}s {', '.join(fused[:5])}" + (" …" if len(fused) > 5 else ""),
                f"fusestatic fused {len(fused)} static {what}(s) into their parents",
                {"fused": fused},
            )
        )

    def survivor(name: str) -> str:
        while name and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name) < 0:
            name = parent_of.get(name, "")
        return name or "world"

    diffs: list[BodyFinding] = []
    ghost = [n for n in fused if n in file_inertia and file_inertia[n][0] == 0 and np.any(file_inertia[n][1])]
    for n in ghost:
        moments = principal_moments(file_inertia[n][1])
        diffs.append(
            (
                survivor(n),
                Finding(
                    Kind.COMPILER,
                    "mujoco",
                    f"{what} {n}",
                    "fusestatic dropped the rotational inertia of this massless link (mass 0, inertia non-zero); "
                    "Pinocchio keeps it",
                    {"principal moments in the file": moments.round(12).tolist()},
                    affects_energy=True,
                    root_cause=True,
                    cause="mujoco.any.fusestatic-massless-inertia",
                    tag=what,
                ),
            )
        )
    changed: list[str] = [n for n, _ in repaired]
    diffs += [(survivor(n), f) for n, f in repaired]
    if spec_before is not None:  # bodies repaired are the repair's findings, and carry its values here too
        for name in changed:
            if spec_before.body(name) is not None:
                _copy_inertial(spec.body(name), spec_before.body(name))
        unrepaired = {n: v for n, v in file_inertia.items() if n not in changed}
        balanced = balance_findings(spec_before, refused, model, source, unrepaired)
        changed += [n for n, _ in balanced]
        diffs += [(survivor(n), f) for n, f in balanced]
    hosts = {survivor(parent_of.get(n, "")) for n in fused}
    altered = [
        n for n in altered_by_compiler(model, file_inertia) if n not in changed and n not in hosts and n != "world"
    ]
    options = {k: getattr(spec.compiler, k) for k in ("settotalmass", "boundmass", "boundinertia")}
    # settotalmass rescales every body: Pinocchio's MJCF parser keeps the file's values.  Without it, what
    # altered an explicit inertial is boundmass / boundinertia, which Pinocchio 4's parser applies as well
    # (the same masses and moments as MuJoCo's): a change from the file, not a difference between engines.
    rescaled = options["settotalmass"] > 0
    # the engine that departs from the file is the cause's (it ignores the option); a bound MuJoCo applied is
    # MuJoCo's own change, no difference between engines
    concerned = cause(SETTOTALMASS).engine if rescaled else "mujoco"
    for n in altered:
        bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n)
        summary = (
            "MuJoCo's compiler altered the mass or inertia; Pinocchio keeps the file's values"
            if rescaled
            else "MuJoCo's compiler raised the mass or inertia to its bound (boundmass, boundinertia); "
            "Pinocchio's MJCF parser applies the same bounds"
        )
        diffs.append(
            (
                n,
                Finding(
                    Kind.COMPILER,
                    concerned,
                    f"{what} {n}",
                    summary,
                    {"mass in the file": file_inertia[n][0], "mass compiled": float(model.body_mass[bid]), **options},
                    affects_energy=rescaled,
                    root_cause=rescaled,
                    cause=SETTOTALMASS if rescaled else "",
                    tag=what,
                ),
            )
        )
    return model, notes, diffs


def _copy_inertial(source: mujoco.MjsBody, target: mujoco.MjsBody) -> None:
    """Give ``target`` the inertial of ``source`` (what :func:`repair_body` changes)."""
    target.explicitinertial = source.explicitinertial
    target.ipos = list(source.ipos)
    target.mass = float(source.mass)
    target.inertia = list(source.inertia)
    target.fullinertia = list(source.fullinertia)


def _not_floatable(tops: list[mujoco.MjsBody], what: str) -> str:
    """Why ``floating`` cannot add a free joint: the root already moves, or there is no single root."""
    if len(tops) == 1:
        joints = [j.name or str(j.type).split("_")[-1].lower() for j in tops[0].joints]
        return (
            f"the top-level {what} {tops[0].name!r} already has joints ({', '.join(joints)}): "
            "it moves without --floating"
        )
    if not tops:
        return f"a free joint goes on the top-level {what}, the robot's root; the file has none"
    names = ", ".join(repr(b.name) for b in tops[:3]) + (f" (+{len(tops) - 3} more)" if len(tops) > 3 else "")
    return f"a free joint goes on the one top-level {what}, the robot's root; the file has {len(tops)}: {names}"


def root_free_joint(model: mujoco.MjModel) -> str | None:
    """Return the name of the free joint of the model's single top-level body, or ``None``.

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    str or None
    """
    tops = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    if len(tops) != 1 or model.body_jntnum[tops[0]] != 1:
        return None
    j = int(model.body_jntadr[tops[0]])
    if model.jnt_type[j] != mujoco.mjtJoint.mjJNT_FREE:
        return None
    return model.joint(j).name or f"{model.body(tops[0]).name}_free"
