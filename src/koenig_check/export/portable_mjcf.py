"""MJCF that every engine reads as MuJoCo reads the original, written from MuJoCo's compiled model.

No ``<include>``, no default classes, no ``<frame>``: every body's pose and explicit ``<inertial>`` (mass,
centre of mass, principal moments and their orientation), every joint's position, axis, range, armature,
damping, stiffness and friction loss written out.  Every body with mass gets an explicit ``<inertial>``;
a massless body gets none and its geoms ``mass="0"`` under ``inertiafromgeom="auto"``, so that every
reader derives a zero mass (Drake refuses a zero-mass ``<inertial>``), and no reader derives a mass from
geometry elsewhere.  A joint's ``ref`` is folded into its body's pose where the body has that
one joint, so that a reader ignoring ``ref`` still puts every body where MuJoCo does at the same ``q``.
Mesh geoms are written only in the formats every reader's MJCF parser reads (``mesh_formats``, from the
engines' declarations: Drake's refuses the whole file for a mesh that is not ``.obj``); the others are listed
as not carried.  For readers that read any mesh (no ``mesh_formats``), every mesh MuJoCo read is written.
Several root bodies are wrapped under one jointless root at the identity (unless one is free or mocap: MuJoCo
holds those only at the top level).  Numbers are written at full precision (Python's shortest repr, which
parses back to the same double).  Joint equalities and keyframes are kept; tendons, actuators, sensors and
other equalities are listed as not carried.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.engines.registry import label
from koenig_check.export.carried import NotCarried
from koenig_check.export.geometry import Geom, model_geoms, relative_mesh_path
from koenig_check.export.model_extras import extras_not_carried
from koenig_check.export.transforms import (
    Pose,
    axis_motion,
    compose,
    matrix_to_quat,
    number,
    numbers,
    quat_to_matrix,
    translation,
)

_TYPES = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}
_WRITABLE = ("plane", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh")


def _body_pose(model: mujoco.MjModel, b: int) -> tuple[Pose, bool]:
    """The body's pose in its parent with a lone joint's ``ref`` folded in; whether it was folded."""
    pose: Pose = (np.array(model.body_pos[b], dtype=float), quat_to_matrix(model.body_quat[b]))
    if model.body_jntnum[b] != 1:
        return pose, False
    j = int(model.body_jntadr[b])
    kind = int(model.jnt_type[j])
    ref = float(model.qpos0[model.jnt_qposadr[j]]) if kind in (2, 3) else 0.0
    if not ref:
        return pose, False
    anchor = np.array(model.jnt_pos[j], dtype=float)
    motion = axis_motion(model.jnt_axis[j], -ref, kind == 3)
    return compose(compose(compose(pose, translation(anchor)), motion), translation(-anchor)), True


def _unused(name: str, names: list[str]) -> str:
    """``name``, prefixed with underscores until no body has it."""
    while name in names:
        name = "_" + name
    return name


def _refusing(geom: Geom, mesh_formats: Mapping[str, tuple[str, ...]]) -> list[str]:
    """The readers whose MJCF parser refuses a mesh geom's file format."""
    suffix = Path(geom.mesh_file).suffix.lower()
    return [e for e, formats in mesh_formats.items() if suffix not in formats]


def _why(geom: Geom, mesh_formats: Mapping[str, tuple[str, ...]]) -> str:
    if geom.shape != "mesh":
        return f"no {geom.shape} shape written"
    if not geom.mesh_file:
        return "mesh without a file"
    refusing = _refusing(geom, mesh_formats)
    read = "/".join(sorted({f for e in refusing for f in mesh_formats[e]}))
    parsers = (
        f"{label(refusing[0])}'s MJCF parser refuses"
        if len(refusing) == 1
        else ("the MJCF parsers of " + " and ".join(label(e) for e in refusing) + " refuse")
    )
    return f"mesh not {read}, which {parsers}; --engines without {','.join(refusing)} writes it"


def _written(geom: Geom, mesh_formats: Mapping[str, tuple[str, ...]]) -> bool:
    """Whether a geom is written: a shape MJCF holds, a mesh with its file in a format every reader reads."""
    if geom.shape not in _WRITABLE:
        return False
    if geom.shape != "mesh":
        return True
    return bool(geom.mesh_file) and not _refusing(geom, mesh_formats)


