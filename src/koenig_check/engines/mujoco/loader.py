"""Build a MuJoCo ``MjModel`` from an MJCF or URDF file through ``MjSpec``.

What this module changes in the spec, and records as findings (:class:`~koenig_check.findings.Finding`):

* URDF: ``compiler.inertiafromgeom`` is set to *false*.  The importer's default (*auto*) gives a
  link without ``<inertial>`` a mass computed from its collision geometry, whereas Pinocchio gives
  it none; links with an ``<inertial>`` keep it either way.
* Mesh files: ``package://`` and ``file://`` URIs are resolved to absolute paths.  A mesh that is
  missing, that MuJoCo has no decoder for (``.dae``) or that MuJoCo refuses to compile (ASCII STL,
  degenerate volume) is dropped together with its geoms: the model loads inertia-only for those
  geoms.  A mesh never makes a model fail.
* ``floating=True`` adds a free joint named :data:`ROOT_JOINT_NAME` to the single top-level body.
* Inertia rejected by MuJoCo raises :class:`InertiaError` naming the link and its principal
  moments, unless ``balance_inertia=True`` (MuJoCo's ``compiler.balanceinertia``), in which case the
  findings record by how much each offending link's principal moments were changed.
* Static bodies that the compiler fused into their parent (``compiler.fusestatic``, on by default
  for URDF) are listed.
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.errors import InertiaError, ModelLoadError
from koenig_check.engines.mujoco.inertia_repair import Repair, repair_body
from koenig_check.engines.mujoco.meshes import drop_mesh, fix_meshes, inertia_only
from koenig_check.findings import Finding, Kind
from koenig_check.segments import check_physical_inertia
from koenig_check.sources.catalogue import ModelSource

#: Name given to the free joint added for a floating base, in both engines (Pinocchio's default).
ROOT_JOINT_NAME = "root_joint"
#: Mesh formats MuJoCo 4.0 has no decoder for ("no decoder found for mesh file").
_ELEMENT = re.compile(r"Element name '([^']*)'")
#: Compilations tried per body under repair (the balance margin grows tenfold each time).
MAX_REPAIR_TRIES = 3


#: A body's mass-property change with the body it concerns (mapped to its segment by the engine adapter).
BodyFinding = tuple[str, Finding]


def _warning(message: str) -> Finding:
    return Finding(Kind.LOAD, "mujoco", "model", f"compiler warning: {message}")


@contextmanager
def _captured_warnings(notes: list[Finding]) -> Iterator[None]:
    """Route MuJoCo's warnings (printed and written to MUJOCO_LOG.TXT by default) into the findings."""
    previous = mujoco.get_mju_user_warning()
    seen: list[str] = []
    mujoco.set_mju_user_warning(seen.append)
    try:
        yield
    finally:
        mujoco.set_mju_user_warning(previous)
        notes.extend(_warning(m) for m in dict.fromkeys(seen))


def _first_line(exc: BaseException) -> str:
    """MuJoCo's message on one line: every line joined with '; ' (the element and line number are kept)."""
    text = str(exc).strip()
    if text.startswith("Error:"):
        text = text[len("Error:") :].strip()
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return "; ".join(lines) if lines else type(exc).__name__


def _spec_inertia(body: mujoco.MjsBody) -> np.ndarray:
    """Return the inertia tensor a spec body declares, in its inertial frame."""
    full = np.asarray(body.fullinertia, dtype=float)
    if not np.isnan(full[0]):
        xx, yy, zz, xy, xz, yz = full
        return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    return np.diag(np.asarray(body.inertia, dtype=float))


def _moments(inertia: np.ndarray) -> str:
    return ", ".join(f"{v:.6g}" for v in np.linalg.eigvalsh(0.5 * (inertia + inertia.T)))


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


def _inertia_error(
    source: ModelSource, element: str, message: str, file_inertia: dict[str, tuple[float, np.ndarray]]
) -> InertiaError:
    what = "link" if source.format == "urdf" else "body"
    head = f"{source.path}: {what} {element!r}: MuJoCo rejects its inertia ({message})"
    if element in file_inertia:
        mass, inertia = file_inertia[element]
        reason = check_physical_inertia(mass, inertia)
        if reason is None:
            reason = f"principal moments {_moments(inertia)}, MuJoCo requires them strictly positive"
        head += f"; {reason}"
    head += f"; {REPAIR_HINT}"
    if "A + B >= C" in message:
        head += " (or --balance-inertia, balance_inertia=True: MuJoCo's balanceinertia)"
    error = InertiaError(head)
    error.brief = (  # one line: the link, MuJoCo's reason, what loads it (the moments are in the message)
        f"{source.path}: {what} {element!r}: MuJoCo rejects its inertia ({_refusal(message)}); "
        "--repair-inertia loads it with the smallest change MuJoCo accepts"
    )
    return error


