"""A ``<body>`` written without any attribute: Pinocchio's MJCF parser skips it, MuJoCo reads it.

Pinocchio 4.1 takes a body's name (or, unnamed, its parent's name + ``"Bis"``) and registers the body while
reading its attributes; a ``<body>`` with none is never registered (verified on a small file: its geoms weigh
nothing, its joints are missing, and its child bodies hang from the world instead of from its parent).  MuJoCo
reads it as a body at its parent's origin.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from koenig_check.engines.catalogue import cause
from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind, shown_names
from koenig_check.modelfile.mjcf import joint_names

#: The catalogued cause of a ``<body>`` without any attribute.
BARE_BODY = "pinocchio.mjcf.bare-body"


def bare_body_causes(root: ET.Element, seg_of: dict[str, str]) -> list[Finding]:
    """The ``<body>`` elements without any attribute, each a root cause for Pinocchio.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    seg_of : dict of str to str
        Body name to the segment (joint) that moves it, from MuJoCo's compiled model.

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` finding per such body (engine ``pinocchio``): where it is, its geoms and own
        joints (those Pinocchio lacks), and the segments it changes (the enclosing one, its own and those below it,
        which Pinocchio hangs from the world); it changes the energy when it has joints or sits in a moving body.
    """
    parents = {child: parent for parent in root.iter() for child in parent}
    skips, reads = cause(BARE_BODY).engine, reference()
    out = []
    for world in root.findall("worldbody"):
        for body in world.iter("body"):
            if body.attrib:
                continue
            parent = parents.get(body)
            where = "worldbody"
            while parent is not None and parent.tag == "body" and not parent.get("name"):
                parent = parents.get(parent)
            if parent is not None and parent.tag == "body":
                where = f"body {parent.get('name')}"
            joints = tuple(joint_names(body))
            own = [j for j in body if j.tag in ("joint", "freejoint")]
            enclosing = seg_of.get(parent.get("name", "")) if parent is not None and parent.tag == "body" else None
            segments = tuple(dict.fromkeys((*([enclosing] if enclosing else []), *joints)))
            geoms = len(body.findall("geom"))
            # at its parent's origin, a bare body welded to a static parent changes nothing that moves
            moves = bool(own) or (enclosing is not None and bool(geoms or body.find("body") is not None))
            out.append(
                Finding(
                    Kind.IGNORED_CONSTRUCT,
                    skips,
                    f"body without attributes in {where}",
                    "<body> without any attribute skipped by Pinocchio's MJCF parser: its geoms and joints are "
                    "missing, its child bodies hang from the world",
                    values={
                        "geoms": geoms,
                        "joints": tuple(j.get("name", "?") for j in own),
                        reads: "loaded",
                        skips: "not read",
                    },
                    affects_energy=moves,
                    root_cause=True,
                    segments=segments,
                    cause=BARE_BODY,
                    tag="body",
                    hint=f"give it a name (or any attribute); joints below: {shown_names(joints)}"
                    if joints
                    else "give it a name (or any attribute)",
                )
            )
    return out
