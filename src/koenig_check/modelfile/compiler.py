"""Compiler options and inertial gaps an MJCF file declares that make engines import it differently."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.mjcf import body_label, read_mjcf

#: The compiler options with which MuJoCo changes masses or inertias while compiling: what it does, and the
#: hint for a reader of the parity report.  An option is in effect when its value is > 0 (a number) or "true".
MASS_OPTIONS = {
    "settotalmass": (
        "MuJoCo rescales every mass and inertia to this total",
        "check whether Pinocchio's MJCF parser does the same (total masses below)",
    ),
    "boundmass": ("MuJoCo raises smaller body masses to this bound", "Pinocchio's MJCF parser applies it too"),
    "boundinertia": ("MuJoCo raises smaller principal moments to this bound", "Pinocchio's MJCF parser applies it too"),
    "balanceinertia": ("MuJoCo alters inertias that violate A + B >= C", ""),
    "inertiafromgeom": ("MuJoCo computes every body's inertia from its geoms", ""),
}


def compiler_options(path: Path) -> list[Finding]:
    """The compiler options an MJCF file sets with which MuJoCo changes masses or inertias.

    The one reading of these options: import parity's notes (:func:`compiler_findings`) and the root
    causes (:func:`koenig_check.diagnosis.pair_causes.compiler_causes`) both start from these records.

    Parameters
    ----------
    path : Path

    Returns
    -------
    list of Finding
        One per option in effect, in file order: kind ``COMPILER``, engine ``mujoco`` (the engine that
        applies it), element ``compiler NAME``, summary what MuJoCo does, values ``{NAME: value, "as written":
        text}`` (a float, or ``True`` for a flag, and the attribute's text); none for a file that is not MJCF
        or cannot be read.
    """
    root = read_mjcf(path)
    if root is None:
        return []
    out = []
    for comp in root.iter("compiler"):
        for name, (effect, hint) in MASS_OPTIONS.items():
            written = comp.get(name)
            value = _in_effect(written)
            if value is not None:
                values = {name: value, "as written": written}
                element = f"compiler {name}"
                out.append(Finding(Kind.COMPILER, "mujoco", element, effect, values, True, hint=hint, tag="compiler"))
    return out


def option_text(option: Finding) -> str:
    """``NAME=VALUE`` of a compiler option record, as the file writes it (``settotalmass=14``).

    Parameters
    ----------
    option : Finding
        A record of :func:`compiler_options`.

    Returns
    -------
    str
    """
    return f"{option.name}={option.values['as written']}"


def _in_effect(written: str | None) -> float | bool | None:
    """An option's value when it changes what MuJoCo compiles (> 0, or ``true``), else ``None``."""
    if written is None:
        return None
    if written.strip() == "true":
        return True
    try:
        value = float(written)
    except ValueError:
        return None
    return value if value > 0 else None


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
        The options of :func:`compiler_options` (``compiler NAME=VALUE: what MuJoCo does[; hint]``), then
        the bodies without ``<inertial>``.
    """
    out = [
        f"compiler {option_text(o)}: {o.summary}" + (f"; {o.hint}" if o.hint else "") for o in compiler_options(path)
    ]
    root = read_mjcf(path)
    if root is None:
        return out
    roots = [b for world in root.findall("worldbody") for b in world.findall("body")]
    for body in root.iter("body"):
        if body.find("inertial") is None and body.find("geom") is not None:
            kinds = _geom_types(body, mj_model)
            named = f"body {body.get('name')!r}" if body.get("name") else body_label(body, roots)  # or by its place
            out.append(
                f"{named} has no <inertial>: its inertia comes from geoms of type "
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
