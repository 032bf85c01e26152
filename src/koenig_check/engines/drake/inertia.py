"""Links whose mass or inertia Drake's URDF parser replaced: a construct Drake reads differently.

Drake 1.51 checks every ``<inertial>`` it parses and, when the tensor fails its physical-validity
test (a negative principal moment, the triangle inequality ``A + B >= C`` broken) or cannot be
re-expressed about the centre of mass (a massless link with a non-zero inertia), logs a warning and
builds the link from other values (verified: allegro's finger links, romeo_small's arm, pr2 and hyq get
other principal moments; bolt's massless knee links get 1 kg), while MuJoCo (with ``--repair-inertia``:
the least change it accepts) and Pinocchio keep, or nearly keep, the file's values.  This module
compares, for the links Drake warned about, the file's values with the body Drake built; a difference
is a root cause (engine ``drake``) that explains Drake's departure.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.validate import parse_xml

#: Relative difference above which Drake is said to have replaced a link's mass or inertia.
REPLACED_RTOL = 1e-9
#: The values key of a replaced link's mass as Drake built it (read by :mod:`koenig_check.engines.drake.limits`).
MASS_IN_DRAKE = "mass in Drake"


def _file_inertials(path: Path) -> dict[str, tuple[float, np.ndarray, np.ndarray]]:
    """Link -> (mass, COM, central inertia in link axes) as the URDF file writes them."""
    try:
        robot = parse_xml(path).getroot()
    except (ET.ParseError, OSError):
        return {}
    out = {}
    for link in robot.findall("link"):
        inertial = link.find("inertial")
        if inertial is None:
            continue
        origin = inertial.find("origin")
        xyz = np.array([float(x) for x in (origin.get("xyz", "0 0 0") if origin is not None else "0 0 0").split()])
        rpy = [float(x) for x in (origin.get("rpy", "0 0 0") if origin is not None else "0 0 0").split()]
        mass_el, inertia_el = inertial.find("mass"), inertial.find("inertia")
        mass = float(mass_el.get("value", 0.0)) if mass_el is not None else 0.0
        keys = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
        xx, yy, zz, xy, xz, yz = (float(inertia_el.get(k, 0.0)) if inertia_el is not None else 0.0 for k in keys)
        tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        R = Rotation.from_euler("xyz", rpy).as_matrix()
        out[link.get("name", "")] = (mass, xyz, R @ tensor @ R.T)
    return out


def replaced_inertias(plant: Any, path: Path, links: list[str], segment_of: dict[str, str]) -> list[Finding]:
    """Root causes for the links whose mass or central inertia Drake built otherwise than the file says.

    Parameters
    ----------
    plant : pydrake.multibody.plant.MultibodyPlant
        Finalized.
    path : Path
        The URDF file.
    links : list of str
        Links Drake warned about while parsing.
    segment_of : dict of str to str
        Body -> the segment it belongs to.

    Returns
    -------
    list of Finding
    """
    if not links:
        return []
    file_values = _file_inertials(path)
    context = plant.CreateDefaultContext()
    out = []
    for link in dict.fromkeys(links):
        if link not in file_values or not plant.HasBodyNamed(link):
            continue
        mass, _, central = file_values[link]
        M = plant.GetBodyByName(link).CalcSpatialInertiaInBodyFrame(context)
        m = float(M.get_mass())
        c = np.asarray(M.get_com(), dtype=float)
        I_Bo = np.asarray(M.CalcRotationalInertia().CopyToFullMatrix3(), dtype=float)
        drake_central = I_Bo - m * (c @ c * np.eye(3) - np.outer(c, c))
        scale = max(float(np.abs(central).max()), float(np.abs(drake_central).max()), 1e-300)
        mass_changed = abs(m - mass) > REPLACED_RTOL * max(mass, m, 1e-300)
        if not mass_changed and np.abs(drake_central - central).max() <= REPLACED_RTOL * scale:
            continue
        out.append(
            Finding(
                Kind.INERTIA,
                "drake",
                f"link {link}",
                "Drake's URDF parser replaced an inertia it judges unphysical (its parser warning names the link)",
                {
                    "mass in the file": mass,
                    MASS_IN_DRAKE: m,
                    "moments in the file": np.round(np.linalg.eigvalsh(central), 12).tolist(),
                    "moments in Drake": np.round(np.linalg.eigvalsh(drake_central), 12).tolist(),
                },
                affects_energy=True,
                root_cause=True,
                segments=(segment_of[link],) if link in segment_of else (),
                cause="drake.urdf.replaced-inertia",
            )
        )
    return out
