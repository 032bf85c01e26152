"""Root causes: the MJCF constructs that Pinocchio's parser reads differently from MuJoCo, named once.

Each cause is one :class:`~koenig_check.findings.Finding` with ``root_cause=True``: the engine that
departs (``pinocchio``), the element (``"include arm.xml"``, ``"body base"``, ``"geom pole"``), the values
on each side, whether it changes the kinetic energy, and the segments whose symptoms it explains.

What Pinocchio 4.1's ``buildModelFromMJCF`` does, verified on small files (``tests/models/causes/``):

* ``<include>`` is ignored wherever it stands: inside a body the included subtree is silently missing;
  when the file's ``<worldbody>`` is left without a ``<body>`` of its own (Menagerie ``scene.xml``), the
  parser fails with "No such node (body)".
* only the first ``<body>`` under ``<worldbody>`` is read; the other root bodies and their joints are missing.
* the pose of a root body without a joint is dropped (the body is welded at the world origin): a
  constant world transform between the engines, which leaves every kinetic energy unchanged.
* a geom ``mass`` from a default class (explicit ``class``, a ``childclass`` or the main default) is not
  applied: density × volume is used instead.  A ``mass`` written on the geom itself is honoured.  The same
  holds for a geom ``pos`` and a joint ``pos`` from a default class (the geom or joint sits at the body
  origin).  Geom ``type``, ``size``, ``fromto``, ``density``, ``euler`` and joint ``type``, ``axis``,
  ``armature`` from classes are applied.
* segments whose mass one engine sees as zero are left out of that engine's segments: they are "massless
  in Pinocchio" (or MuJoCo), not missing.

The file's constructs come from its XML (which attribute is written on the element, which default class
applies, resolved the MuJoCo way: ``class``, else the nearest ``childclass``, else ``main``); MuJoCo's
resolved values come from :class:`mujoco.MjSpec` and the compiled model; Pinocchio's from its model.  A
per-construct cause is reported only when the engines' segments show its symptom.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Callable
from collections.abc import Set as AbstractSet
from dataclasses import dataclass
from functools import wraps
from pathlib import Path
from typing import Any, TypeVar, cast

import mujoco
import numpy as np

from koenig_check.exceptions import (
    CoupledJointsError,
    InertiaError,
    JointMismatch,
    ModelLoadError,
    NoMovingSegmentError,
)
from koenig_check.findings import Finding, Kind
from koenig_check.validate import parse_xml

#: Attributes that Pinocchio 4.1's MJCF parser ignores when they come from a default class.
CLASS_ATTRIBUTES_IGNORED = (("geom", "mass"), ("geom", "pos"), ("joint", "pos"))
#: Lengths (m) and masses (kg) under which both engines are taken to agree, relative to the model's size.
RTOL = 1e-9
#: Names listed in one element before "+N more".
_SHOWN = 4

F = TypeVar("F", bound=Callable[..., Any])


# ------------------------------------------------------------------------------------------- XML reading
def _read_mjcf(path: Path, included: bool = False) -> ET.Element | None:
    """The root ``<mujoco>`` element of a file, or ``None`` when it is not a readable MJCF file.

    An included file's top element may have any name (``<mujocoinclude>`` is common): MuJoCo drops it.
    """
    try:
        root = parse_xml(path).getroot()
    except (ET.ParseError, OSError):
        return None
    return root if included or root.tag == "mujoco" else None


_ORDINALS = ("first", "second", "third")


def body_label(body: ET.Element, roots: list[ET.Element]) -> str:
    """A body as a reader can find it: its name, or where it is and its first joint (or position).

    Parameters
    ----------
    body : xml.etree.ElementTree.Element
    roots : list of Element
        The root bodies (direct ``<body>`` children of ``<worldbody>``), in file order.

    Returns
    -------
    str
        ``"kettle"``, or e.g. ``"first root body, unnamed, with joint 'shoulder'"``.
    """
    if body.get("name"):
        return str(body.get("name"))
    index = next((i for i, b in enumerate(roots) if b is body), None)
    if index is None:
        place = "body"
    elif index < len(_ORDINALS):
        place = f"{_ORDINALS[index]} root body"
    else:
        place = f"root body {index + 1}"
    joints = [j.get("name") for j in body.findall("joint") + list(body.iter("joint")) if j.get("name")]
    if joints:
        return f"{place}, unnamed, with joint '{joints[0]}'"
    return f"{place}, unnamed, at pos '{body.get('pos', '0 0 0')}'"


def _names(items: list[str]) -> str:
    shown = ", ".join(items[:_SHOWN])
    return shown + (f" (+{len(items) - _SHOWN} more)" if len(items) > _SHOWN else "")


@dataclass(frozen=True)
class _Included:
    """What one ``<include>`` of the main file brings in."""

    file: str
    where: str  # "body <name>", "worldbody" or "mujoco" (top level)
    bodies: tuple[str, ...]
    joints: tuple[str, ...]
    defaults: bool  # it defines default classes


def _joint_names(element: ET.Element) -> list[str]:
    return [j.get("name", "?") for j in element.iter() if j.tag in ("joint", "freejoint")]


def _included(root: ET.Element, directory: Path) -> list[_Included]:
    """Every ``<include>`` of the main file with the bodies, joints and defaults it brings in."""
    out = []
    parents = {child: parent for parent in root.iter() for child in parent}
    roots = [b for w in root.findall("worldbody") for b in w.findall("body")]
    for inc in root.iter("include"):
        name = inc.get("file", "")
        parent = parents.get(inc)
        where = "mujoco" if parent is None or parent.tag == "mujoco" else parent.tag
        if parent is not None and parent.tag == "body":
            where = f"body {parent.get('name')}" if parent.get("name") else body_label(parent, roots)
        sub = _read_mjcf(directory / name, included=True)
        if sub is None:
            out.append(_Included(name, where, (), (), False))
            continue
        nested = _included(sub, directory)
        bodies = [b.get("name", "?") for b in sub.iter("body")] + [b for n in nested for b in n.bodies]
        joints = _joint_names(sub) + [j for n in nested for j in n.joints]
        defaults = sub.find("default") is not None or any(n.defaults for n in nested)
        out.append(_Included(name, where, tuple(bodies), tuple(joints), defaults))
    return out


class _Defaults:
    """MuJoCo's default classes of one file: attribute lookup up the class tree."""

    def __init__(self, root: ET.Element) -> None:
        self.parent: dict[str, str | None] = {}
        self.element: dict[str, ET.Element] = {}
        for top in root.findall("default"):
            self._add(top, "main", None)

    def _add(self, element: ET.Element, name: str, parent: str | None) -> None:
        if name not in self.element:
            self.parent[name], self.element[name] = parent, element
        for child in element.findall("default"):
            self._add(child, child.get("class", "?"), name)

    def lookup(self, cls: str, tag: str, attr: str) -> tuple[str, str] | None:
        """The class that sets ``attr`` of ``tag`` for an element of class ``cls``, and the value."""
        name: str | None = cls if cls in self.element else "main"
        while name is not None and name in self.element:
            for setter in self.element[name].findall(tag):
                if attr in setter.attrib:
                    return name, setter.attrib[attr]
            name = self.parent.get(name)
        return None


