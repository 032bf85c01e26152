"""Root causes read from both engines' loaded models: what Pinocchio's MJCF parser computed differently.

* a geom ``mass`` from a default class (explicit ``class``, a ``childclass`` or the main default) is not
  applied by Pinocchio 4.1: density × volume is used instead; the same holds for a geom ``pos`` and a joint
  ``pos`` from a default class (the geom or joint sits at the body origin);
* ``compiler settotalmass`` is not applied;
* geoms with ``contype="0" conaffinity="0"`` weigh nothing (:mod:`koenig_check.diagnosis.visual_geoms`);
* mass and inertia are not computed from a mesh;
* segments whose mass one engine sees as zero are "massless in Pinocchio" (or MuJoCo), not missing.

A per-construct cause is reported only when the engines' segments show its symptom.  File-level causes come
from :mod:`koenig_check.engines.parser_traps`; the file is read through :mod:`koenig_check.modelfile.mjcf`.
"""

from __future__ import annotations

import warnings
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from koenig_check.diagnosis.cause_effect import by_effect
from koenig_check.diagnosis.inertia_groups import inertia_group_causes
from koenig_check.diagnosis.root_frame import FrameOffset, _vec, root_frame_offset
from koenig_check.diagnosis.segment_masses import pinocchio_segment_masses
from koenig_check.diagnosis.visual_geoms import visual_geom_causes
from koenig_check.engines.canonical import segment_by_body_id, segment_of_body
from koenig_check.engines.catalogue import cause
from koenig_check.engines.parser_traps import file_causes
from koenig_check.engines.registry import label
from koenig_check.engines.specs import parity_pair, reference
from koenig_check.findings import Finding, Kind, shown_names
from koenig_check.modelfile.compiler import compiler_options, option_text
from koenig_check.modelfile.mjcf import ClassValue, class_values, read_mjcf

#: The catalogued causes built here (the engine each names departs; the reference engine reads the file), and
#: (tag, attribute) of a value from a default class -> its cause.
SETTOTALMASS, MESH_MASS = "pinocchio.mjcf.settotalmass", "pinocchio.mjcf.mesh-mass"
CLASS_VALUES = {
    (t, a): f"pinocchio.mjcf.class-{t}-{a}" for t, a in (("geom", "mass"), ("geom", "pos"), ("joint", "pos"))
}

#: Lengths (m) and masses (kg) under which both engines are taken to agree, relative to the model's size.
RTOL = 1e-9


@dataclass
class _Segments:
    """Both engines' segments at ``qpos0``: mass, COM and anchor by name (Pinocchio's in MuJoCo's world)."""

    mass: dict[str, tuple[float, float]]
    com: dict[str, tuple[np.ndarray, np.ndarray]]
    pole: dict[str, tuple[np.ndarray, np.ndarray]]
    size: float


def _segments(pair: Any, offset: FrameOffset | None) -> _Segments:
    mj, pn = pair.mujoco, pair.pinocchio
    qpos0 = np.asarray(mj.model.qpos0, dtype=float)[None]
    zero = np.zeros((1, mj.model.nv))
    sa, sb = mj.segment_states(qpos0, zero), pn.segment_states(qpos0, zero)
    com_b, pole_b = sb.com[0], sb.pole[0]
    if offset is not None:
        com_b, pole_b = offset.point(com_b), offset.point(pole_b)
    b_index = {n: k for k, n in enumerate(sb.names)}
    pin_mass = pinocchio_segment_masses(pair)
    mass, com, pole = {}, {}, {}
    for k, n in enumerate(sa.names):
        mass[n] = (float(sa.mass[k]), pin_mass.get(n, float("nan")))
        if n in b_index:
            com[n] = (sa.com[0, k], com_b[b_index[n]])
            pole[n] = (sa.pole[0, k], pole_b[b_index[n]])
    size = max(float(np.abs(sa.com[0]).max(initial=0.0)), float(np.abs(sa.pole[0]).max(initial=0.0)), 1.0)
    return _Segments(mass, com, pole, size)


