"""Canonical (MuJoCo) states <-> iDynTree's, joint by joint, paired by name.

iDynTree 15.1's conventions (verified against MuJoCo's kinematics, mass matrix and inverse dynamics):

* its model is always free-floating: ``(base pose, s)`` and ``ν = (v_b, ω, ṡ)`` with, in the mixed representation
  used here, ``v_b`` the velocity of the base link's origin and ``ω`` the angular velocity, both in the world; its
  mass matrix is ``(6 + n) × (6 + n)`` in that order, its inverse dynamics takes ``ν̇`` and returns the base's
  force and torque (world axes, about the base's origin) then the joints' torques;
* its DOF order is its own (a joint's ``getDOFsOffset``): DOFs are paired with MuJoCo's by joint name;
* a fixed base: the base link is put where MuJoCo has it (a URDF's root at the origin), at rest; the mass matrix's
  and forces' joint block is the fixed-base one;
* the base is the link MuJoCo's root body is; if iDynTree made that link a frame of another link (massless, fixed),
  the base is that link, placed through the frame's constant transform.

MuJoCo's free joint has the root link's origin velocity in the world and the angular velocity in the link's frame:
``ν = T(q) q̇`` with ``ω = R ω_L`` and ``v_b = v_o + ω × R d`` (``d`` the base origin in the root's frame); the
acceleration is ``T q̈`` plus ``ω × (ω × R d)`` (:meth:`IDynTreeStateMap.acceleration_bias`).
"""

from __future__ import annotations

import mujoco
import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.engines.canonical import VelocityMapped
from koenig_check.engines.idyntree.loader import IDynTreeLoadError
from koenig_check.engines.joint_pairs import EngineJoint, LinkJointPair, pair_by_name


def joint_kind(joint: object) -> str:
    """``"hinge"``, ``"slide"``, ``"fixed"`` or another word for an iDynTree joint, in MuJoCo's words."""
    if joint.isRevoluteJoint():  # type: ignore[attr-defined]
        return "hinge"
    if joint.isPrismaticJoint():  # type: ignore[attr-defined]
        return "slide"
    return "fixed" if joint.isFixedJoint() else "spherical"  # type: ignore[attr-defined]


def pair_joints(mj_model: mujoco.MjModel, model: object, path: str, base: int, floating: bool) -> list[LinkJointPair]:
    """Pair every MuJoCo joint with iDynTree's joint of the same name (the free root with the floating base).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    model : idyntree.swig.Model
    path : str
    base : int
        iDynTree's base link.
    floating : bool

    Returns
    -------
    list of LinkJointPair

    Raises
    ------
    IDynTreeLoadError
        Naming the joints found in one engine only, and those whose types differ.
    """
    joints = {}
    for j in range(model.getNrOfJoints()):  # type: ignore[attr-defined]
        joint = model.getJoint(j)  # type: ignore[attr-defined]
        if joint.getNrOfDOFs() > 0:
            kind = joint_kind(joint)
            link, dof = int(joint.getSecondAttachedLink()), int(joint.getDOFsOffset())
            joints[model.getJointName(j)] = EngineJoint(kind, kind, link, dof)  # type: ignore[attr-defined]

    def floating_base(j: int) -> int | None:
        return base if floating and mj_model.body_parentid[mj_model.jnt_bodyid[j]] == 0 else None

    pairing = pair_by_name(mj_model, joints, "idyntree", floating_base)
    failure = pairing.failure(path, "iDynTree")
    if failure is not None:
        raise IDynTreeLoadError(failure)
    return pairing.pairs