@dataclass(frozen=True)
class _ClassValue:
    """An attribute of a geom or joint that comes from a default class, not from the element."""

    tag: str
    attr: str
    cls: str
    body: str
    index: int  # position among the body's direct children of this tag
    name: str  # the element's name, or "<body>/<tag><index>"
    named: bool


def _class_values(root: ET.Element) -> list[_ClassValue]:
    """Attributes in :data:`CLASS_ATTRIBUTES_IGNORED` that the main file's elements get from a class.

    Geoms and joints of the main file's body tree only (not those inside ``<frame>`` or included files).
    The geoms of a body with its own ``<inertial>`` are left out: neither engine takes the body's mass
    properties from them (unless ``<compiler inertiafromgeom="true">``), so their class values change nothing.
    """
    defaults = _Defaults(root)
    from_geoms = any(c.get("inertiafromgeom") == "true" for c in root.iter("compiler"))
    wanted = {tag: [a for t, a in CLASS_ATTRIBUTES_IGNORED if t == tag] for tag, _ in CLASS_ATTRIBUTES_IGNORED}
    out: list[_ClassValue] = []

    def walk(body: ET.Element, childclass: str) -> None:
        own = body.get("childclass", childclass)
        counts: dict[str, int] = {}
        for child in body:
            if child.tag == "body":
                walk(child, own)
                continue
            if child.tag not in wanted:
                continue
            if child.tag == "geom" and body.find("inertial") is not None and not from_geoms:
                counts["geom"] = counts.get("geom", 0) + 1
                continue  # the body's <inertial> is its mass, COM and inertia: its geoms are not causes
            index = counts.get(child.tag, 0)
            counts[child.tag] = index + 1
            cls = child.get("class", own)
            bname = body.get("name", "?")
            for attr in wanted[child.tag]:
                if attr in child.attrib:
                    continue
                if child.tag == "geom" and attr == "pos" and "fromto" in child.attrib:
                    continue  # fromto places the geom
                found = defaults.lookup(cls, child.tag, attr)
                if found is None:
                    continue
                name = child.get("name") or f"{bname}/{child.tag}{index}"
                out.append(_ClassValue(child.tag, attr, found[0], bname, index, name, child.get("name") is not None))

    for world in root.findall("worldbody"):
        for body in world.findall("body"):
            walk(body, "main")
    return out


