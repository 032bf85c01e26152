"""Joints whose default attributes come through a class that has no ``<joint>`` of its own (Drake loses them).

MuJoCo looks a joint attribute up the class tree: a class without a ``<joint>`` element passes its parent's on.
Drake's MJCF parser (1.51) does not: a joint of such a class gets Drake's defaults (axis 0 0 1), the catalogued
cause ``drake.mjcf.class-joint-default``.  This module reads the file as written (the main file's body tree).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from koenig_check.modelfile.mjcf import DefaultClasses, read_mjcf


def inherited_through_jointless_class(path: str | Path) -> tuple[str, ...]:
    """The joints whose class has no ``<joint>`` default while a class above it has one.

    Parameters
    ----------
    path : str or Path
        An MJCF file.

    Returns
    -------
    tuple of str
        Joint names (``"<body>/joint<k>"`` for an unnamed joint), in file order; empty for a file that is not MJCF.
    """
    root = read_mjcf(Path(path))
    if root is None:
        return ()
    defaults = DefaultClasses(root)
    classes = defaults.element  # class name -> its <default> element
    out: list[str] = []

    def passes_on(cls: str) -> bool:
        name = cls if cls in classes else "main"
        if name not in classes or classes[name].find("joint") is not None:
            return False
        parent = defaults.parent.get(name)
        while parent is not None:
            setter = classes[parent].find("joint")
            if setter is not None and setter.attrib:
                return True
            parent = defaults.parent.get(parent)
        return False

    def walk(body: ET.Element, childclass: str) -> None:
        own = body.get("childclass", childclass)
        for k, joint in enumerate(body.findall("joint")):
            if passes_on(joint.get("class", own)):
                out.append(joint.get("name") or f"{body.get('name', '?')}/joint{k}")
        for child in body.findall("body"):
            walk(child, own)

    for world in root.findall("worldbody"):
        for body in world.findall("body"):
            walk(body, "main")
    return tuple(out)
