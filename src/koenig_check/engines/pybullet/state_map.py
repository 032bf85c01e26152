"""Canonical (MuJoCo) states <-> PyBullet's, joint by joint, paired by name.

PyBullet 3.2.7's conventions (verified against MuJoCo's kinematics, mass matrix and inverse dynamics):

* a revolute (URDF revolute or continuous) or prismatic joint: one coordinate, as MuJoCo's hinge or slide of a
  URDF (no ``ref``);
* the floating base is set by the pose of its *inertial frame* (the COM and the principal axes PyBullet chose,
  ``resetBasePositionAndOrientation``) and the COM's velocity and the angular velocity, both in the world
  (``resetBaseVelocity``); MuJoCo's free joint has the link frame's origin and orientation, the origin's velocity
  in the world and the angular velocity in the link's frame;
* ``calculateMassMatrix`` of a floating base has the base first as ``(ω, v_COM)`` in the base's inertial frame,
  then the joints; ``calculateInverseDynamics`` takes velocities in that layout, accelerations too but with the
  COM's *classical* acceleration in the base's axes (not the derivative of ``v_COM``'s components), ignores the
  base's pose it is given, and returns the base's force first, then its torque, then the joints'.

With ``ν = T(q) q̇`` (PyBullet's velocity), mass matrices and forces convert as ``Tᵀ M T`` and ``Tᵀ τ``; PyBullet's
acceleration is ``T q̈`` plus a term of the velocities (:meth:`PyBulletStateMap.acceleration_bias`).
"""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.canonical import VelocityMapped
from koenig_check.engines.joint_pairs import EngineJoint, LinkJointPair, pair_by_name
from koenig_check.engines.pybullet.client import PyBulletLoadError
from koenig_check.engines.pybullet.tree import BodyTree, matrix_quat

#: PyBullet's joint types that MuJoCo has, in MuJoCo's words.
_MJ_WORDS = {"revolute": "hinge", "prismatic": "slide"}


def pair_joints(mj_model: mujoco.MjModel, tree: BodyTree, path: str, floating: bool) -> list[LinkJointPair]:
    """Pair every MuJoCo joint with PyBullet's joint of the same name (the free root with the floating base).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    tree : BodyTree
    path : str
    floating : bool
        Whether PyBullet's base floats.

    Returns
    -------
    list of LinkJointPair

    Raises
    ------
    PyBulletLoadError
        Naming the joints found in one engine only, and those whose types differ.
    """
    joints = {
        name: EngineJoint(
            _MJ_WORDS.get(tree.joint_types[k], tree.joint_types[k]), tree.joint_types[k], k, int(tree.u_index[k])
        )
        for k, name in enumerate(tree.joint_names)
        if k and tree.joint_types[k] != "fixed"
    }

    def floating_base(j: int) -> int | None:
        body = int(mj_model.jnt_bodyid[j])
        root = mj_model.body_parentid[body] == 0 and mj_model.body(body).name == tree.link_names[0]
        return 0 if floating and root else None

    pairing = pair_by_name(mj_model, joints, "pybullet", floating_base)
    if floating and not any(p.kind == "free" for p in pairing.pairs):
        pairing.only_engine.append(f"floating base {tree.link_names[0]}")
    failure = pairing.failure(path, "PyBullet")
    if failure is not None:
        raise PyBulletLoadError(failure)
    return pairing.pairs


def skew(r: np.ndarray) -> np.ndarray:
    """The matrix of ``r ×``, shape (3, 3)."""
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