# ------------------------------------------------------------------------------------ file-level causes
@dataclass(frozen=True)
class _Framed:
    """What one outermost ``<frame>`` of the main file holds."""

    where: str  # "body <name>" or "worldbody"
    label: str  # the frame's name, or its position among its parent's frames
    bodies: tuple[str, ...]
    joints: tuple[str, ...]
    geoms: int  # geoms of the enclosing body inside the frame (not those of the bodies inside it)
    enclosing: str | None  # the enclosing body's name


def _frames(root: ET.Element) -> list[_Framed]:
    """Every outermost ``<frame>`` under ``<worldbody>``, with the bodies, joints and geoms inside it."""
    out: list[_Framed] = []

    def own_geoms(frame: ET.Element) -> int:  # geoms in the frame and its nested frames, not in bodies
        return sum(1 if c.tag == "geom" else own_geoms(c) if c.tag == "frame" else 0 for c in frame)

    def walk(element: ET.Element, where: str, enclosing: str | None) -> None:
        count = 0
        for child in element:
            if child.tag == "frame":
                count += 1
                bodies = tuple(b.get("name", "?") for b in child.iter("body"))
                label = child.get("name") or f"#{count}"
                out.append(_Framed(where, label, bodies, tuple(_joint_names(child)), own_geoms(child), enclosing))
            elif child.tag == "body":
                name = child.get("name", "?")
                walk(child, f"body {name}", name)

    for world in root.findall("worldbody"):
        walk(world, "worldbody", None)
    return out


def frame_causes(root: ET.Element, seg_of: dict[str, str], engine: str = "pinocchio") -> list[Finding]:
    """The ``<frame>`` elements an engine's MJCF parser does not read, with what they hold.

    MuJoCo resolves a ``<frame>`` at compile time (its pose moves every child); Pinocchio 4.1's and
    Drake's MJCF parsers skip the element and everything inside it: its bodies (with their joints) and
    the geoms it adds to the enclosing body, whose mass and inertia the segment then lacks.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    seg_of : dict of str to str
        Body name to the segment (joint) that moves it, from MuJoCo's compiled model.
    engine : str
        The engine whose parser skips ``<frame>``.

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause per outermost frame that holds a body or a geom.
    """
    parser = {"pinocchio": "Pinocchio's", "drake": "Drake's"}.get(engine, engine)
    out = []
    for fr in _frames(root):
        if not fr.bodies and not fr.geoms:
            continue
        held = [f"{len(fr.bodies)} bodies", f"{len(fr.joints)} joints"] if fr.bodies else []
        if fr.geoms:
            held.append(f"{fr.geoms} geoms of body {fr.enclosing}" if fr.enclosing else f"{fr.geoms} world geoms")
        moved = tuple(dict.fromkeys(seg_of[b] for b in (*fr.bodies, fr.enclosing or "") if seg_of.get(b)))
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                engine,
                f"frame {fr.label} in {fr.where}",
                f"<frame> not read by {parser} MJCF parser: what it holds is missing ({', '.join(held)})",
                values={"bodies": fr.bodies, "joints": fr.joints, "geoms": fr.geoms},
                affects_energy=bool(fr.joints or moved),
                root_cause=True,
                segments=moved or fr.joints,
                hint="give the bodies and geoms inside it the frame's pose and remove the <frame> "
                "(MuJoCo resolves it at compile time)",
            )
        )
    return out