class IDynTreeStateMap(VelocityMapped):
    """Vectorized conversion from canonical (MuJoCo) states to iDynTree's free-floating ones.

    Parameters
    ----------
    pairs : list of LinkJointPair
    n_dofs : int
        iDynTree's joint DOFs.
    nq, nv : int
        Canonical sizes.
    root_to_base : ndarray, shape (4, 4)
        The base link's frame in the frame of MuJoCo's root body.
    fixed_root : ndarray, shape (4, 4)
        The root's pose in the world when it does not float.
    """

    def __init__(
        self,
        pairs: list[LinkJointPair],
        n_dofs: int,
        nq: int,
        nv: int,
        root_to_base: np.ndarray,
        fixed_root: np.ndarray,
    ) -> None:
        self.pairs = tuple(pairs)
        self.nq, self.nv, self.n_dofs = nq, nv, n_dofs
        self.base = next((p for p in pairs if p.kind == "free"), None)
        if (6 if self.base is not None else 0) + n_dofs != nv:
            raise ValueError(f"iDynTree state map: canonical nv={nv} but iDynTree has {n_dofs} joint DOFs")
        self._X = np.asarray(root_to_base, dtype=float)
        self._fixed = np.asarray(fixed_root, dtype=float)
        self.columns = np.array([p.dof + 6 for p in pairs if p.kind != "free"], dtype=int)
        self.rows = np.array([p.vadr for p in pairs if p.kind != "free"], dtype=int)

    def _root(self, qpos: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The root's rotation (P, 3, 3) and origin (P, 3) in the world."""
        P = qpos.shape[0]
        if self.base is None:
            return np.broadcast_to(self._fixed[:3, :3], (P, 3, 3)), np.broadcast_to(self._fixed[:3, 3], (P, 3))
        a = self.base.qadr
        R = Rotation.from_quat(qpos[:, a + 3 : a + 7], scalar_first=True).as_matrix().reshape(-1, 3, 3)
        return R, qpos[:, a : a + 3]

    def base_pose(self, qpos: np.ndarray) -> np.ndarray:
        """The base pose ``world_H_base`` iDynTree takes, per pose, shape (P, 4, 4).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, 4, 4)
        """
        R, o = self._root(qpos)
        H = np.zeros((qpos.shape[0], 4, 4))
        H[:, :3, :3] = R @ self._X[:3, :3]
        H[:, :3, 3] = o + R @ self._X[:3, 3]
        H[:, 3, 3] = 1.0
        return H

    def joint_positions(self, qpos: np.ndarray) -> np.ndarray:
        """The joint positions ``s`` iDynTree takes (its DOF order), shape (P, n_dofs).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, n_dofs)
        """
        s = np.zeros((qpos.shape[0], self.n_dofs))
        for p in self.pairs:
            if p.kind != "free":
                s[:, p.dof] = qpos[:, p.qadr]
        return s

    def velocity_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``T`` with ``ν = T q̇`` (iDynTree's 6 + n velocities), shape (P, 6 + n_dofs, nv).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, 6 + n_dofs, nv)
        """
        P = qpos.shape[0]
        T = np.zeros((P, 6 + self.n_dofs, self.nv))
        T[:, self.columns, self.rows] = 1.0
        if self.base is not None:
            a = self.base.vadr
            R, _ = self._root(qpos)
            d = R @ self._X[:3, 3]  # the base origin from the root's, world axes
            T[:, 0:3, a : a + 3] = np.eye(3)
            T[:, 0:3, a + 3 : a + 6] = -_skew(d) @ R  # v_b = v_o + (R ω_L) × d
            T[:, 3:6, a + 3 : a + 6] = R
        return T

    def acceleration_bias(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """What iDynTree's ``ν̇`` adds to ``T q̈``: ``ω × (ω × R d)`` on the base's linear part, shape (P, 6 + n_dofs).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        ndarray, shape (P, 6 + n_dofs)
        """
        out = np.zeros((qpos.shape[0], 6 + self.n_dofs))
        if self.base is not None:
            a = self.base.vadr
            R, _ = self._root(qpos)
            w = np.einsum("pij,pj->pi", R, qvel[:, a + 3 : a + 6])
            out[:, 0:3] = np.cross(w, np.cross(w, R @ self._X[:3, 3]))
        return out


def _skew(r: np.ndarray) -> np.ndarray:
    """``r ×`` as matrices, shape (..., 3, 3)."""
    out = np.zeros((*r.shape[:-1], 3, 3))
    out[..., 0, 1], out[..., 0, 2], out[..., 1, 2] = -r[..., 2], r[..., 1], -r[..., 0]
    return out - np.swapaxes(out, -1, -2)