def _geom(parent: ET.Element, geom: Geom, meshes: dict[str, str], out_file: str | os.PathLike[str]) -> None:
    attrib = {
        "name": geom.name,
        "type": geom.shape,
        "pos": numbers(geom.pose[0]),
        "quat": numbers(matrix_to_quat(geom.pose[1])),
    }
    if geom.shape == "mesh":
        key = relative_mesh_path(geom.mesh_file, out_file) + "|" + numbers(geom.mesh_scale)
        attrib["mesh"] = meshes.setdefault(key, f"mesh{len(meshes)}")
    else:
        attrib["size"] = numbers(geom.size)
    attrib["rgba"] = numbers(geom.rgba)
    attrib["mass"] = "0"
    attrib["contype"] = "1" if geom.collides else "0"
    attrib["conaffinity"] = "1" if geom.collides else "0"
    ET.SubElement(parent, "geom", attrib)


def _joint(body: ET.Element, model: mujoco.MjModel, j: int, name: str, folded: bool) -> None:
    kind = int(model.jnt_type[j])
    if kind == 0:
        ET.SubElement(body, "freejoint", {"name": name})
        return
    dof = int(model.jnt_dofadr[j])
    attrib = {"name": name, "type": _TYPES[kind], "pos": numbers(model.jnt_pos[j])}
    if kind in (2, 3):
        attrib["axis"] = numbers(model.jnt_axis[j])
        ref = float(model.qpos0[model.jnt_qposadr[j]])
        if ref and not folded:
            attrib["ref"] = number(ref)
        attrib["springref"] = number(model.qpos_spring[model.jnt_qposadr[j]])
    attrib["limited"] = "true" if model.jnt_limited[j] else "false"
    if model.jnt_limited[j]:
        attrib["range"] = numbers(model.jnt_range[j])
    attrib["armature"] = number(model.dof_armature[dof])
    attrib["damping"] = number(model.dof_damping[dof])
    attrib["frictionloss"] = number(model.dof_frictionloss[dof])
    attrib["stiffness"] = number(model.jnt_stiffness[j])
    ET.SubElement(body, "joint", attrib)


def _inertial(body: ET.Element, model: mujoco.MjModel, b: int) -> None:
    ET.SubElement(
        body,
        "inertial",
        {
            "pos": numbers(model.body_ipos[b]),
            "quat": numbers(model.body_iquat[b]),
            "mass": number(model.body_mass[b]),
            "diaginertia": numbers(model.body_inertia[b]),
        },
    )