def file_causes(path: str | os.PathLike[str], mj_model: mujoco.MjModel | None = None) -> list[Finding]:
    """Root causes visible in the file alone: ignored ``<include>`` and ``<frame>``, the root bodies Pinocchio skips.

    Used when Pinocchio cannot load the file or its joints cannot be paired with MuJoCo's, and for every
    model loaded in both engines.

    Parameters
    ----------
    path : str or path
        An MJCF file (anything else gives no cause).
    mj_model : mujoco.MjModel, optional
        MuJoCo's compiled model of the file: tells which included bodies move (a jointless subtree
        included in a moving body carries mass of that segment).

    Returns
    -------
    list of Finding
    """
    path = Path(path)
    root = _read_mjcf(path)
    if root is None:
        return []
    out: list[Finding] = []
    seg_of = {} if mj_model is None else _segment_of_body(mj_model)
    world_bodies = [b for w in root.findall("worldbody") for b in w.findall("body")]
    for inc in _included(root, path.parent):
        if not inc.bodies and not inc.defaults:
            continue  # assets, visual settings: nothing kinematic
        moved = tuple(dict.fromkeys(seg_of[b] for b in inc.bodies if seg_of.get(b)))
        if inc.bodies and not world_bodies:
            summary = (
                "<include> ignored by Pinocchio's MJCF parser; the file's <worldbody> has no <body> of its own "
                "(Pinocchio fails with 'No such node (body)')"
            )
        elif inc.bodies:
            summary = "<include> ignored by Pinocchio's MJCF parser: the included bodies and joints are missing"
        else:
            summary = "<include> ignored by Pinocchio's MJCF parser: the default classes it defines are unknown"
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                "pinocchio",
                f"include {inc.file}",
                summary,
                values={
                    "in": inc.where,
                    "bodies": inc.bodies,
                    "joints": inc.joints,
                    "mujoco": f"{len(inc.bodies)} bodies, {len(inc.joints)} joints",
                    "pinocchio": "not read",
                },
                affects_energy=bool(inc.joints or moved),
                root_cause=True,
                segments=moved or inc.joints,
                hint="load a file without <include> (e.g. the robot's own file)" if inc.bodies else "",
            )
        )
    out += frame_causes(root, seg_of)
    for body in world_bodies[1:]:
        joints = tuple(_joint_names(body))
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                "pinocchio",
                f"body {body_label(body, world_bodies)}",
                f"root body after the first ({body_label(world_bodies[0], world_bodies)}) under <worldbody>: "
                "Pinocchio's MJCF parser reads only the first",
                values={"joints": joints, "mujoco": "loaded", "pinocchio": "not read"},
                affects_energy=bool(joints),
                root_cause=True,
                segments=joints,
            )
        )
    return out


def nothing_moves(path: str | os.PathLike[str], has_body: bool = True) -> Finding:
    """The finding for a model without a joint: nothing to compare, not an engine error.

    Parameters
    ----------
    path : str or path
    has_body : bool
        Whether the model has a body that ``--floating`` could set free.

    Returns
    -------
    Finding
    """
    return Finding(
        Kind.NOTHING_MOVES,
        "file",
        "model",
        "no joint: nothing moves, so there is no kinetic energy to compare (not an engine error)"
        + ("" if has_body else "; the <worldbody> holds no <body>"),
        values={"file": str(path)},
        root_cause=True,
        hint="--floating (floating=True) gives the root body a free joint" if has_body else "",
    )


