"""The Drake state map: canonical (MuJoCo) (q, q̇) <-> Drake (q, v), joint by joint, matched by name.

Drake 1.51's conventions (verified against MuJoCo's energy and kinematics):

* ``QuaternionFloatingJoint``: ``q = (qw, qx, qy, qz, x, y, z)`` (world <- body and the body origin
  in the world), ``v = (ω_WB, v_WB)`` *both in the world frame*; MuJoCo's free joint has
  ``qpos = (x, y, z, qw, qx, qy, qz)`` and ``qvel = (v_world, ω_body)``, so ``ω_W = R ω_B``.
* ``BallRpyJoint`` (what Drake makes of an MJCF ``ball``): ``q`` = roll, pitch, yaw (extrinsic
  x-y-z angles of the child relative to the parent frame), ``v`` = the angular velocity *in the
  parent frame*; MuJoCo's ball has a quaternion and the angular velocity in the child frame.  The
  angles are singular at pitch ±π/2 (a MuJoCo quaternion there still maps, rates are not used).
* ``RevoluteJoint``, ``PrismaticJoint``: one coordinate each; Drake 1.51 honours an MJCF joint's ``ref``
  as MuJoCo does (the file's pose at ``q = ref``, which is Drake's default position; verified), but
  :func:`build_drake_state_map` still checks both engines' body poses at ``qpos0`` and offsets those
  coordinates if a parser put the file's pose at ``q = 0`` instead (a ``LOAD`` finding then says so).

Since ``d/dt (R ω_B) = R ω̇_B`` (``Ṙ ω_B = R (ω_B × ω_B) = 0``), Drake's velocities *and*
accelerations are ``T(q) q̇`` and ``T(q) q̈`` with one orthogonal ``T``: a permutation with rotated
blocks; mass matrices and forces convert with ``Tᵀ M T`` and ``Tᵀ τ``.

Joints pair by name; a joint Drake names otherwise (a free joint takes its body's name in Drake)
pairs through the body it moves when that body has one joint in MuJoCo.  A URDF ``planar`` joint is MuJoCo's
slides ``<name>_TX``, ``<name>_TY`` and hinge ``<name>_RZ`` and Drake's one ``PlanarJoint`` with the same
``q = (x, y, θ)`` and ``v = (ẋ, ẏ, θ̇)`` (rates in the parent frame; both honour the URDF axis: verified on
poses and mass matrices), paired coordinate by coordinate.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.engines.canonical import VelocityMapped, mujoco_joint_names
from koenig_check.engines.drake.loader import DrakeLoadError
from koenig_check.engines.joint_pairs import MJ_KIND, mismatch_message

_COMPATIBLE = {
    "free": {"quaternion_floating"},
    "ball": {"ball_rpy"},
    "hinge": {"revolute"},
    "slide": {"prismatic"},
}


#: MuJoCo's joints of a URDF planar joint ``name`` (``name + suffix``), with their MuJoCo kinds.
_PLANAR_PARTS = (("_TX", "slide"), ("_TY", "slide"), ("_RZ", "hinge"))


def _planar_part(name: str, by_name: dict[str, Any]) -> tuple[Any, int] | None:
    """Drake's ``PlanarJoint`` and the coordinate (0 x, 1 y, 2 θ) a MuJoCo joint ``<planar>_TX|_TY|_RZ`` is."""
    for k, (suffix, _) in enumerate(_PLANAR_PARTS):
        joint = by_name.get(name[: -len(suffix)]) if name.endswith(suffix) else None
        if joint is not None and joint.type_name() == "planar":
            return joint, k
    return None


@dataclass(frozen=True)
class DrakeJointPair:
    """One MuJoCo joint and the Drake joint it maps to.

    Parameters
    ----------
    name : str
        Canonical (MuJoCo) joint name.
    kind : str
        MuJoCo type: ``"free"``, ``"ball"``, ``"hinge"`` or ``"slide"``.
    drake_name : str
        Drake's joint name.
    body : str
        The body the joint moves.
    qadr, vadr : int
        Canonical position/velocity addresses.
    dq, dv : int
        Drake position/velocity starts.
    q_offset : float
        ``q_drake = q_canonical - q_offset`` (hinge/slide only).
    """

    name: str
    kind: str
    drake_name: str
    body: str
    qadr: int
    vadr: int
    dq: int
    dv: int
    q_offset: float = 0.0


