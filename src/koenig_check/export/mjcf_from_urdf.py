"""URDF → MJCF: MuJoCo's own URDF import, written at full precision with nothing derived from geometry.

The URDF is compiled by the project's loader (``inertiafromgeom`` false: a link without ``<inertial>``
has no mass, as in Pinocchio; meshes resolved; ``--repair-inertia`` applied and recorded) and the
compiled model is written by :func:`~koenig_check.export.portable_mjcf.write_portable_mjcf`, whose numbers
parse back to the same doubles.  What the import changed is listed: links fused into their parents
(MuJoCo's ``fusestatic``) and inertias repaired for MuJoCo.
"""

from __future__ import annotations

import os
from collections.abc import Mapping

import mujoco

from koenig_check.engines.mujoco.mass_changes import BodyFinding
from koenig_check.export.carried import NotCarried
from koenig_check.export.portable_mjcf import write_portable_mjcf
from koenig_check.findings import Finding, Kind


def import_not_carried(findings: list[Finding], body_findings: list[BodyFinding]) -> list[NotCarried]:
    """What MuJoCo's import of a URDF changed, from the loader's findings.

    Parameters
    ----------
    findings : list of Finding
        The loader's model-level findings.
    body_findings : list of (str, Finding)
        The loader's per-body findings (repairs, compiler changes).

    Returns
    -------
    list of NotCarried
    """
    out = []
    for f in findings:
        if f.kind == Kind.LOAD and "fused" in f.values:
            fused = list(f.values["fused"])
            out.append(
                NotCarried(
                    "fixed links",
                    "links " + ", ".join(fused),
                    "fused into their parents by MuJoCo's import (fusestatic): their mass is in the parent's "
                    "inertial, their frames are not written",
                )
            )
    for body, f in body_findings:
        if f.kind in (Kind.REPAIR, Kind.COMPILER) and f.affects_energy:
            out.append(NotCarried("inertia changed", f"link {body}", f.message(), True))
    return out


def write_mjcf_from_urdf(
    model: mujoco.MjModel,
    findings: list[Finding],
    body_findings: list[BodyFinding],
    out_file: str | os.PathLike[str],
    *,
    model_name: str = "robot",
    model_dir: str | os.PathLike[str] | None = None,
    mesh_formats: Mapping[str, tuple[str, ...]] | None = None,
) -> tuple[str, list[NotCarried]]:
    """Write MuJoCo's import of a URDF as MJCF.

    Parameters
    ----------
    model : mujoco.MjModel
        The URDF compiled by :func:`koenig_check.engines.mujoco.loader.load_mujoco`.
    findings, body_findings
        What the loader found (fused links, repairs).
    out_file : path
    model_name : str
    model_dir : path, optional
    mesh_formats : mapping of str to tuple of str, optional
        The mesh formats of the readers that read only some (see :func:`write_portable_mjcf`).

    Returns
    -------
    text : str
    not_carried : list of NotCarried
    """
    text, not_carried = write_portable_mjcf(
        model, out_file, model_name=model_name, model_dir=model_dir, mesh_formats=mesh_formats
    )
    return text, import_not_carried(findings, body_findings) + not_carried
