"""The catalogued causes found on a user's robot when PyBullet reads it (:mod:`koenig_check.engines.pybullet.causes`).

* links without ``<inertial>`` that PyBullet gave 1 kg and a unit inertia: a root cause of PyBullet's departure on
  the segments they belong to (the root link's only when the base floats; on a fixed base, a note that it would);
* the loading options users choose (``loadURDF`` without ``URDF_USE_INERTIA_FROM_FILE``, with
  ``URDF_MERGE_FIXED_LINKS``), each measured on this robot: the file loaded again with the option, its mass matrix
  at the reference pose against the one checked, the change said when it is above PyBullet's precision;
* a refusal explained: an MJCF, a mesh file that does not exist;
* an inertia that breaks the triangle inequality, which PyBullet sets to zero (MuJoCo refuses such a file unless
  asked to repair it: not a catalogued cause, whose fixture every engine must load as it is).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.pybullet import SPEC
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.urdf_links import links_without_inertial

#: The value a zeroed-inertia finding carries PyBullet's moments under (what its parser limit reads).
MOMENTS_IN_PYBULLET = "moments in PyBullet"
#: The cause of an inertia PyBullet set to zero (:func:`zeroed_findings`).
ZEROED = "pybullet.urdf.zeroed-inertia"
#: The loading options measured on each robot: cause id -> the flags its users pass.
OPTIONS = {
    "pybullet.urdf.inertia-from-collision": (),
    "pybullet.urdf.merge-fixed-links": ("URDF_USE_INERTIA_FROM_FILE", "URDF_MERGE_FIXED_LINKS"),
}


def _urdf(path: Path) -> ET.Element | None:
    try:
        return ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return None


def missing_meshes(path: Path, package_dirs: tuple[Path, ...]) -> list[str]:
    """The mesh files a URDF names that exist nowhere PyBullet looks (its folder, the package folders).

    Parameters
    ----------
    path : Path
    package_dirs : tuple of Path

    Returns
    -------
    list of str
        As written in the file.
    """
    robot = _urdf(path)
    if robot is None:
        return []
    out = []
    for mesh in robot.iter("mesh"):
        name = mesh.get("filename", "")
        rest = name.removeprefix("package://").removeprefix("file://")
        places = [Path(rest)] if Path(rest).is_absolute() else [path.parent / rest, *(d / rest for d in package_dirs)]
        if name and not any(p.is_file() for p in places):
            out.append(name)
    return out


def inertial_findings(engine: Any, path: Path) -> list[Finding]:
    """Links without ``<inertial>`` to which PyBullet gave its default mass, where they move.

    Parameters
    ----------
    engine : PyBulletEngine
    path : Path

    Returns
    -------
    list of Finding
    """
    tree = engine.tree
    bare = set(links_without_inertial(path))
    segment = {}
    for k, rows in enumerate(engine._members):
        segment.update({int(r): engine.segment_names[k] for r in rows})
    moving = [r for r in range(1, len(tree.link_names)) if tree.link_names[r] in bare and r in segment]
    out = []
    if moving:
        names = [tree.link_names[r] for r in moving]
        out.append(
            Finding(
                Kind.MASS,
                "pybullet",
                "links " + ", ".join(names),
                "PyBullet gives a link without <inertial> 1 kg and a unit inertia",
                {"links": names, "pybullet mass": [float(tree.mass[r]) for r in moving]},
                affects_energy=True,
                root_cause=True,
                segments=tuple(dict.fromkeys(segment[r] for r in moving)),
                cause="pybullet.urdf.link-without-inertial",
                tag="links",
            )
        )
    root = tree.link_names[0]
    if root in bare:
        floating = engine.state_map.base is not None
        out.append(
            Finding(
                Kind.MASS if floating else Kind.LOAD,
                "pybullet",
                f"link {root}",
                "PyBullet gives the floating root link without <inertial> 1 kg and a unit inertia"
                if floating
                else "the root link has no <inertial>: welded to the world it is static, but PyBullet gives it "
                "1 kg and a unit inertia when the base floats",
                {"links": [root], "pybullet mass when floating": 1.0},
                affects_energy=floating and 0 in segment,
                root_cause=floating and 0 in segment,
                segments=(segment[0],) if 0 in segment else (),
                cause="pybullet.urdf.floating-root-without-inertial",
                tag="link",
            )
        )
    return out


def _file_moments(link: ET.Element) -> np.ndarray | None:
    """The principal moments of a URDF link's ``<inertia>`` as written (None without one)."""
    inertia = link.find("inertial/inertia")
    if inertia is None:
        return None
    value = {k: float(inertia.get(k, "0") or 0) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
    tensor = np.array(
        [
            [value["ixx"], value["ixy"], value["ixz"]],
            [value["ixy"], value["iyy"], value["iyz"]],
            [value["ixz"], value["iyz"], value["izz"]],
        ]
    )
    return np.linalg.eigvalsh(tensor)


def _negligible(engine: Any, mj_model: Any) -> float:
    """An inertia no larger than PyBullet's precision times its M's largest entry at the reference pose (kg m²).

    Setting such an inertia to zero changes no entry of M by more than PyBullet's round-off.
    """
    qpos0 = np.asarray(mj_model.qpos0, dtype=float)[None]
    return float(SPEC.precision * np.abs(engine.mass_matrix(qpos0)[0]).max())


def zeroed_findings(engine: Any, path: Path, mj_model: Any) -> list[Finding]:
    """Links whose inertia breaks the triangle inequality (A + B < C): PyBullet sets it to zero (measured on 3.2.7).

    Such a link is another robot than the file's in PyBullet: the finding shows one of its parser limits
    (:mod:`koenig_check.engines.pybullet.limits`), so that PyBullet casts no vote on the model.

    Parameters
    ----------
    engine : PyBulletEngine
    path : Path
    mj_model : mujoco.MjModel
        MuJoCo's model of the file (the reference pose, where an inertia too small to matter is judged).

    Returns
    -------
    list of Finding
        One per link, unless its inertia as written changes M by no more than PyBullet's round-off.
    """
    robot = _urdf(path)
    if robot is None:
        return []
    tree = engine.tree
    segment = {int(r): engine.segment_names[k] for k, rows in enumerate(engine._members) for r in rows}
    rows = {name: r for r, name in enumerate(tree.link_names)}
    out = []
    for link in robot.findall("link"):
        moments, row = _file_moments(link), rows.get(link.get("name", ""), -1)
        if moments is None or row not in segment or tree.principal[row].any():
            continue
        if not moments[0] + moments[1] < moments[2]:  # sorted: A + B >= C holds, PyBullet keeps it
            continue
        if np.abs(moments).max() <= _negligible(engine, mj_model):  # round-off (icub's 1e-20): nothing lost
            continue
        out.append(
            Finding(
                Kind.INERTIA,
                "pybullet",
                f"link {tree.link_names[row]}",
                "PyBullet sets an inertia that breaks the triangle inequality (A + B < C) to zero",
                {
                    "mass in PyBullet": float(tree.mass[row]),
                    "moments in the file": np.round(moments, 12).tolist(),
                    MOMENTS_IN_PYBULLET: tree.principal[row].tolist(),
                },
                affects_energy=True,
                root_cause=True,
                segments=(segment[row],) if row in segment else (),
                cause=ZEROED,
                tag="link",
            )
        )
    return out


def option_findings(engine: Any, source: Any, mj_model: Any) -> list[Finding]:
    """Each loading option of :data:`OPTIONS` measured on this robot: its change of M at the reference pose.

    Parameters
    ----------
    engine : PyBulletEngine
        The robot as checked (``URDF_USE_INERTIA_FROM_FILE``).
    source : ModelSource
    mj_model : mujoco.MjModel

    Returns
    -------
    list of Finding
        One ``LOAD`` finding per option that changes M by more than PyBullet's precision (its spec's), relative
        to M's largest entry, carrying the cause's id and the change.
    """
    from koenig_check.engines.pybullet.adapter import PyBulletEngine
    from koenig_check.engines.pybullet.client import Client, PyBulletLoadError
    from koenig_check.engines.pybullet.state_map import PyBulletStateMap, pair_joints
    from koenig_check.engines.pybullet.tree import read_tree

    qpos0 = np.asarray(mj_model.qpos0, dtype=float)[None]
    checked = engine.mass_matrix(qpos0)[0]
    scale = float(np.abs(checked).max())
    floating = engine.state_map.base is not None
    out = []
    for cause_id, flags in OPTIONS.items():
        client = Client(source.package_dirs[0] if source.package_dirs else None)
        try:
            body = client.load_urdf(Path(source.path), floating, flags)
            tree = read_tree(client, body)
            pairs = pair_joints(mj_model, tree, str(source.path), floating)
            state_map = PyBulletStateMap(pairs, tree, mj_model.nq, mj_model.nv)
            other = PyBulletEngine(client, body, tree, state_map, engine.path, qpos0[0]).mass_matrix(qpos0)[0]
        except (PyBulletLoadError, ValueError, ZeroDivisionError):
            continue  # the option cannot even load this robot: nothing to size
        finally:
            client.close()
        change = float(np.abs(other - checked).max()) / max(scale, float(np.abs(other).max()), 1e-300)
        if change > SPEC.precision:
            words = "without URDF_USE_INERTIA_FROM_FILE" if not flags else "with URDF_MERGE_FIXED_LINKS"
            out.append(
                Finding(
                    Kind.LOAD,
                    "pybullet",
                    "loadURDF flags",
                    f"PyBullet's loadURDF {words} would change M by {100 * change:.2g} % on this robot",
                    {"M change": change, "flags": list(flags)},
                    cause=cause_id,
                )
            )
    return out