def explain_load_failures(load: F) -> F:
    """Decorate a loader so that its load errors carry the file's root causes.

    The error keeps its type; ``err.causes`` (:attr:`~koenig_check.exceptions.KoenigCheckError.causes`) is
    the tuple of root causes (possibly empty) and, when there are any, the one-line message ends with them.
    A model without a joint gets :func:`nothing_moves`.

    Parameters
    ----------
    load : callable
        ``load_model(path_or_name, ...)``.

    Returns
    -------
    callable
    """

    @wraps(load)
    def wrapper(path_or_name: Any, *args: Any, **kwargs: Any) -> Any:
        try:
            return load(path_or_name, *args, **kwargs)
        except NoMovingSegmentError as err:
            err.attach_causes([nothing_moves(getattr(err, "path", path_or_name))], in_message=False)
            raise
        except (CoupledJointsError, InertiaError) as err:  # MuJoCo's refusal or the file's couplings
            err.attach_causes([])
            raise
        except (ModelLoadError, JointMismatch) as err:
            err.attach_causes(_file_causes_of(path_or_name, kwargs.get("fmt")))
            raise

    return cast("F", wrapper)


def _file_causes_of(path_or_name: Any, fmt: str | None) -> list[Finding]:
    from koenig_check.sources.catalogue import resolve_model

    try:
        source = resolve_model(path_or_name, fmt)
    except Exception:  # the original error says what is wrong with the name
        return []
    if source.format != "mjcf":
        return []
    try:
        model = mujoco.MjModel.from_xml_path(str(source.path))
    except Exception:  # MuJoCo refuses the file itself: Pinocchio's reading of it is not the cause
        return []
    if model.njnt == 0:  # e.g. a <worldbody> without a <body>: Pinocchio fails, but nothing moves anyway
        return [nothing_moves(source.path, has_body=model.nbody > 1)]
    return file_causes(source.path, model)


# ----------------------------------------------------------------------------------- model-level causes
@dataclass(frozen=True)
class FrameOffset:
    """The constant transform ``world_mujoco <- world_pinocchio`` of a dropped root-body pose.

    Attributes
    ----------
    rotation : ndarray, shape (3, 3)
    translation : ndarray, shape (3,)
    """

    rotation: np.ndarray
    translation: np.ndarray

    def point(self, x: np.ndarray) -> np.ndarray:
        """Map points (..., 3) from Pinocchio's world to MuJoCo's."""
        return x @ self.rotation.T + self.translation

    def vector(self, v: np.ndarray) -> np.ndarray:
        """Map free vectors (..., 3) from Pinocchio's world to MuJoCo's."""
        return v @ self.rotation.T

    def frame(self, R: np.ndarray) -> np.ndarray:
        """Map rotations (..., 3, 3) world <- segment from Pinocchio's world to MuJoCo's."""
        return self.rotation @ R


def root_frame_offset(pair: Any, atol: float = 1e-9) -> tuple[FrameOffset | None, Finding | None]:
    """The dropped pose of a jointless root body: where MuJoCo and Pinocchio put the first root body.

    Parameters
    ----------
    pair : ModelPair
    atol : float
        Under this (rotation entries, metres) the poses are the same.

    Returns
    -------
    offset : FrameOffset or None
    finding : Finding or None
        A FRAME note (``affects_energy=False``) naming the body and both poses.
    """
    import pinocchio as pin

    mj_model, pin_model = pair.mujoco.model, pair.pinocchio.model
    roots = [b for b in range(1, mj_model.nbody) if mj_model.body_parentid[b] == 0]
    if not roots:
        return None, None
    body = roots[0]
    name = mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_BODY, body) or ""
    if mj_model.body_jntnum[body] > 0 or not name or not pin_model.existFrame(name):
        return None, None
    data = mujoco.MjData(mj_model)
    data.qpos[:] = mj_model.qpos0
    mujoco.mj_kinematics(mj_model, data)
    R_mj, p_mj = data.xmat[body].reshape(3, 3).copy(), data.xpos[body].copy()
    pdata = pin_model.createData()
    q = pair.state_map.to_pinocchio(np.asarray(mj_model.qpos0, dtype=float))
    pin.framesForwardKinematics(pin_model, pdata, q)
    placement = pdata.oMf[pin_model.getFrameId(name)]
    R_pin, p_pin = np.array(placement.rotation), np.array(placement.translation)
    if np.abs(R_mj - R_pin).max() <= atol and np.abs(p_mj - p_pin).max() <= atol:
        return None, None
    R = R_mj @ R_pin.T
    offset = FrameOffset(R, p_mj - R @ p_pin)
    quat = _quat(R_mj)
    finding = Finding(
        Kind.FRAME,
        "pinocchio",
        f"body {name}",
        "pose of the jointless root body dropped by Pinocchio's MJCF parser: a constant world transform "
        "between the engines (segments compared in MuJoCo's world after removing it)",
        values={
            "mujoco pos": _vec(p_mj),
            "pinocchio pos": _vec(p_pin),
            "mujoco quat": _vec(quat),
            "pinocchio quat": _vec(_quat(R_pin)),
        },
        affects_energy=False,
        root_cause=True,
        segments=tuple(pair.pinocchio.segment_names),
    )
    return offset, finding


