"""MJCF → URDF from MuJoCo's compiled model: the robot MuJoCo simulates, written for URDF readers.

The compiled ``MjModel`` already has default classes, ``<include>``s, ``<frame>``s, mesh-derived inertias
and ``settotalmass`` applied, so every number written here is the one MuJoCo uses.  Each body becomes one
link with an explicit ``<inertial>`` (mass, centre of mass, full tensor in the link frame); each hinge a
``revolute`` (``continuous`` without a range), each slide a ``prismatic``, each jointless body a ``fixed``
joint.  No dummy links: a body with several joints, a ball joint or a free joint below the root cannot be
written and is refused (:class:`~koenig_check.export.carried.ExportRefusedError`, naming the joints).

Frames: a URDF joint sits at its child link's origin, an MJCF joint anywhere in its body (``pos``) and
with a reference angle ``ref`` (the file's pose is at ``q = ref``).  The link frame is the body frame
moved to the joint anchor, and the joint origin carries ``Rot(axis, -ref)`` (``Trans(-ref axis)``
for a slide), so that a coordinate ``q`` puts every link where MuJoCo puts its body.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.export.carried import ExportRefusedError, NotCarried
from koenig_check.export.geometry import Geom, model_geoms, relative_mesh_path
from koenig_check.export.model_extras import extras_not_carried
from koenig_check.export.transforms import (
    Pose,
    axis_motion,
    compose,
    inverse,
    matrix_to_rpy,
    number,
    numbers,
    quat_to_matrix,
    translation,
)

_HINGE, _SLIDE = int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)
_FREE, _BALL = int(mujoco.mjtJoint.mjJNT_FREE), int(mujoco.mjtJoint.mjJNT_BALL)
#: The URDF link standing for MuJoCo's world body (URDF readers take a link so named as the world).
WORLD_LINK = "world"


def body_names(model: mujoco.MjModel) -> list[str]:
    """The name of every body (``body<id>`` for an unnamed one), world first.

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    list of str
    """
    return [WORLD_LINK] + [model.body(b).name or f"body{b}" for b in range(1, model.nbody)]


def _refusals(model: mujoco.MjModel, joints: list[str], bodies: list[str]) -> list[NotCarried]:
    tops = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    out = []
    for b in range(1, model.nbody):
        n = int(model.body_jntnum[b])
        adr = int(model.body_jntadr[b])
        names = joints[adr : adr + n]
        kinds = [int(model.jnt_type[j]) for j in range(adr, adr + n)]
        if _BALL in kinds:
            ball = [names[i] for i, k in enumerate(kinds) if k == _BALL]
            out.append(NotCarried("ball joint", "joints " + ", ".join(ball), "URDF has no ball joint", True))
        elif n > 1:
            out.append(
                NotCarried(
                    "several joints in one body",
                    f"body {bodies[b]} (joints {', '.join(names)})",
                    "URDF gives each link one joint; splitting it would need massless dummy links",
                    True,
                )
            )
        elif _FREE in kinds and (len(tops) != 1 or b != tops[0]):
            out.append(
                NotCarried(
                    "free joint",
                    f"joint {names[0]} (body {bodies[b]})",
                    f"URDF holds one floating base, the single root link; this model has {len(tops)} root bodies",
                    True,
                )
            )
    return out


def _element(parent: ET.Element, tag: str, **attrib: str) -> ET.Element:
    return ET.SubElement(parent, tag, attrib)


def _origin(parent: ET.Element, pose: Pose) -> None:
    _element(parent, "origin", xyz=numbers(pose[0]), rpy=numbers(matrix_to_rpy(pose[1])))


def _inertial(link: ET.Element, model: mujoco.MjModel, b: int, frame: Pose) -> None:
    """The body's inertial in the link frame: COM and the full tensor with axes parallel to the link's."""
    com: Pose = (np.array(model.body_ipos[b], dtype=float), quat_to_matrix(model.body_iquat[b]))
    pos, rot = compose(inverse(frame), com)
    tensor = rot @ np.diag(np.asarray(model.body_inertia[b], dtype=float)) @ rot.T
    tensor = 0.5 * (tensor + tensor.T)
    inertial = _element(link, "inertial")
    _element(inertial, "origin", xyz=numbers(pos), rpy="0 0 0")
    _element(inertial, "mass", value=number(model.body_mass[b]))
    names = {"ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2), "izz": (2, 2)}
    _element(inertial, "inertia", **{k: number(tensor[i, j]) for k, (i, j) in names.items()})


def _shape(parent: ET.Element, geom: Geom, out_file: str | os.PathLike[str]) -> bool:
    """Write ``<geometry>``; ``False`` when URDF has no such shape."""
    s = geom.size
    if geom.shape == "sphere":
        _element(_element(parent, "geometry"), "sphere", radius=number(s[0]))
    elif geom.shape == "box":
        _element(_element(parent, "geometry"), "box", size=numbers(2 * s))
    elif geom.shape == "cylinder":
        _element(_element(parent, "geometry"), "cylinder", radius=number(s[0]), length=number(2 * s[1]))
    elif geom.shape == "mesh" and geom.mesh_file:
        attrib = {"filename": relative_mesh_path(geom.mesh_file, out_file)}
        if not np.allclose(geom.mesh_scale, 1.0):
            attrib["scale"] = numbers(geom.mesh_scale)
        _element(_element(parent, "geometry"), "mesh", **attrib)
    else:
        return False
    return True


def _geoms(
    link: ET.Element, geoms: list[Geom], frame: Pose, out_file: str | os.PathLike[str], skipped: list[Geom]
) -> None:
    for geom in geoms:
        pose = compose(inverse(frame), geom.pose)
        for tag in ("visual", "collision") if geom.collides else ("visual",):
            element = ET.Element(tag, {"name": geom.name})
            _origin(element, pose)
            if not _shape(element, geom, out_file):
                skipped.append(geom)
                break
            link.append(element)


def _joint(robot: ET.Element, model: mujoco.MjModel, j: int, name: str, drake_extensions: bool) -> ET.Element:
    kind = int(model.jnt_type[j])
    limited = bool(model.jnt_limited[j])
    urdf_type = "prismatic" if kind == _SLIDE else ("revolute" if limited else "continuous")
    joint = _element(robot, "joint", name=name, type=urdf_type)
    dof = int(model.jnt_dofadr[j])
    if limited or kind == _SLIDE:
        lo, hi = (float(v) for v in model.jnt_range[j]) if limited else (-1e16, 1e16)
        effort = float(np.abs(model.jnt_actfrcrange[j]).max()) if model.jnt_actfrclimited[j] else 0.0
        _element(joint, "limit", lower=number(lo), upper=number(hi), effort=number(effort), velocity="0")
    damping, friction = float(model.dof_damping[dof]), float(model.dof_frictionloss[dof])
    if damping or friction:
        _element(joint, "dynamics", damping=number(damping), friction=number(friction))
    if drake_extensions and model.dof_armature[dof]:
        _element(joint, "drake:rotor_inertia", value=number(model.dof_armature[dof]))
        _element(joint, "drake:gear_ratio", value="1")
    return joint


def write_urdf(
    model: mujoco.MjModel,
    out_file: str | os.PathLike[str],
    *,
    robot_name: str = "robot",
    drake_extensions: bool = False,
    model_dir: str | os.PathLike[str] | None = None,
) -> tuple[str, list[NotCarried]]:
    """Write a compiled MuJoCo model as URDF text.

    Parameters
    ----------
    model : mujoco.MjModel
        The compiled model (its numbers are the ones written).
    out_file : path
        Where the text will be written (mesh paths are made relative to its directory).
    robot_name : str
    drake_extensions : bool
        Write each joint's armature as Drake's ``drake:rotor_inertia`` (gear ratio 1).
    model_dir : path, optional
        Directory relative mesh paths of the model are read from.

    Returns
    -------
    text : str
        The URDF document.
    not_carried : list of NotCarried
        What the URDF does not hold (armature, equalities, tendons, actuators, geoms URDF has no shape
        for, the free root joint that the reader must restore as a floating base).

    Raises
    ------
    ExportRefusedError
        A ball joint, a body with several joints, or a free joint that is not the single root's.
    """
    joints = mujoco_joint_names(model)
    bodies = body_names(model)
    refused = _refusals(model, joints, bodies)
    if refused:
        raise ExportRefusedError(
            "URDF cannot hold " + "; ".join(f"{r.construct} ({r.element})" for r in refused), tuple(refused)
        )
    tops = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    floating = (
        len(tops) == 1 and model.body_jntnum[tops[0]] == 1 and model.jnt_type[model.body_jntadr[tops[0]]] == _FREE
    )
    robot = ET.Element("robot", {"name": robot_name})
    if drake_extensions:
        robot.set("xmlns:drake", "http://drake.mit.edu")
    geoms = model_geoms(model, model_dir)
    by_body: dict[int, list[Geom]] = {}
    for g in geoms:
        by_body.setdefault(g.body, []).append(g)
    skipped: list[Geom] = []
    not_carried: list[NotCarried] = []
    frames: dict[int, Pose] = {0: translation(np.zeros(3))}
    if not floating:
        world = _element(robot, "link", name=WORLD_LINK)
        _geoms(world, by_body.get(0, []), frames[0], out_file, skipped)
    elif by_body.get(0):
        not_carried.append(
            NotCarried(
                "world geoms",
                "geoms " + ", ".join(g.name for g in by_body[0]),
                "a floating-base URDF has no world link to hold static geoms",
            )
        )
    for b in range(1, model.nbody):
        parent = int(model.body_parentid[b])
        n = int(model.body_jntnum[b])
        j = int(model.body_jntadr[b]) if n else -1
        kind = int(model.jnt_type[j]) if n else -1
        body: Pose = (np.array(model.body_pos[b], dtype=float), quat_to_matrix(model.body_quat[b]))
        if kind in (_HINGE, _SLIDE):
            anchor = np.array(model.jnt_pos[j], dtype=float)
            ref = float(model.qpos0[model.jnt_qposadr[j]])
            frames[b] = translation(anchor)
            origin = compose(compose(body, frames[b]), axis_motion(model.jnt_axis[j], -ref, kind == _HINGE))
        else:
            frames[b] = translation(np.zeros(3))
            origin = body
        link = _element(robot, "link", name=bodies[b])
        _inertial(link, model, b, frames[b])
        _geoms(link, by_body.get(b, []), frames[b], out_file, skipped)
        if kind == _FREE:
            not_carried.append(
                NotCarried(
                    "floating base",
                    f"joint {joints[j]}",
                    "URDF has no free joint: load this file with a floating base (koenig-check --floating, "
                    "Pinocchio JointModelFreeFlyer); q of the free joint is the root link's pose",
                )
            )
            continue
        origin = compose(inverse(frames[parent]), origin)
        if kind in (_HINGE, _SLIDE):
            joint = _joint(robot, model, j, joints[j], drake_extensions)
            _element(joint, "axis", xyz=numbers(model.jnt_axis[j]))
        else:
            joint = _element(robot, "joint", name=f"{bodies[b]}_fixed", type="fixed")
            if model.body_mocapid[b] >= 0:
                not_carried.append(NotCarried("mocap", f"body {bodies[b]}", "written as a fixed link"))
        _element(joint, "parent", link=bodies[parent])
        _element(joint, "child", link=bodies[b])
        _origin(joint, origin)
    not_carried += _dof_not_carried(model, joints, drake_extensions)
    not_carried += extras_not_carried(model, "URDF")
    if skipped:
        kinds = sorted({g.shape for g in skipped})
        not_carried.append(
            NotCarried(
                "geom shape",
                "geoms " + ", ".join(g.name for g in skipped),
                f"URDF has no {'/'.join(kinds)} shape (the inertia is written explicitly, so the mass matrix is kept)",
            )
        )
    ET.indent(robot)
    return ET.tostring(robot, encoding="unicode") + "\n", not_carried


def _dof_not_carried(model: mujoco.MjModel, joints: list[str], drake_extensions: bool) -> list[NotCarried]:
    out = []
    for j in range(model.njnt):
        dof = int(model.jnt_dofadr[j])
        if model.dof_armature[dof] and int(model.jnt_type[j]) in (_HINGE, _SLIDE):
            reason = (
                "written as drake:rotor_inertia, which only Drake reads"
                if drake_extensions
                else "URDF has no armature (rotor inertia); --drake-extensions writes Drake's drake:rotor_inertia"
            )
            out.append(NotCarried("armature", f"joint {joints[j]}", f"{model.dof_armature[dof]:g}: {reason}", True))
        if model.jnt_stiffness[j]:
            out.append(NotCarried("stiffness", f"joint {joints[j]}", "URDF has no joint spring"))
    return out