class PyBulletStateMap(VelocityMapped):
    """Vectorized conversion from canonical (MuJoCo) states to PyBullet's.

    Parameters
    ----------
    pairs : list of LinkJointPair
    tree : BodyTree
    nq, nv : int
        Canonical sizes.
    """

    def __init__(self, pairs: list[LinkJointPair], tree: BodyTree, nq: int, nv: int) -> None:
        self.pairs = tuple(pairs)
        self.nq, self.nv = nq, nv
        self.base = next((p for p in pairs if p.kind == "free"), None)
        self.n_joints = tree.n_dofs
        self.base_width = 6 if self.base is not None else 0
        self.pb_nv = self.base_width + self.n_joints
        if self.pb_nv != nv:
            raise ValueError(f"PyBullet state map: canonical nv={nv} but PyBullet nv={self.pb_nv}")
        self._r = tree.inertial_pos[0]  # the base's COM in its link frame
        self._R_in = tree.inertial_rot[0]  # link <- base inertial frame

    def _base_rotation(self, qpos: np.ndarray) -> np.ndarray:
        from scipy.spatial.transform import Rotation

        assert self.base is not None
        quat = qpos[:, self.base.qadr + 3 : self.base.qadr + 7]
        return Rotation.from_quat(quat, scalar_first=True).as_matrix().reshape(-1, 3, 3)

    def velocity_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``T`` with ``ν_pybullet = T q̇``, shape (P, nv, nv).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv, nv)
        """
        P = qpos.shape[0]
        T = np.zeros((P, self.nv, self.nv))
        w = self.base_width
        for p in self.pairs:
            if p.kind != "free":
                T[:, w + p.dof, p.vadr] = 1.0
        if self.base is not None:
            R = self._base_rotation(qpos)
            a = self.base.vadr
            Rin_t = self._R_in.T
            T[:, 0:3, a + 3 : a + 6] = Rin_t  # ω in the inertial frame from ω in the link frame
            T[:, 3:6, a : a + 3] = Rin_t @ np.swapaxes(R, 1, 2)  # v_COM = Rinᵀ (Rᵀ v_o + ω_L × r)
            T[:, 3:6, a + 3 : a + 6] = -Rin_t @ skew(self._r)
        return T

    def acceleration_bias(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """What PyBullet's acceleration adds to ``T q̈``, shape (P, nv).

        ``calculateInverseDynamics`` takes the base COM's classical acceleration in the base's axes,
        ``Rᵀ a_C = R_inᵀ (Rᵀ v̇_o + ω̇_L × r + ω_L × (ω_L × r))`` (verified: at ``v̇ = 0`` a spinning body's force
        is zero, not ``m ω × v``): ``T q̈`` holds the first two terms, this the third.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        ndarray, shape (P, nv)
        """
        out = np.zeros((qpos.shape[0], self.nv))
        if self.base is not None:
            a = self.base.vadr
            w = qvel[:, a + 3 : a + 6]
            out[:, 3:6] = np.cross(w, np.cross(w, self._r)) @ self._R_in
        return out

    def joints(self, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """PyBullet's joint positions and velocities (its joint order), shape (P, n_joints) each.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        q, v : ndarray
        """
        P = qpos.shape[0]
        q, v = np.zeros((P, self.n_joints)), np.zeros((P, self.n_joints))
        for p in self.pairs:
            if p.kind != "free":
                q[:, p.dof], v[:, p.dof] = qpos[:, p.qadr], qvel[:, p.vadr]
        return q, v

    def base_state(self, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, ...]:
        """The floating base's inertial frame and velocities, as ``resetBase*`` take them.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        com, quat_xyzw, v_com, omega : ndarray, shapes (P, 3), (P, 4), (P, 3), (P, 3)
            World frame.
        """
        assert self.base is not None
        a, qa = self.base.vadr, self.base.qadr
        R = self._base_rotation(qpos)
        com = qpos[:, qa : qa + 3] + R @ self._r
        omega_link = qvel[:, a + 3 : a + 6]
        v_com = qvel[:, a : a + 3] + np.einsum("pij,pj->pi", R, np.cross(omega_link, self._r))
        omega = np.einsum("pij,pj->pi", R, omega_link)
        return com, matrix_quat(R @ self._R_in), v_com, omega
