"""Compiler options and inertial gaps an MJCF file declares that make engines import it differently."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from koenig_check.modelfile.validate import parse_xml


def compiler_findings(path: Path, mj_model: Any = None) -> list[str]:
    """Compiler options and inertial gaps in an MJCF file that make the engines import it differently.

    Parameters
    ----------
    path : Path
    mj_model : mujoco.MjModel, optional
        The compiled model: geom types are read from it (MuJoCo's resolution of default classes and
        ``childclass``).  Without it, only types written on the geoms are known.

    Returns
    -------
    list of str
    """
    try:
        root = parse_xml(path).getroot()
    except (ET.ParseError, OSError):
        return []
    if root.tag != "mujoco":
        return []
    out = []
    for comp in root.iter("compiler"):
        for attr in (
            "settotalmass",
            "boundmass",
            "boundinertia",
            "balanceinertia",
            "inertiafromgeom",
            "inertiagrouprange",
        ):
            value = comp.get(attr)
            if value is None:
                continue
            if attr == "settotalmass" and float(value) > 0:
                out.append(
                    f"compiler settotalmass={value}: MuJoCo rescales every mass and inertia to this total; "
                    "check whether Pinocchio's MJCF parser does the same (total masses below)"
                )
            elif attr in ("boundmass", "boundinertia") and float(value) > 0:
                out.append(f"compiler {attr}={value}: MuJoCo raises smaller masses/inertias to this bound")
            elif attr == "balanceinertia" and value == "true":
                out.append("compiler balanceinertia=true: MuJoCo alters inertias that violate A + B >= C")
            elif attr == "inertiafromgeom" and value == "true":
                out.append("compiler inertiafromgeom=true: MuJoCo computes every body's inertia from its geoms")
    for body in root.iter("body"):
        if body.find("inertial") is None and body.find("geom") is not None:
            kinds = _geom_types(body, mj_model)
            out.append(
                f"body {body.get('name', '?')!r} has no <inertial>: its inertia comes from geoms of type "
                f"{kinds}; a parser that ignores a geom type (e.g. mesh) gets a different inertia"
            )
    return out


def _geom_types(body: ET.Element, mj_model: Any) -> list[str]:
    """Types of a body's geoms as MuJoCo resolved them (classes included), else as written."""
    import mujoco

    b = -1 if mj_model is None else mujoco.mj_name2id(mj_model, mujoco.mjtObj.mjOBJ_BODY, body.get("name", ""))
    if b < 0:
        return sorted({g.get("type", "default class") for g in body.findall("geom")})
    adr, num = int(mj_model.body_geomadr[b]), int(mj_model.body_geomnum[b])
    types = mj_model.geom_type[adr : adr + num]
    return sorted({mujoco.mjtGeom(int(t)).name.removeprefix("mjGEOM_").lower() for t in types})