def _vec(x: np.ndarray) -> tuple[float, ...]:
    """A vector as a tuple of floats rounded to 1e-12 (readable in messages, exact enough as data)."""
    return tuple(round(float(v), 12) + 0.0 for v in np.ravel(x))


def _quat(R: np.ndarray) -> np.ndarray:
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(R).ravel())
    return quat


def _segment_of_body(mj_model: mujoco.MjModel) -> dict[str, str]:
    """MuJoCo body name -> the segment (name of its carrier's last joint) that moves it ('' if static)."""
    seg = _segment_by_body_id(mj_model)
    names = (mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(mj_model.nbody))
    return {name: seg[b] for b, name in enumerate(names) if name}


def _segment_by_body_id(mj_model: mujoco.MjModel) -> list[str]:
    """The segment of every MuJoCo body, by body id ('' for the world and static bodies)."""
    seg = [""] * mj_model.nbody
    for b in range(1, mj_model.nbody):  # parents come before children
        if mj_model.body_jntnum[b] > 0:
            seg[b] = _joint_name(mj_model, mj_model.body_jntadr[b] + mj_model.body_jntnum[b] - 1)
        else:
            seg[b] = seg[mj_model.body_parentid[b]]
    return seg


def _joint_name(mj_model: mujoco.MjModel, j: int) -> str:
    from koenig_check.engines.canonical import mujoco_joint_names

    return mujoco_joint_names(mj_model)[j]


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
    pin_mass = _pinocchio_segment_masses(pair)
    mass, com, pole = {}, {}, {}
    for k, n in enumerate(sa.names):
        mass[n] = (float(sa.mass[k]), pin_mass.get(n, float("nan")))
        if n in b_index:
            com[n] = (sa.com[0, k], com_b[b_index[n]])
            pole[n] = (sa.pole[0, k], pole_b[b_index[n]])
    size = max(float(np.abs(sa.com[0]).max(initial=0.0)), float(np.abs(sa.pole[0]).max(initial=0.0)), 1.0)
    return _Segments(mass, com, pole, size)


def _pinocchio_segment_masses(pair: Any) -> dict[str, float]:
    """Pinocchio's mass of every joint-keyed segment, massless ones included."""
    names = pair.state_map.segment_names
    inertias = pair.pinocchio.model.inertias
    return {names[i]: float(inertias[i].mass) for i in range(1, len(inertias)) if names[i]}