def write_portable_mjcf(
    model: mujoco.MjModel,
    out_file: str | os.PathLike[str],
    *,
    model_name: str = "robot",
    model_dir: str | os.PathLike[str] | None = None,
    mesh_formats: Mapping[str, tuple[str, ...]] | None = None,
) -> tuple[str, list[NotCarried]]:
    """Write a compiled MuJoCo model as one self-contained MJCF document.

    Parameters
    ----------
    model : mujoco.MjModel
    out_file : path
        Where the text will be written (mesh paths are made relative to its directory).
    model_name : str
    model_dir : path, optional
        Directory relative mesh paths of the model are read from.
    mesh_formats : mapping of str to tuple of str, optional
        Reader -> the mesh suffixes its MJCF parser reads, for the readers that read only some
        (:func:`koenig_check.engines.registry.mjcf_mesh_formats`: Drake's refuses a file with a mesh that is
        not ``.obj``).  Default: every reader reads every mesh MuJoCo read (STL, MSH, ...).

    Returns
    -------
    text : str
    not_carried : list of NotCarried
    """
    joints = mujoco_joint_names(model)
    names = ["world"] + [model.body(b).name or f"body{b}" for b in range(1, model.nbody)]
    root = ET.Element("mujoco", {"model": model_name})
    ET.SubElement(root, "compiler", {"angle": "radian", "inertiafromgeom": "auto", "autolimits": "false"})
    ET.SubElement(root, "option", {"timestep": number(model.opt.timestep), "gravity": numbers(model.opt.gravity)})
    asset = ET.SubElement(root, "asset")
    world = ET.SubElement(root, "worldbody")
    meshes: dict[str, str] = {}
    not_carried: list[NotCarried] = []
    by_body: dict[int, list[Geom]] = {}
    skipped: list[Geom] = []
    readers = mesh_formats or {}
    for g in model_geoms(model, model_dir):
        if _written(g, readers):
            by_body.setdefault(g.body, []).append(g)
        else:
            skipped.append(g)
    tops = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    free_top = any(model.jnt_type[model.body_jntadr[b]] == 0 for b in tops if model.body_jntnum[b])
    free_top = free_top or any(model.body_mocapid[b] >= 0 for b in tops)
    elements: dict[int, ET.Element] = {0: world}
    posed: list[str] = []
    massless: list[str] = []
    if len(tops) > 1 and not free_top:
        wrapper = _unused("root", names)
        elements[0] = ET.SubElement(world, "body", {"name": wrapper, "pos": "0 0 0", "quat": "1 0 0 0"})
    elif len(tops) > 1:
        not_carried.append(
            NotCarried(
                "several root bodies",
                "bodies " + ", ".join(names[b] for b in tops),
                "kept at the top level: MuJoCo holds free joints and mocap bodies only as root bodies",
            )
        )
    for g in by_body.get(0, []):
        _geom(world, g, meshes, out_file)
    for b in range(1, model.nbody):
        pose, folded = _body_pose(model, b)
        parent = elements[int(model.body_parentid[b])]
        if model.body_jntnum[b] > 1 and np.any(pose[0]):
            parent = ET.SubElement(
                parent,
                "body",
                {
                    "name": _unused(f"{names[b]}_pose", names),
                    "pos": numbers(pose[0]),
                    "quat": numbers(matrix_to_quat(pose[1])),
                },
            )
            pose = translation(np.zeros(3))
            posed.append(names[b])
        body = ET.SubElement(
            parent, "body", {"name": names[b], "pos": numbers(pose[0]), "quat": numbers(matrix_to_quat(pose[1]))}
        )
        if model.body_mocapid[b] >= 0:
            body.set("mocap", "true")
        elements[b] = body
        if model.body_mass[b] > 0:
            _inertial(body, model, b)
        elif np.any(model.body_inertia[b] > 0):
            massless.append(names[b])
        for j in range(int(model.body_jntadr[b]), int(model.body_jntadr[b]) + int(model.body_jntnum[b])):
            _joint(body, model, j, joints[j], folded)
        for g in by_body.get(b, []):
            _geom(body, g, meshes, out_file)
    for key, name in meshes.items():
        file, scale = key.split("|")
        ET.SubElement(asset, "mesh", {"name": name, "file": file, "scale": scale})
    if massless:
        not_carried.append(
            NotCarried(
                "rotational inertia of a massless body",
                "bodies " + ", ".join(massless),
                "not written: Drake's MJCF parser aborts on an <inertial> of mass 0",
                True,
            )
        )
    if posed:
        not_carried.append(
            NotCarried(
                "body pose of a multi-joint body",
                "bodies " + ", ".join(posed),
                "the pose is written on a massless parent body '<name>_pose' welded to the parent: Drake's MJCF "
                "parser drops the body's pos for the first of several joints",
            )
        )
    _equalities(root, model, joints)
    _keyframes(root, model)
    if skipped:
        not_carried.append(
            NotCarried(
                "geom shape",
                "geoms " + ", ".join(g.name for g in skipped),
                "not written (" + "/".join(sorted({_why(g, readers) for g in skipped})) + "); the inertia is explicit",
            )
        )
    not_carried += [
        n for n in extras_not_carried(model, "the portable MJCF", keep_equalities=True) if n.construct != "keyframe"
    ]
    ET.indent(root)
    return ET.tostring(root, encoding="unicode") + "\n", not_carried


def _equalities(root: ET.Element, model: mujoco.MjModel, joints: list[str]) -> None:
    rows = [i for i in range(model.neq) if int(model.eq_type[i]) == int(mujoco.mjtEq.mjEQ_JOINT)]
    if not rows:
        return
    equality = ET.SubElement(root, "equality")
    for i in rows:
        attrib = {"joint1": joints[int(model.eq_obj1id[i])], "polycoef": numbers(model.eq_data[i, :5])}
        if model.eq_obj2id[i] >= 0:
            attrib["joint2"] = joints[int(model.eq_obj2id[i])]
        attrib["active"] = "true" if model.eq_active0[i] else "false"
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_EQUALITY, i)
        if name:
            attrib["name"] = name
        ET.SubElement(equality, "joint", attrib)


def _keyframes(root: ET.Element, model: mujoco.MjModel) -> None:
    if not model.nkey:
        return
    keyframe = ET.SubElement(root, "keyframe")
    for k in range(model.nkey):
        attrib = {"qpos": numbers(model.key_qpos[k]), "qvel": numbers(model.key_qvel[k])}
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_KEY, k)
        if name:
            attrib["name"] = name
        ET.SubElement(keyframe, "key", attrib)
