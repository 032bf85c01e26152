"""The catalogued causes found on a user's robot when iDynTree reads it (:mod:`koenig_check.engines.idyntree.causes`).

A link of mass 0 with a rotational inertia, fixed to another link, is made a frame by iDynTree's URDF reader: its
inertia is dropped.  Where such a link moves with a segment, that is a root cause of iDynTree's reading.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from koenig_check.findings import Finding, Kind


def massless_with_inertia(path: Path) -> list[str]:
    """The URDF's links whose ``<inertial>`` has mass 0 and a non-zero rotational inertia, in file order.

    Parameters
    ----------
    path : Path

    Returns
    -------
    list of str
    """
    try:
        robot = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return []
    out = []
    for link in robot.findall("link"):
        mass, inertia = link.find("inertial/mass"), link.find("inertial/inertia")
        if mass is None or inertia is None or float(mass.get("value", "0") or 0) != 0.0:
            continue
        if any(float(inertia.get(k, "0") or 0) != 0.0 for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")):
            out.append(link.get("name", ""))
    return out


def frame_findings(engine: Any, path: Path) -> list[Finding]:
    """Massless links with inertia that iDynTree made frames, where they move with a segment.

    Parameters
    ----------
    engine : IDynTreeEngine
    path : Path

    Returns
    -------
    list of Finding
        One root cause naming the links and the segments they move with, or none.
    """
    model = engine.model
    links = {model.getLinkName(k) for k in range(model.getNrOfLinks())}
    frames = {model.getFrameName(k): int(model.getFrameLink(k)) for k in range(model.getNrOfFrames())}
    segment = engine.segment_of_link()
    dropped = [n for n in massless_with_inertia(path) if n not in links and frames.get(n, -1) in segment]
    if not dropped:
        return []
    return [
        Finding(
            Kind.INERTIA,
            "idyntree",
            "links " + ", ".join(dropped),
            "iDynTree makes a massless link fixed to another a frame: its rotational inertia is dropped",
            {"links": dropped},
            affects_energy=True,
            root_cause=True,
            segments=tuple(dict.fromkeys(segment[frames[n]] for n in dropped)),
            cause="idyntree.urdf.massless-link-inertia",
        )
    ]
