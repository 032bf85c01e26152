"""MuJoCo's joints paired with Pinocchio's by name, never by index (composites, unnamed joints, kinds checked)."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import pinocchio as pin

from koenig_check.engines.canonical import mujoco_joint_names, pinocchio_body_name
from koenig_check.engines.errors import JointMismatch
from koenig_check.engines.pinocchio.planar import planar_targets

_MJ_KIND = {
    mujoco.mjtJoint.mjJNT_FREE: "free",
    mujoco.mjtJoint.mjJNT_BALL: "ball",
    mujoco.mjtJoint.mjJNT_SLIDE: "slide",
    mujoco.mjtJoint.mjJNT_HINGE: "hinge",
}
_PIN_KIND = {
    "JointModelFreeFlyer": "free",
    "JointModelSpherical": "ball",
    "JointModelRX": "revolute",
    "JointModelRY": "revolute",
    "JointModelRZ": "revolute",
    "JointModelRevoluteUnaligned": "revolute",
    "JointModelRUBX": "unbounded",
    "JointModelRUBY": "unbounded",
    "JointModelRUBZ": "unbounded",
    "JointModelRevoluteUnboundedUnaligned": "unbounded",
    "JointModelPX": "prismatic",
    "JointModelPY": "prismatic",
    "JointModelPZ": "prismatic",
    "JointModelPrismaticUnaligned": "prismatic",
    "JointModelPlanar": "planar",
}
_COMPATIBLE = {"free": {"free"}, "ball": {"ball"}, "hinge": {"revolute", "unbounded"}, "slide": {"prismatic"}}
_COMPOSITE_PREFIX = "Composite_"


@dataclass(frozen=True)
class JointPair:
    """One MuJoCo joint and the Pinocchio (sub-)joint it maps to.

    Parameters
    ----------
    name : str
        Canonical (MuJoCo) joint name.
    kind : str
        MuJoCo type: ``"free"``, ``"ball"``, ``"hinge"`` or ``"slide"``.
    pin_kind : str
        ``"free"``, ``"ball"``, ``"revolute"``, ``"unbounded"`` (cos, sin), ``"prismatic"`` or ``"planar"``
        (one of the three MuJoCo joints of a URDF planar joint: :mod:`~koenig_check.engines.pinocchio.planar`).
    body : str
        MuJoCo body carrying the joint.
    qadr, vadr : int
        Canonical position/velocity addresses.
    pin_joint : int
        Pinocchio joint index (the composite's index for a sub-joint).
    pin_sub : int
        Position inside a composite joint, ``-1`` for a plain joint.
    pin_qadr, pin_vadr : int
        Pinocchio position/velocity addresses (of the planar joint for its three MuJoCo joints).
    q_offset : float
        ``q_pin = q_canonical - q_offset`` (hinge/slide only).
    """

    name: str
    kind: str
    pin_kind: str
    body: str
    qadr: int
    vadr: int
    pin_joint: int
    pin_sub: int
    pin_qadr: int
    pin_vadr: int
    q_offset: float = 0.0


def _pin_leaves(model: pin.Model, i: int) -> list[tuple[int, pin.JointModel]]:
    """Return ``[(sub_index, joint_model)]`` of a Pinocchio joint (one entry unless composite)."""
    joint = model.joints[i]
    if joint.shortname() == "JointModelComposite":
        return list(enumerate(joint.extract().joints))
    return [(-1, joint)]


def match_joints(mj_model: mujoco.MjModel, pin_model: pin.Model, path: str = "<model>") -> list[JointPair]:
    """Pair every MuJoCo joint with a Pinocchio (sub-)joint by name.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    pin_model : pinocchio.Model
    path : str
        File name for error messages.

    Returns
    -------
    list of JointPair
        In canonical (MuJoCo) order.

    Raises
    ------
    JointMismatch
        Listing the joints found in only one engine and those whose types are incompatible.
    """
    names = mujoco_joint_names(mj_model)
    index = {n: j for j, n in enumerate(names)}
    for j in range(mj_model.njnt):
        # Pinocchio names an unnamed <freejoint/> "<body>_free" but an unnamed <joint type="free"/>
        # "<body>Joint_<k>"; MuJoCo's compiled model keeps no trace of which one the file wrote.
        if not mj_model.joint(j).name and mj_model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            body = int(mj_model.jnt_bodyid[j])
            bname = pinocchio_body_name(mj_model, body)
            index.setdefault(f"{bname}Joint_{j - int(mj_model.body_jntadr[body])}", j)
    pairs: dict[int, JointPair] = {}
    only_pin: list[str] = []
    kind_mismatch: list[str] = []
    seen: set[int] = set()
    for i in range(1, pin_model.njoints):
        pname = pin_model.names[i]
        leaves = _pin_leaves(pin_model, i)
        if leaves[0][0] >= 0:  # composite: sub-joints follow the first joint's body in order
            first = pname[len(_COMPOSITE_PREFIX) :] if pname.startswith(_COMPOSITE_PREFIX) else pname
            if first not in index:
                only_pin.append(pname)
                continue
            body = int(mj_model.jnt_bodyid[index[first]])
            start, count = int(mj_model.body_jntadr[body]), int(mj_model.body_jntnum[body])
            if index[first] != start or count != len(leaves):
                only_pin.append(pname)
                continue
            targets = list(range(start, start + count))
        elif pname not in index and leaves[0][1].shortname() == "JointModelPlanar":
            found = planar_targets(mj_model, index, pname)  # URDF planar: MuJoCo's <name>_TX, _TY, _RZ
            if found is None:
                only_pin.append(pname)
                continue
            targets, leaves = found, leaves * 3  # kinds and axes checked by planar_targets
        else:
            if pname not in index:
                only_pin.append(pname)
                continue
            targets = [index[pname]]
        for (sub, leaf), j in zip(leaves, targets, strict=True):
            seen.add(j)
            kind = _MJ_KIND[mujoco.mjtJoint(mj_model.jnt_type[j])]
            pin_kind = _PIN_KIND.get(leaf.shortname(), leaf.shortname())
            if pin_kind not in _COMPATIBLE[kind] and not (pin_kind == "planar" and pname not in index):
                kind_mismatch.append(f"{names[j]}: mujoco {kind} vs pinocchio {leaf.shortname()}")
                continue
            pairs[j] = JointPair(
                name=names[j],
                kind=kind,
                pin_kind=pin_kind,
                body=mj_model.body(int(mj_model.jnt_bodyid[j])).name,
                qadr=int(mj_model.jnt_qposadr[j]),
                vadr=int(mj_model.jnt_dofadr[j]),
                pin_joint=i,
                pin_sub=sub,
                pin_qadr=int(leaf.idx_q),
                pin_vadr=int(leaf.idx_v),
            )
    only_mj = [names[j] for j in range(mj_model.njnt) if j not in seen]
    if only_mj or only_pin or kind_mismatch:
        raise JointMismatch(path, only_mj, only_pin, kind_mismatch)
    return [pairs[j] for j in range(mj_model.njnt)]
