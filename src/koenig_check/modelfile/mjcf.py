"""Reading an MJCF file as written: its includes, default classes, root bodies and frames.

What MuJoCo resolves at compile time (an ``<include>``, a default class, a ``<frame>``) other parsers may not:
the engines' traps (:mod:`koenig_check.engines.parser_traps`) and the pair causes
(:mod:`koenig_check.diagnosis.pair_causes`) read the file through these functions, never by hand.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

from koenig_check.modelfile.validate import parse_xml

#: The root element of an MJCF file: a tag of the file format (named after the engine that defined it).
ROOT_TAG = "mujoco"
#: Attributes that Pinocchio 4.1's MJCF parser ignores when they come from a default class.
CLASS_ATTRIBUTES_IGNORED = (("geom", "mass"), ("geom", "pos"), ("joint", "pos"))


def read_mjcf(path: Path, included: bool = False) -> ET.Element | None:
    """The root ``<mujoco>`` element of a file, or ``None`` when it is not a readable MJCF file.

    An included file's top element may have any name (``<mujocoinclude>`` is common): MuJoCo drops it.
    """
    try:
        root = parse_xml(path).getroot()
    except (ET.ParseError, OSError):
        return None
    return root if included or root.tag == ROOT_TAG else None


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


@dataclass(frozen=True)
class Included:
    """What one ``<include>`` of the main file brings in."""

    file: str
    where: str  # "body <name>", "worldbody" or "mujoco" (top level)
    bodies: tuple[str, ...]
    joints: tuple[str, ...]
    defaults: bool  # it defines default classes


#: Sections whose ``<joint>`` elements are not joints: a default class's attributes, an equality or a tendon
#: naming a joint (``<equality><joint joint1=...>``, ``<tendon><fixed><joint joint=...>``), and the like.
_NOT_JOINTS = frozenset({"default", "equality", "tendon", "actuator", "contact", "sensor", "keyframe", "custom"})


def joint_names(element: ET.Element) -> list[str]:
    """The names of the joints (and free joints) anywhere inside an element ("?" for an unnamed one).

    A ``<joint>`` in a ``<default>``, ``<equality>``, ``<tendon>`` (or another section that only refers to joints)
    is not a joint and is not counted.

    Parameters
    ----------
    element : xml.etree.ElementTree.Element

    Returns
    -------
    list of str
    """
    if element.tag in _NOT_JOINTS:
        return []
    own = [element.get("name", "?")] if element.tag in ("joint", "freejoint") else []
    return own + [name for child in element for name in joint_names(child)]


def includes(root: ET.Element, directory: Path) -> list[Included]:
    """Every ``<include>`` of the main file with the bodies, joints and defaults it brings in."""
    out = []
    parents = {child: parent for parent in root.iter() for child in parent}
    roots = [b for w in root.findall("worldbody") for b in w.findall("body")]
    for inc in root.iter("include"):
        name = inc.get("file", "")
        parent = parents.get(inc)
        where = ROOT_TAG if parent is None or parent.tag == ROOT_TAG else parent.tag
        if parent is not None and parent.tag == "body":
            where = f"body {parent.get('name')}" if parent.get("name") else body_label(parent, roots)
        sub = read_mjcf(directory / name, included=True)
        if sub is None:
            out.append(Included(name, where, (), (), False))
            continue
        nested = includes(sub, directory)
        bodies = [b.get("name", "?") for b in sub.iter("body")] + [b for n in nested for b in n.bodies]
        joints = joint_names(sub) + [j for n in nested for j in n.joints]
        defaults = sub.find("default") is not None or any(n.defaults for n in nested)
        out.append(Included(name, where, tuple(bodies), tuple(joints), defaults))
    return out


class DefaultClasses:
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
class ClassValue:
    """An attribute of a geom or joint that comes from a default class, not from the element."""

    tag: str
    attr: str
    cls: str
    body: str
    index: int  # position among the body's direct children of this tag
    name: str  # the element's name, or "<body>/<tag><index>"
    named: bool


def class_values(root: ET.Element) -> list[ClassValue]:
    """Attributes in :data:`CLASS_ATTRIBUTES_IGNORED` that the main file's elements get from a class.

    Geoms and joints of the main file's body tree only (not those inside ``<frame>`` or included files).
    The geoms of a body with its own ``<inertial>`` are left out: neither engine takes the body's mass
    properties from them (unless ``<compiler inertiafromgeom="true">``), so their class values change nothing.
    """
    defaults = DefaultClasses(root)
    from_geoms = any(c.get("inertiafromgeom") == "true" for c in root.iter("compiler"))
    wanted = {tag: [a for t, a in CLASS_ATTRIBUTES_IGNORED if t == tag] for tag, _ in CLASS_ATTRIBUTES_IGNORED}
    out: list[ClassValue] = []

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
                out.append(ClassValue(child.tag, attr, found[0], bname, index, name, child.get("name") is not None))

    for world in root.findall("worldbody"):
        for body in world.findall("body"):
            walk(body, "main")
    return out


@dataclass(frozen=True)
class Framed:
    """What one outermost ``<frame>`` of the main file holds."""

    where: str  # "body <name>" or "worldbody"
    label: str  # the frame's name, or its position among its parent's frames
    bodies: tuple[str, ...]
    joints: tuple[str, ...]
    geoms: int  # geoms of the enclosing body inside the frame (not those of the bodies inside it)
    enclosing: str | None  # the enclosing body's name


def frames(root: ET.Element) -> list[Framed]:
    """Every outermost ``<frame>`` under ``<worldbody>``, with the bodies, joints and geoms inside it."""
    out: list[Framed] = []

    def own_geoms(frame: ET.Element) -> int:  # geoms in the frame and its nested frames, not in bodies
        return sum(1 if c.tag == "geom" else own_geoms(c) if c.tag == "frame" else 0 for c in frame)

    def walk(element: ET.Element, where: str, enclosing: str | None) -> None:
        count = 0
        for child in element:
            if child.tag == "frame":
                count += 1
                bodies = tuple(b.get("name", "?") for b in child.iter("body"))
                label = child.get("name") or f"#{count}"
                out.append(Framed(where, label, bodies, tuple(joint_names(child)), own_geoms(child), enclosing))
            elif child.tag == "body":
                name = child.get("name", "?")
                walk(child, f"body {name}", name)

    for world in root.findall("worldbody"):
        walk(world, "worldbody", None)
    return out