def massless_causes(pair: Any) -> list[Finding]:
    """Segments with mass in one engine and none in the other ("massless in Pinocchio").

    Parameters
    ----------
    pair : ModelPair

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
    pin_mass = _pinocchio_segment_masses(pair)
    out = []
    for engine, have, lack in (("pinocchio", mj_mass, pin_mass), ("mujoco", pin_mass, mj_mass)):
        if engine == "mujoco":
            lack = {n: 0.0 for n in _mujoco_massless(pair)}
        names = sorted(n for n, m in have.items() if m > 0 and n in lack and lack[n] <= 0)
        if not names:
            continue
        values: dict[str, Any] = {"segments": tuple(names)}
        values["mujoco" if engine == "pinocchio" else "pinocchio"] = float(sum(have[n] for n in names))
        values[engine] = 0.0
        out.append(
            Finding(
                Kind.SEGMENTS,
                engine,
                f"segment {_names(names)}",
                f"massless in {'Pinocchio' if engine == 'pinocchio' else 'MuJoCo'} (mass only in the other engine)",
                values=values,
                affects_energy=True,
                root_cause=True,
                segments=tuple(names),
            )
        )
    return out


def _mujoco_massless(pair: Any) -> list[str]:
    """MuJoCo segments (joint-keyed) whose lumped mass is zero."""
    m = pair.mujoco.model
    total: dict[str, float] = {}
    for b, s in enumerate(_segment_by_body_id(m)):
        if s:
            total[s] = total.get(s, 0.0) + float(m.body_mass[b])
    return [s for s, mass in total.items() if mass <= 0]


def class_value_causes(pair: Any, offset: FrameOffset | None = None) -> list[Finding]:
    """Geom masses, geom positions and joint positions from default classes that Pinocchio did not apply.

    A candidate from the file is reported only when its segment shows the symptom in the engines
    (mass for a geom mass, COM for a geom position, anchor for a joint position).

    Parameters
    ----------
    pair : ModelPair
    offset : FrameOffset, optional
        A dropped root pose to remove before comparing positions.

    Returns
    -------
    list of Finding
        One finding per (attribute, default class), naming its elements.
    """
    path = Path(str(pair.mujoco.path))
    root = _read_mjcf(path)
    if root is None:
        return []
    candidates = _class_values(root)
    if not candidates:
        return []
    try:
        spec = mujoco.MjSpec.from_file(str(path))
    except Exception:  # MuJoCo loaded the file through our loader; a raw re-read may need its fixes
        return []
    mj_model = pair.mujoco.model
    seg_of = _segment_of_body(mj_model)
    segs = _segments(pair, offset)
    tol_len = RTOL * segs.size
    groups: dict[tuple[str, str, str], list[tuple[_ClassValue, Any, str]]] = {}
    for cand in candidates:
        element = _spec_element(spec, cand)
        segment = seg_of.get(cand.body, "")
        if element is None or not segment:
            continue
        if cand.tag == "geom" and cand.attr == "mass":
            m_a, m_b = segs.mass.get(segment, (0.0, 0.0))
            shows = abs(m_a - m_b) > RTOL * max(abs(m_a), abs(m_b), 1e-300)
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
        names = [c.name for c, _, _ in members]
        segments = tuple(dict.fromkeys(s for _, _, s in members))
        if attr == "mass":
            try:
                masses = _mass_values(spec, [e for _, e, _ in members])
            except ValueError:  # the raw file does not compile without the loader's fixes (meshes)
                masses = {  # the engines' own masses of the segments concerned instead
                    f"{engine} mass of segments": float(sum(segs.mass.get(s, (0.0, 0.0))[k] for s in segments))
                    for k, engine in enumerate(("mujoco", "pinocchio"))
                }
            values = {"class": cls, "geoms": tuple(names), **masses}
            summary = f"geom mass from default class '{cls}' not applied by Pinocchio; density × volume used"
            kind = Kind.MASS
        else:
            pos = list(dict.fromkeys(_vec(np.array(e.pos, dtype=float)) for _, e, _ in members))
            values = {"class": cls, f"{tag}s": tuple(names), "mujoco": pos[0] if len(pos) == 1 else tuple(pos)}
            values["pinocchio"] = (0.0, 0.0, 0.0)
            summary = f"{tag} pos from default class '{cls}' not applied by Pinocchio; {tag} placed at the body origin"
            kind = Kind.ANCHOR if tag == "joint" else Kind.COM
        out.append(
            Finding(
                kind,
                "pinocchio",
                f"{tag} {_names(names)}",
                summary,
                values=values,
                affects_energy=True,
                root_cause=True,
                segments=segments,
            )
        )
    return out


def _mass_differs(segs: _Segments, segment: str) -> bool:
    m_a, m_b = segs.mass.get(segment, (0.0, 0.0))
    return abs(m_a - m_b) > RTOL * max(abs(m_a), abs(m_b), 1e-300)


def _spec_element(spec: mujoco.MjSpec, cand: _ClassValue) -> Any:
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
    base = spec.compile()
    given = float(sum(g.mass for g in geoms))
    saved = [g.mass for g in geoms]
    try:
        for g in geoms:
            g.mass = float("nan")  # unset: MuJoCo computes density × volume
        unset = spec.compile()
    finally:
        for g, m in zip(geoms, saved, strict=True):
            g.mass = m
    return {"mujoco": given, "pinocchio": float(given + unset.body_mass.sum() - base.body_mass.sum())}


def compiler_causes(pair: Any) -> list[Finding]:
    """Compiler options MuJoCo applies and Pinocchio's MJCF parser does not (``settotalmass``).

    Reported when the engines' total masses differ and MuJoCo's equals the option's value.

    Parameters
    ----------
    pair : ModelPair

    Returns
    -------
    list of Finding
    """
    root = _read_mjcf(Path(str(pair.mujoco.path)))
    if root is None:
        return []
    out = []
    for compiler in root.iter("compiler"):
        value = compiler.get("settotalmass")
        if value is None or float(value) <= 0:
            continue
        m_mj = float(np.asarray(pair.mujoco.model.body_mass).sum())
        m_pin = float(sum(Y.mass for Y in pair.pinocchio.model.inertias))
        scale = max(m_mj, m_pin, 1e-300)
        if abs(m_mj - float(value)) <= RTOL * scale and abs(m_mj - m_pin) > RTOL * scale:
            out.append(
                Finding(
                    Kind.COMPILER,
                    "pinocchio",
                    "compiler settotalmass",
                    f"settotalmass={value}: MuJoCo rescales every mass and inertia to this total, Pinocchio does not",
                    values={"mujoco": m_mj, "pinocchio": m_pin},
                    affects_energy=True,
                    root_cause=True,
                    segments=tuple(pair.mujoco.segment_names),
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
    pair : ModelPair
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
    seg_of = _segment_of_body(pair.mujoco.model)
    segs = _segments(pair, None)
    geoms: list[str] = []
    segments: list[str] = []
    for body in spec.bodies:
        segment = seg_of.get(body.name, "")
        if not segment or segment in explained or not _mass_differs(segs, segment):
            continue
        meshed = [g.name or f"{body.name}/geom{k}" for k, g in enumerate(body.geoms) if g.meshname]
        if meshed:
            geoms += meshed
            segments.append(segment)
    if not geoms:
        return []
    segments = list(dict.fromkeys(segments))
    return [
        Finding(
            Kind.MASS,
            "pinocchio",
            f"geom {_names(geoms)}",
            "geoms with a mesh: Pinocchio's MJCF parser does not compute mass and inertia from the mesh "
            "(a mesh-typed geom counts as 1 kg with unit inertia, a primitive fitted to a mesh as nothing)",
            values={
                "geoms": tuple(geoms),
                "mujoco": float(sum(segs.mass[s][0] for s in segments)),
                "pinocchio": float(sum(segs.mass[s][1] for s in segments)),
            },
            affects_energy=True,
            root_cause=True,
            segments=tuple(segments),
        )
    ]


def model_causes(pair: Any) -> tuple[list[Finding], FrameOffset | None]:
    """Every root cause of an MJCF model loaded in both engines, and the dropped root pose if any.

    Parameters
    ----------
    pair : ModelPair

    Returns
    -------
    causes : list of Finding
        Root causes, those that change the energy first.
    offset : FrameOffset or None
        ``world_mujoco <- world_pinocchio`` when Pinocchio dropped a root body's pose.
    """
    mj_path, pin_path = Path(str(pair.mujoco.path)), Path(str(pair.pinocchio.path))
    if mj_path != pin_path or _read_mjcf(mj_path) is None:
        return [], None
    causes = file_causes(mj_path, pair.mujoco.model)
    offset, frame = root_frame_offset(pair)
    causes += compiler_causes(pair)
    causes += class_value_causes(pair, offset)
    causes += mesh_causes(pair)
    causes += massless_causes(pair)
    if frame is not None:
        causes.append(frame)
    return sorted(causes, key=lambda f: not f.affects_energy), offset