def massless_causes(pair: Any, explained: AbstractSet[str] = frozenset()) -> list[Finding]:
    """Segments with mass in one engine and none in the other ("massless in Pinocchio").

    Parameters
    ----------
    pair : LoadedModel
    explained : set of str
        Segments whose missing mass another cause already explains: a finding only on such segments is not a root
        cause (the segments stay massless, not missing).

    Returns
    -------
    list of Finding
    """
    mj_mass = dict(
        zip(
            pair.mujoco.segment_names,
            pair.mujoco.segment_states(
                np.asarray(pair.mujoco.model.qpos0, dtype=float)[None], np.zeros((1, pair.mujoco.model.nv))
            ).mass,
            strict=True,
        )
    )
    pin_mass = pinocchio_segment_masses(pair)
    out = []
    first, second = parity_pair()  # the reference (MuJoCo) and the other (Pinocchio), as pair.mujoco, pair.pinocchio
    for engine, other, have, lack in ((second, first, mj_mass, pin_mass), (first, second, pin_mass, mj_mass)):
        if engine == first:
            lack = {n: 0.0 for n in _mujoco_massless(pair)}
        names = sorted(n for n, m in have.items() if m > 0 and n in lack and lack[n] <= 0)
        if not names:
            continue
        values: dict[str, Any] = {"segments": tuple(names)}
        values[other] = float(sum(have[n] for n in names))
        values[engine] = 0.0
        out.append(
            Finding(
                Kind.SEGMENTS,
                engine,
                f"segment {shown_names(names)}",
                f"massless in {label(engine)} (mass only in the other engine)",
                values=values,
                affects_energy=True,
                root_cause=not set(names) <= explained,
                segments=tuple(names),
                brief=f"massless in {label(engine)}",
                tag="segment",
            )
        )
    return out


def _mujoco_massless(pair: Any) -> list[str]:
    """MuJoCo segments (joint-keyed) whose lumped mass is zero."""
    m = pair.mujoco.model
    total: dict[str, float] = {}
    for b, s in enumerate(segment_by_body_id(m)):
        if s:
            total[s] = total.get(s, 0.0) + float(m.body_mass[b])
    return [s for s, mass in total.items() if mass <= 0]


def class_value_causes(pair: Any, offset: FrameOffset | None = None) -> list[Finding]:
    """Geom masses, geom positions and joint positions from default classes that Pinocchio did not apply.

    A candidate from the file is reported only when its segment shows the symptom in the engines
    (mass for a geom mass, COM for a geom position, anchor for a joint position).

    Parameters
    ----------
    pair : LoadedModel
    offset : FrameOffset, optional
        A dropped root pose to remove before comparing positions.

    Returns
    -------
    list of Finding
        One finding per (attribute, default class), naming its elements.
    """
    path = Path(str(pair.mujoco.path))
    root = read_mjcf(path)
    if root is None:
        return []
    candidates = class_values(root)
    if not candidates:
        return []
    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except Exception:  # MuJoCo loaded the file through our loader; a raw re-read may need its fixes
        return []
    mj_model = pair.mujoco.model
    seg_of = segment_of_body(mj_model)
    segs = _segments(pair, offset)
    tol_len = RTOL * segs.size
    groups: dict[tuple[str, str, str], list[tuple[ClassValue, Any, str]]] = {}
    for cand in candidates:
        element = _spec_element(spec, cand)
        segment = seg_of.get(cand.body, "")
        if element is None or not segment:
            continue
        if cand.tag == "geom" and cand.attr == "mass":
            shows = _mass_differs(segs, segment)
        elif cand.tag == "geom":
            pair_com = segs.com.get(segment)
            shows = pair_com is not None and float(np.linalg.norm(pair_com[0] - pair_com[1])) > tol_len
        else:
            pair_pole = segs.pole.get(segment)
            shows = pair_pole is not None and float(np.linalg.norm(pair_pole[0] - pair_pole[1])) > tol_len
        if shows:
            groups.setdefault((cand.tag, cand.attr, cand.cls), []).append((cand, element, segment))
    out = []
    for (tag, attr, cls), members in groups.items():
        cause_id = CLASS_VALUES[tag, "mass" if attr == "mass" else "pos"]
        names = [c.name for c, _, _ in members]
        segments = tuple(dict.fromkeys(s for _, _, s in members))
        if attr == "mass":
            try:
                masses = _mass_values(spec, [e for _, e, _ in members])
            except ValueError:  # the raw file does not compile without the loader's fixes (meshes)
                masses = {  # the engines' own masses of the segments concerned instead
                    f"{engine} mass of segments": float(sum(segs.mass.get(s, (0.0, 0.0))[k] for s in segments))
                    for k, engine in enumerate(parity_pair())
                }
            values = {"class": cls, "geoms": tuple(names), **masses}
            summary = f"geom mass from default class '{cls}' not applied by Pinocchio; density × volume used"
            kind = Kind.MASS
        else:
            pos = list(dict.fromkeys(_vec(np.array(e.pos, dtype=float)) for _, e, _ in members))
            values = {"class": cls, f"{tag}s": tuple(names), reference(): pos[0] if len(pos) == 1 else tuple(pos)}
            values[cause(cause_id).engine] = (0.0, 0.0, 0.0)
            summary = f"{tag} pos from default class '{cls}' not applied by Pinocchio; {tag} placed at the body origin"
            kind = Kind.ANCHOR if tag == "joint" else Kind.COM
        out.append(
            Finding(
                kind,
                cause(cause_id).engine,
                f"{tag} {shown_names(names)}",
                summary,
                values=values,
                affects_energy=True,
                root_cause=True,
                segments=segments,
                cause=cause_id,
                tag=tag,
            )
        )
    return out