def match_drake_joints(mj_model: mujoco.MjModel, plant: Any, path: str) -> list[DrakeJointPair]:
    """Pair every MuJoCo joint with a Drake joint, by name, else by the single joint of the same body.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    plant : pydrake.multibody.plant.MultibodyPlant
        Finalized.
    path : str
        For messages.

    Returns
    -------
    list of DrakeJointPair
        In canonical order.

    Raises
    ------
    DrakeLoadError
        Naming the joints found in one engine only and those of incompatible types.
    """
    names = mujoco_joint_names(mj_model)
    drake_joints = [plant.get_joint(j) for j in plant.GetJointIndices() if plant.get_joint(j).num_velocities() > 0]
    by_name = {j.name(): j for j in drake_joints}
    by_body = {j.child_body().name(): j for j in drake_joints}
    used: set[str] = set()
    pairs, only_mj, mismatch = [], [], []
    for k, name in enumerate(names):
        body_id = int(mj_model.jnt_bodyid[k])
        body = mj_model.body(body_id).name
        joint = by_name.get(name)
        part = _planar_part(name, by_name) if joint is None else None
        if part is not None:  # one coordinate of a URDF planar joint: Drake's (x, y, θ) are MuJoCo's
            joint, k_part = part
            kind = MJ_KIND[int(mj_model.jnt_type[k])]
            if kind != _PLANAR_PARTS[k_part][1] or mj_model.body_jntnum[body_id] != 3:
                mismatch.append(f"{name}: mujoco {kind} vs drake planar")
                continue
            used.add(joint.name())
            qadr, vadr = int(mj_model.jnt_qposadr[k]), int(mj_model.jnt_dofadr[k])
            dq, dv = int(joint.position_start()) + k_part, int(joint.velocity_start()) + k_part
            pairs.append(DrakeJointPair(name, kind, joint.name(), body, qadr, vadr, dq, dv))
            continue
        if joint is None and mj_model.body_jntnum[body_id] == 1:
            joint = by_body.get(body)
        if joint is None or joint.name() in used:
            only_mj.append(name)
            continue
        used.add(joint.name())
        kind = MJ_KIND[int(mj_model.jnt_type[k])]
        if joint.type_name() not in _COMPATIBLE[kind]:
            mismatch.append(f"{name}: mujoco {kind} vs drake {joint.type_name()}")
            continue
        pairs.append(
            DrakeJointPair(
                name,
                kind,
                joint.name(),
                body,
                int(mj_model.jnt_qposadr[k]),
                int(mj_model.jnt_dofadr[k]),
                int(joint.position_start()),
                int(joint.velocity_start()),
            )
        )
    only_drake = [j.name() for j in drake_joints if j.name() not in used]
    failure = mismatch_message(path, "Drake", only_mj, only_drake, mismatch)
    if failure is not None:
        raise DrakeLoadError(failure)
    return pairs


