"""Links a URDF's joints name but the file never declares (Drake's implicit ``world`` link among them).

Drake's URDF parser reads a joint whose parent is ``world`` as welded to its world without a ``<link
name="world"/>``; MuJoCo ("URDF joint parent or child missing") and Pinocchio (urdfdom: "parent link [world] of
joint [...] not found") refuse such a file.  :func:`undeclared_links` says which joint names which link, so
that a refusal can name the element and what to add.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from koenig_check.modelfile.validate import parse_xml


def undeclared_links(path: str | Path) -> str:
    """Which joints name a link the URDF does not declare, in one clause, or ``""``.

    Parameters
    ----------
    path : str or Path
        A URDF file.

    Returns
    -------
    str
        ``"joint 'base_weld': parent link 'world' not declared; only Drake implies the world link: add <link
        name='world'/>"``; empty when every link named is declared or the file cannot be read.
    """
    root = _readable_root(path)
    if root is None:
        return ""
    declared = {link.get("name") for link in root.iter("link")}
    missing = []
    for joint in root.iter("joint"):
        for side in ("parent", "child"):
            element = joint.find(side)
            link = element.get("link") if element is not None else None
            if link is not None and link not in declared:
                missing.append((joint.get("name", "?"), side, link))
    if not missing:
        return ""
    named = ", ".join(f"joint {joint!r}: {side} link {link!r}" for joint, side, link in missing[:3])
    more = f" (and {len(missing) - 3} more)" if len(missing) > 3 else ""
    links = sorted({link for _, _, link in missing})
    text = f"{named}{more} not declared"
    if "world" in links:
        text += '; only Drake implies the world link: add <link name="world"/>'
    return text


def planar_joints(path: str | Path) -> list[str]:
    """The names of the URDF's ``planar`` joints (MuJoCo's import makes each three joints, Pinocchio one).

    Parameters
    ----------
    path : str or Path
        A URDF file.

    Returns
    -------
    list of str
        Empty when there is none or the file cannot be read.
    """
    root = _readable_root(path)
    if root is None:
        return []
    return [j.get("name", "?") for j in root.iter("joint") if j.get("type") == "planar"]


def planar_axes(path: str | Path) -> dict[str, tuple[float, ...]]:
    """The URDF's ``planar`` joints with their ``<axis>`` (the plane's normal; ``1 0 0`` when not written).

    Parameters
    ----------
    path : str or Path
        A URDF file.

    Returns
    -------
    dict of str to tuple of float
        Joint name -> axis as written; empty when there is none or the file cannot be read.
    """
    root = _readable_root(path)
    if root is None:
        return {}
    out = {}
    for joint in root.iter("joint"):
        if joint.get("type") == "planar":
            axis = joint.find("axis")
            text = axis.get("xyz", "1 0 0") if axis is not None else "1 0 0"
            try:
                out[joint.get("name", "?")] = tuple(float(x) for x in text.split())
            except ValueError:
                out[joint.get("name", "?")] = ()
    return out


def links_without_inertial(path: str | Path) -> list[str]:
    """The URDF's links that declare no ``<inertial>``, in file order (massless by the URDF convention).

    PyBullet gives such a link 1 kg and a unit inertia, Newton mass from its collision shapes: each engine's traps
    read this one list.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    list of str
        Empty when the file cannot be read (the engines that read it say why).
    """
    robot = _readable_root(path)
    if robot is None:
        return []
    return [link.get("name", "") for link in robot.findall("link") if link.find("inertial") is None]


def _readable_root(path: str | Path) -> ET.Element | None:
    """The URDF document's root element, or ``None`` when the file cannot be read (the engines then say why)."""
    try:
        return parse_xml(path).getroot()
    except (OSError, ET.ParseError):
        return None