def _mass_differs(segs: _Segments, segment: str) -> bool:
    m_a, m_b = segs.mass.get(segment, (0.0, 0.0))
    return abs(m_a - m_b) > RTOL * max(abs(m_a), abs(m_b), 1e-300)


def _spec_element(spec: mujoco.MjSpec, cand: ClassValue) -> Any:
    """The MjSpec geom or joint of a file element (by name, else by body and position)."""
    if cand.named:
        return spec.geom(cand.name) if cand.tag == "geom" else spec.joint(cand.name)
    body = spec.body(cand.body)
    if body is None:
        return None
    items = list(body.geoms if cand.tag == "geom" else body.joints)
    return items[cand.index] if cand.index < len(items) else None


def _mass_values(spec: mujoco.MjSpec, geoms: list[Any]) -> dict[str, float]:
    """MuJoCo's mass of these geoms and MuJoCo's density × volume for them (what Pinocchio uses)."""
    saved = [g.mass for g in geoms]
    given = float(sum(saved))
    try:
        with warnings.catch_warnings():  # the compiler's warnings are the loader's findings already
            warnings.simplefilter("ignore")
            base = float(spec.compile().body_mass.sum())  # each compiled model let go once read (mesh-heavy files)
            for g in geoms:
                g.mass = float("nan")  # unset: MuJoCo computes density × volume
            unset = float(spec.compile().body_mass.sum())
    finally:
        for g, m in zip(geoms, saved, strict=True):
            g.mass = m
    return {
        reference(): given,
        cause(CLASS_VALUES["geom", "mass"]).engine: given + unset - base,
    }


def compiler_causes(pair: Any) -> list[Finding]:
    """Compiler options MuJoCo applies and Pinocchio's MJCF parser does not (``settotalmass``).

    Read from :func:`koenig_check.modelfile.compiler.compiler_options` (the one reading of the file's compiler
    options, which import parity's notes share); reported when the engines' total masses differ and MuJoCo's
    equals the option's value.

    Parameters
    ----------
    pair : LoadedModel

    Returns
    -------
    list of Finding
    """
    out = []
    for option in compiler_options(Path(str(pair.mujoco.path))):
        if "settotalmass" not in option.values:
            continue
        m_mj = float(np.asarray(pair.mujoco.model.body_mass).sum())
        m_pin = float(sum(Y.mass for Y in pair.pinocchio.model.inertias))
        scale = max(m_mj, m_pin, 1e-300)
        if abs(m_mj - option.values["settotalmass"]) <= RTOL * scale and abs(m_mj - m_pin) > RTOL * scale:
            out.append(
                replace(  # the option's record, blamed on the engine that ignores it (the cause's)
                    option,
                    engine=cause(SETTOTALMASS).engine,
                    summary=f"{option_text(option)}: {option.summary}, Pinocchio does not",
                    values={reference(): m_mj, cause(SETTOTALMASS).engine: m_pin},
                    root_cause=True,
                    segments=tuple(pair.mujoco.segment_names),
                    hint="",
                    cause=SETTOTALMASS,
                )
            )
    return out