#: What a refusal says would load the file.
REPAIR_HINT = "--repair-inertia (repair_inertia=True) loads it with the smallest change MuJoCo accepts, recorded"


def _repair_finding(repair: Repair, message: str, what: str) -> Finding:
    return Finding(
        Kind.REPAIR,
        "mujoco",
        f"{what} {repair.body}",
        "mass and principal moments raised to MuJoCo's bounds and balanced (A + B >= C) so that MuJoCo accepts "
        "them; Pinocchio keeps the file's values",
        {
            "mass before": repair.mass[0],
            "mass after": repair.mass[1],
            "moments before": list(repair.moments[0]),
            "moments after": list(repair.moments[1]),
            "max moment change": repair.max_change,
            "refused for": _refusal(message),
        },
        affects_energy=True,
        root_cause=True,
    )


def _refusal(message: str) -> str:
    """MuJoCo's reason without the element and line it names (the finding names the link)."""
    return message.split("; Element name")[0].removeprefix("error ").strip()


def _compile(
    spec: mujoco.MjSpec,
    source: ModelSource,
    notes: list[Finding],
    file_inertia: dict[str, tuple[float, np.ndarray]],
    repair: bool = False,
) -> tuple[mujoco.MjModel, list[str], list[BodyFinding]]:
    """Compile, dropping meshes MuJoCo refuses one by one; raise clear errors otherwise.

    With ``repair``, a body whose mass or inertia MuJoCo refuses is repaired in ``spec``
    (:func:`~koenig_check.engines.mujoco.inertia_repair.repair_body`) and a copy compiled again (a failed
    compilation leaves the spec's static bodies fused).

    Returns the model, the names of the meshes dropped on the way and the repairs.
    """
    refused: list[str] = []
    reasons: list[str] = []
    files: list[str] = []
    losers: list[str] = []
    repairs: dict[str, tuple[Repair, str]] = {}
    tries: dict[str, int] = {}
    what = "link" if source.format == "urdf" else "body"
    while True:
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                model = (spec.copy() if repair else spec).compile()
            notes.extend(_warning(str(w.message)) for w in caught)
        except ValueError as exc:
            message = _first_line(exc)
            match = _ELEMENT.search(str(exc))
            element = match.group(1) if match else ""
            mesh = next(
                (m for m in spec.meshes if (element and m.name == element) or (m.file and m.file in str(exc))),
                None,
            )
            if mesh is not None:
                refused.append(mesh.name)
                reasons.append(message)
                files.append(mesh.file)
                losers += drop_mesh(spec, mesh)
                continue
            if "inertia" in message or "mass" in message:
                body = spec.body(element) if element else None
                if repair and body is not None and tries.get(element, 0) < MAX_REPAIR_TRIES:
                    tries[element] = tries.get(element, 0) + 1
                    done = repair_body(body, margin=8.0 * 10 ** (tries[element] - 1))
                    first = repairs.get(element)
                    if first is not None:  # a second pass: before = the file's values
                        done = Repair(
                            done.body, (first[0].mass[0], done.mass[1]), (first[0].moments[0], done.moments[1])
                        )
                    repairs[element] = (done, first[1] if first else message)
                    continue
                if "moving bodies" in message:
                    raise InertiaError(
                        f"{source.path}: {what} {element!r}: MuJoCo rejects a moving body without mass or "
                        f"inertia ({message}); Pinocchio accepts it; {REPAIR_HINT}"
                    ) from exc
                raise _inertia_error(source, element, message, file_inertia) from exc
            where = f" at element {element!r}" if element else ""
            raise ModelLoadError(f"{source.path}: MuJoCo cannot compile the model{where}: {message}") from exc
        if refused:
            notes.append(inertia_only(spec, "MuJoCo refused to compile them: " + "; ".join(reasons), files, losers))
        return model, refused, [(n, _repair_finding(r, m, what)) for n, (r, m) in repairs.items()]


