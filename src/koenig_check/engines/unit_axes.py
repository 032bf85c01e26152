"""``axisangle`` with an axis that is not of unit length: MuJoCo normalizes it, Pinocchio's MJCF parser does not.

MuJoCo reads ``axisangle="x y z a"`` as a rotation by ``a`` about the direction of ``(x, y, z)``; Pinocchio 4.1's
``buildModelFromMJCF`` puts the axis as written into Rodrigues' formula (verified on small files: a body placed
with ``axisangle="1 0 1 40"`` gets a placement matrix that is no rotation, a geom's or an ``<inertial>``'s
principal moments change).  Each such element is one root cause, read from the file.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np

from koenig_check.findings import Finding, Kind

#: Relative departure of the axis length from 1 under which the axis is taken as a unit one.
UNIT_RTOL = 1e-9
#: The elements whose orientation gives a segment its placement or its inertia.
_ORIENTED = ("body", "geom", "inertial")


def _axis_length(text: str) -> tuple[np.ndarray, float] | None:
    """The axis and its length, when the rotation is not the identity; ``None`` otherwise or when unreadable."""
    try:
        values = [float(v) for v in text.split()]
    except ValueError:
        return None
    if len(values) != 4 or values[3] == 0.0:
        return None
    axis = np.asarray(values[:3])
    return axis, float(np.linalg.norm(axis))


def _element_name(element: ET.Element, body: ET.Element | None, place: int) -> str:
    """``body c``, ``geom rod``, ``geom #2 of body a``, ``inertial of body a``."""
    owner = f"body {body.get('name', '?')}" if body is not None else "worldbody"
    if element.tag == "body":
        return f"body {element.get('name', '?')}"
    if element.tag == "inertial":
        return f"inertial of {owner}"
    name = element.get("name")
    return f"geom {name}" if name else f"geom #{place} of {owner}"


def _segments(body: ET.Element | None, seg_of: dict[str, str], subtree: bool) -> tuple[str, ...]:
    """The segments moved with a body (and, for a body's own placement, with every body under it)."""
    if body is None:
        return ()
    bodies = body.iter("body") if subtree else [body]
    return tuple(dict.fromkeys(seg_of[b.get("name", "")] for b in bodies if seg_of.get(b.get("name", ""))))


def axisangle_causes(root: ET.Element, seg_of: dict[str, str]) -> list[Finding]:
    """Bodies, geoms and inertials whose ``axisangle`` axis is not of unit length.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    seg_of : dict of str to str
        Body name to the segment (joint) that moves it, from MuJoCo's compiled model (empty: not known).

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause (engine ``pinocchio``) per element, with the axis and its length.
    """
    out: list[Finding] = []

    def walk(parent: ET.Element, body: ET.Element | None) -> None:
        geoms = 0
        for child in parent:
            geoms += child.tag == "geom"
            if child.tag in _ORIENTED and child.get("axisangle") is not None:
                read = _axis_length(child.get("axisangle", ""))
                if read is not None and abs(read[1] - 1.0) > UNIT_RTOL:
                    axis, length = read
                    segments = _segments(child if child.tag == "body" else body, seg_of, child.tag == "body")
                    what = "placement" if child.tag == "body" else "inertia"
                    out.append(
                        Finding(
                            Kind.IGNORED_CONSTRUCT,
                            "pinocchio",
                            _element_name(child, body, geoms),
                            f"axisangle axis of length {length:.6g}: MuJoCo normalizes it, Pinocchio's MJCF parser "
                            f"does not (the {what} it builds is distorted); write a unit axis",
                            values={"axis": axis.tolist(), "length": length},
                            affects_energy=bool(segments) or not seg_of,
                            root_cause=True,
                            segments=segments,
                            cause="pinocchio.mjcf.axisangle-length",
                        )
                    )
            if child.tag == "body":
                walk(child, child)
            elif child.tag in ("worldbody", "frame"):
                walk(child, body)

    for world in root.findall("worldbody"):
        walk(world, None)
    return out