class DrakeStateMap(VelocityMapped):
    """Vectorized conversion from canonical (MuJoCo) states to Drake's.

    Parameters
    ----------
    pairs : list of DrakeJointPair
    nq, nv : int
        Canonical sizes.
    drake_nq, drake_nv : int
        Drake's sizes.
    """

    def __init__(self, pairs: list[DrakeJointPair], nq: int, nv: int, drake_nq: int, drake_nv: int) -> None:
        if nv != drake_nv:
            raise ValueError(f"Drake state map: canonical nv={nv} but Drake nv={drake_nv}")
        self.pairs = tuple(pairs)
        self.nq, self.nv, self.drake_nq, self.drake_nv = nq, nv, drake_nq, drake_nv

    def velocity_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``T`` with ``v_drake = T q̇`` (and ``v̇_drake = T q̈``), shape (P, nv, nv).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv, nv)
        """
        P = qpos.shape[0]
        T = np.zeros((P, self.nv, self.nv))
        for p in self.pairs:
            if p.kind in ("hinge", "slide"):
                T[:, p.dv, p.vadr] = 1.0
            elif p.kind == "ball":
                R = _rotations(qpos[:, p.qadr : p.qadr + 4])
                T[:, p.dv : p.dv + 3, p.vadr : p.vadr + 3] = R
            else:
                R = _rotations(qpos[:, p.qadr + 3 : p.qadr + 7])
                T[:, p.dv : p.dv + 3, p.vadr + 3 : p.vadr + 6] = R
                T[:, p.dv + 3 : p.dv + 6, p.vadr : p.vadr + 3] = np.eye(3)
        return T

    def positions(self, qpos: np.ndarray) -> np.ndarray:
        """Drake's ``q`` for canonical ``qpos`` (quaternions normalized), shape (P, drake_nq).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, drake_nq)
        """
        P = qpos.shape[0]
        q = np.zeros((P, self.drake_nq))
        for p in self.pairs:
            if p.kind in ("hinge", "slide"):
                q[:, p.dq] = qpos[:, p.qadr] - p.q_offset
            elif p.kind == "ball":
                quat = qpos[:, p.qadr : p.qadr + 4]
                with warnings.catch_warnings():  # at pitch ±90° the angles are not unique, the rotation is exact
                    warnings.filterwarnings("ignore", message="Gimbal lock detected", category=UserWarning)
                    q[:, p.dq : p.dq + 3] = Rotation.from_quat(quat, scalar_first=True).as_euler("xyz")
            else:
                quat = qpos[:, p.qadr + 3 : p.qadr + 7]
                q[:, p.dq : p.dq + 4] = quat / np.linalg.norm(quat, axis=-1, keepdims=True)
                q[:, p.dq + 4 : p.dq + 7] = qpos[:, p.qadr : p.qadr + 3]
        return q

    def to_drake(self, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Convert canonical ``(qpos, qvel)`` (or ``(qpos, qacc)``) to Drake's ``(q, v)`` (or ``(q, v̇)``).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        q : ndarray, shape (P, drake_nq)
        v : ndarray, shape (P, drake_nv)
        """
        return self.positions(qpos), np.einsum("pij,pj->pi", self.velocity_matrix(qpos), qvel)


def _rotations(quat: np.ndarray) -> np.ndarray:
    return Rotation.from_quat(quat, scalar_first=True).as_matrix().reshape(-1, 3, 3)


def build_drake_state_map(mj_model: mujoco.MjModel, plant: Any, path: str) -> DrakeStateMap:
    """Pair the joints and decide the ``ref`` offsets from both engines' body poses at ``qpos0``.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    plant : pydrake.multibody.plant.MultibodyPlant
    path : str

    Returns
    -------
    DrakeStateMap
    """
    pairs = match_drake_joints(mj_model, plant, path)
    plain = DrakeStateMap(pairs, mj_model.nq, mj_model.nv, plant.num_positions(), plant.num_velocities())
    refs = [k for k, p in enumerate(pairs) if p.kind in ("hinge", "slide") and mj_model.qpos0[p.qadr] != 0.0]
    if not refs:
        return plain
    shifted = list(pairs)
    for k in refs:
        p = pairs[k]
        shifted[k] = DrakeJointPair(**{**p.__dict__, "q_offset": float(mj_model.qpos0[p.qadr])})
    offset = DrakeStateMap(shifted, mj_model.nq, mj_model.nv, plant.num_positions(), plant.num_velocities())
    errors = [_pose_error(mj_model, plant, m) for m in (plain, offset)]
    return offset if errors[1] < errors[0] else plain


def _pose_error(mj_model: mujoco.MjModel, plant: Any, state_map: DrakeStateMap) -> float:
    """Largest difference of body poses between MuJoCo and Drake at ``qpos0`` (rotation entries + metres)."""
    data = mujoco.MjData(mj_model)
    mujoco.mj_kinematics(mj_model, data)
    context = plant.CreateDefaultContext()
    plant.SetPositions(context, state_map.positions(np.asarray(mj_model.qpos0, dtype=float)[None])[0])
    worst = 0.0
    for b in range(1, mj_model.nbody):
        name = mj_model.body(b).name
        if not name or not plant.HasBodyNamed(name):
            continue
        X = plant.EvalBodyPoseInWorld(context, plant.GetBodyByName(name))
        worst = max(
            worst,
            float(np.abs(X.rotation().matrix() - data.xmat[b].reshape(3, 3)).max()),
            float(np.abs(X.translation() - data.xpos[b]).max()),
        )
    return worst