def _balance_findings(
    spec_before: mujoco.MjSpec,
    refused: list[str],
    model: mujoco.MjModel,
    source: ModelSource,
    file_inertia: dict[str, tuple[float, np.ndarray]],
) -> list[BodyFinding]:
    """Per link whose inertia MuJoCo would reject: how balanceinertia changed it (a REPAIR finding)."""
    bad = {}
    for name, (mass, inertia) in file_inertia.items():
        lam = np.linalg.eigvalsh(0.5 * (inertia + inertia.T))
        if mass > 0 and (check_physical_inertia(mass, inertia) is not None or lam[0] <= 0):
            bad[name] = lam
    if not bad:
        return []
    compiled = model
    if any(mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n) < 0 for n in bad):
        spec_before.compiler.fusestatic = False
        for mesh in list(spec_before.meshes):
            if mesh.name in refused:
                drop_mesh(spec_before, mesh)
        compiled = spec_before.compile()
    what = "link" if source.format == "urdf" else "body"
    out = []
    for name, lam in bad.items():
        bid = mujoco.mj_name2id(compiled, mujoco.mjtObj.mjOBJ_BODY, name)
        new = np.sort(compiled.body_inertia[bid])
        change = np.abs(new - lam).max() / max(np.abs(lam).max(), 1e-300)
        finding = Finding(
            Kind.REPAIR,
            "mujoco",
            f"{what} {name}",
            "principal moments changed by MuJoCo's balanceinertia (A + B >= C); Pinocchio keeps the file's values",
            {
                "moments before": lam.round(12).tolist(),
                "moments after": new.round(12).tolist(),
                "max relative change": change,
            },
            affects_energy=True,
            root_cause=True,
            hint="--balance-inertia (balance_inertia=True) was asked for",
        )
        out.append((name, finding))
    return out


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
    with _captured_warnings(notes):
        return _load(source, floating, balance_inertia, notes, repair_inertia)


def _load(
    source: ModelSource, floating: bool, balance_inertia: bool, notes: list[Finding], repair_inertia: bool = False
) -> tuple[mujoco.MjModel, list[Finding], list[BodyFinding]]:
    path = Path(source.path)
    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except ValueError as exc:
        raise ModelLoadError(f"{path}: MuJoCo cannot parse the file: {_first_line(exc)}") from exc
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
            names = [b.name for b in tops]
            raise ModelLoadError(
                f"{path}: floating=True needs exactly one top-level {what} without joints, found {names}"
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
    model, refused, repaired = _compile(spec, source, notes, file_inertia, repair=repair_inertia)
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
        moments = np.linalg.eigvalsh(0.5 * (file_inertia[n][1] + file_inertia[n][1].T))
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
                ),
            )
        )
    changed: list[str] = [n for n, _ in repaired]
    diffs += [(survivor(n), f) for n, f in repaired]
    if spec_before is not None:
        balanced = _balance_findings(spec_before, refused, model, source, file_inertia)
        changed += [n for n, _ in balanced]
        diffs += [(survivor(n), f) for n, f in balanced]
    hosts = {survivor(parent_of.get(n, "")) for n in fused}
    altered = [
        n for n in _altered_by_compiler(model, file_inertia) if n not in changed and n not in hosts and n != "world"
    ]
    options = {k: getattr(spec.compiler, k) for k in ("settotalmass", "boundmass", "boundinertia")}
    for n in altered:
        bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n)
        diffs.append(
            (
                n,
                Finding(
                    Kind.COMPILER,
                    "mujoco",
                    f"{what} {n}",
                    "MuJoCo's compiler altered the mass or inertia; Pinocchio keeps the file's values",
                    {"mass in the file": file_inertia[n][0], "mass compiled": float(model.body_mass[bid]), **options},
                    affects_energy=True,
                    root_cause=True,
                ),
            )
        )
    return model, notes, diffs


def _altered_by_compiler(model: mujoco.MjModel, file_inertia: dict[str, tuple[float, np.ndarray]]) -> list[str]:
    """Bodies still present after compilation whose mass or principal moments differ from the file's."""
    out = []
    for name, (mass, inertia) in file_inertia.items():
        bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
        if bid < 0:
            continue
        moments = np.linalg.eigvalsh(0.5 * (inertia + inertia.T))
        compiled = np.sort(model.body_inertia[bid])
        scale = max(np.abs(moments).max(), 1e-300)
        if abs(model.body_mass[bid] - mass) > 1e-12 * max(mass, 1e-300) or np.abs(compiled - moments).max() > (
            1e-9 * scale
        ):
            out.append(name)
    return out


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