def mesh_causes(pair: Any, explained: AbstractSet[str] = frozenset()) -> list[Finding]:
    """Geoms with a mesh in segments whose mass differs between the engines.

    Pinocchio 4.1's MJCF parser does not compute mass and inertia from a mesh: verified, a geom of type
    ``mesh`` counts as 1 kg with a unit inertia whatever its ``mass``, and a primitive fitted to a mesh (a
    geom with ``mesh`` but no mesh type) as nothing.

    Parameters
    ----------
    pair : LoadedModel
    explained : set of str
        Segments whose mass difference another cause already explains.

    Returns
    -------
    list of Finding
    """
    try:
        spec = mujoco.MjSpec.from_file(str(pair.mujoco.path))
    except Exception:
        return []
    seg_of = segment_of_body(pair.mujoco.model)
    segs = _segments(pair, None)
    geoms: list[str] = []
    visual: list[str] = []
    segments: list[str] = []
    for body in spec.bodies:
        segment = seg_of.get(body.name, "")
        if not segment or segment in explained or not _mass_differs(segs, segment):
            continue
        meshed = [g.name or f"{body.name}/geom{k}" for k, g in enumerate(body.geoms) if g.meshname]
        visual += [
            g.name or f"{body.name}/geom{k}"
            for k, g in enumerate(body.geoms)
            if g.meshname and int(g.contype) == 0 and int(g.conaffinity) == 0
        ]
        if meshed:
            geoms += meshed
            segments.append(segment)
    if not geoms:
        return []
    segments = list(dict.fromkeys(segments))
    geoms = [g for g in geoms if g not in visual] + visual  # those Pinocchio weighs (1 kg each) first
    weighs = cause(MESH_MASS).engine
    also = f"; {shown_names(visual)}: contype=0 and conaffinity=0, read as visual only, count as nothing" * bool(visual)
    return [
        Finding(
            Kind.MASS,
            weighs,
            f"geom {shown_names(geoms)}",
            "geoms with a mesh: Pinocchio's MJCF parser does not compute mass and inertia from the mesh "
            f"(a mesh-typed geom counts as 1 kg with unit inertia, a primitive fitted to a mesh as nothing{also})",
            values={
                "geoms": tuple(geoms),
                "visual geoms": tuple(visual),
                reference(): float(sum(segs.mass[s][0] for s in segments)),
                weighs: float(sum(segs.mass[s][1] for s in segments)),
            },
            affects_energy=True,
            root_cause=True,
            segments=tuple(segments),
            cause=MESH_MASS,
            tag="geom",
        )
    ]


def model_causes(pair: Any) -> tuple[list[Finding], FrameOffset | None]:
    """Every root cause of an MJCF model loaded in both engines, and the dropped root pose if any.

    Parameters
    ----------
    pair : LoadedModel

    Returns
    -------
    causes : list of Finding
        Root causes, those that change the energy first.
    offset : FrameOffset or None
        ``world_mujoco <- world_pinocchio`` when Pinocchio dropped a root body's pose.
    """
    mj_path, pin_path = Path(str(pair.mujoco.path)), Path(str(pair.pinocchio.path))
    if mj_path != pin_path or read_mjcf(mj_path) is None:
        return [], None
    causes = file_causes(mj_path, pair.mujoco.model)
    offset, frame = root_frame_offset(pair)
    causes += compiler_causes(pair)
    causes += inertia_group_causes(pair)
    causes += class_value_causes(pair, offset)
    visual = visual_geom_causes(pair)
    causes += visual
    causes += mesh_causes(pair)
    causes += massless_causes(pair, explained={s for c in visual for s in c.segments})
    if frame is not None:
        causes.append(frame)
    return by_effect(sorted(causes, key=lambda f: not f.affects_energy)), offset  # the largest effect first
