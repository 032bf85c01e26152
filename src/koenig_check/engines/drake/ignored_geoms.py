"""Geoms Drake's MJCF parser says it ignores ("... geom NAME will be ignored"): a construct it does not read.

Drake 1.51 warns, e.g. "The fromto tag for box is currently unsupported; geom box will be ignored", and
builds the body without that geom's mass.  Such a geom that weighs in MuJoCo gives Drake another robot: it is
an ``IGNORED_CONSTRUCT`` finding that changes the energy, so Drake casts no vote on the model
(:mod:`koenig_check.diagnosis.engine_limits`); a geom without mass only a note.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

from koenig_check.findings import Finding, Kind

_IGNORED = re.compile(r"\bgeom (\S+) will be ignored")


def ignored_geom(message: str) -> str | None:
    """The geom a Drake parser warning says is ignored, or ``None``.

    Parameters
    ----------
    message : str

    Returns
    -------
    str or None
    """
    match = _IGNORED.search(message)
    return match.group(1).rstrip(".;,") if match else None


def geom_mass(path: Path, name: str) -> float | None:
    """The mass a named geom gives its body in MuJoCo, or ``None`` when MuJoCo has no geom of that name.

    Parameters
    ----------
    path : Path
        The MJCF file.
    name : str

    Returns
    -------
    float or None
    """
    import mujoco

    try:
        spec = mujoco.MjSpec.from_file(str(path))
        geom = spec.geom(name)
        if geom is None:
            return None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            whole = float(spec.compile().body_mass.sum())
            geom.mass, geom.density = 0.0, 0.0
            without = float(spec.compile().body_mass.sum())
    except Exception:  # MuJoCo refuses the file alone (the loader's repairs): the mass is not known
        return None
    return whole - without


def ignored_geom_finding(path: Path, name: str, warning: str, lines: list[int]) -> Finding:
    """The finding of a geom Drake's parser ignores: a root cause when it weighs in MuJoCo (or its mass is unknown).

    Parameters
    ----------
    path : Path
        The MJCF file.
    name : str
        The geom, as Drake names it.
    warning : str
        Drake's warning, whole.
    lines : list of int
        The file's lines it names.

    Returns
    -------
    Finding
    """
    mass = geom_mass(path, name)
    values: dict[str, object] = {"mujoco": mass if mass is not None else "not known", "drake": "ignored"}
    if lines:
        values["lines"] = lines
    return Finding(
        Kind.IGNORED_CONSTRUCT,
        "drake",
        f"geom {name}",
        f"ignored by Drake's MJCF parser ({warning})",
        values,
        affects_energy=mass is None or mass > 0,
        root_cause=mass is None or mass > 0,
        cause="drake.mjcf.ignored-geom",
    )
