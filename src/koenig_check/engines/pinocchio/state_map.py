"""The state map: canonical (q, q̇) <-> Pinocchio (q, v), joint by joint, matched by name.

Canonical convention (:mod:`koenig_check.engines.canonical`)
--------------------
The canonical state is MuJoCo's ``qpos``/``qvel`` layout of the MuJoCo model (``nq``/``nv`` of the ``MjModel``,
joints in MuJoCo order):

* hinge, slide: one angle/displacement (``qpos0`` holds the joint's ``ref``), one rate;
* ball: ``qpos`` quaternion ``(w, x, y, z)`` of the child relative to the parent, ``qvel`` angular velocity in the
  child (local) frame;
* free: ``qpos`` = world position of the body origin then quaternion ``(w, x, y, z)`` world <- body; ``qvel`` =
  *linear velocity of the body origin in the world frame*, then *angular velocity in the body (local) frame*
  (verified for MuJoCo 4.0 with ``mj_integratePos`` and ``cvel``).

Pinocchio differs: quaternions are ``(x, y, z, w)``; a free flyer's ``v`` is ``(v, ω)`` both in the local frame
(``v_pin = Rᵀ v_world``); URDF ``continuous`` joints (``JointModelRUB*``) store ``(cos θ, sin θ)`` (nq=2, nv=1); a
MuJoCo body with several joints is one ``JointModelComposite`` named ``"Composite_<first joint>"`` whose sub-joints
follow the body's joints in order; a URDF ``planar`` joint is MuJoCo's three joints and Pinocchio's one
(:mod:`~koenig_check.engines.pinocchio.planar`); joint orders may differ. Pinocchio 4.1's MJCF parser honours ``ref``
for a single hinge or slide and for a slide inside a composite, but *ignores it for a hinge inside a composite* (the
file's pose is at pin ``q = 0``, not at ``q = ref``); :func:`build_state_map` detects this from both engines'
kinematics at ``qpos0`` and offsets those coordinates, recording a note.

Matching is by joint name, never by index.  Unnamed MuJoCo joints get the name Pinocchio's MJCF parser gives them
(``"<body>Joint_<k>"``, ``"<body>_free"``); anything left unpaired raises ``JointMismatch``.
"""

from __future__ import annotations

import itertools
from dataclasses import replace
from typing import overload

import mujoco
import numpy as np
import pinocchio as pin
from scipy.spatial.transform import Rotation

from koenig_check.engines.canonical import VelocityMapped
from koenig_check.engines.pinocchio.joint_pairing import JointPair, match_joints
from koenig_check.engines.pinocchio.planar import PlanarBlocks, planar_notes
from koenig_check.findings import Finding, Kind

#: Rotation mismatch (max abs entry) under which two engines' relative rotations are "equal".
_ROTATION_ATOL = 1e-9


class StateMap(VelocityMapped):
    """Vectorized conversion between canonical (MuJoCo) and Pinocchio states.

    Parameters
    ----------
    pairs : list of JointPair
        From :func:`match_joints`, canonical order.
    nq, nv : int
        Canonical sizes (MuJoCo ``nq``/``nv``).
    pin_nq, pin_nv : int
        Pinocchio sizes.
    segment_names : dict
        Pinocchio joint index -> canonical segment name (the last MuJoCo joint it carries).
    findings : list of Finding
        What the map compensates for.
    free_placements : dict of int to (ndarray, ndarray), optional
        Pinocchio joint index of a free joint -> its placement in the world ``(R, p)`` (``jointPlacements``):
        MuJoCo's free ``qpos`` is the body's world pose ``T``, Pinocchio's ``q`` is ``placement⁻¹ T`` (its MJCF
        parser places a root ``<freejoint>`` of a body with both ``pos`` and an orientation at ``pos − R pos``;
        a URDF ``floating`` joint sits at its ``<origin>``).  Missing: the identity.
    """

    def __init__(
        self,
        pairs: list[JointPair],
        nq: int,
        nv: int,
        pin_nq: int,
        pin_nv: int,
        segment_names: dict[int, str],
        findings: list[Finding] | None = None,
        free_placements: dict[int, tuple[np.ndarray, np.ndarray]] | None = None,
    ) -> None:
        if nv != pin_nv:
            raise ValueError(f"state map: canonical nv={nv} but Pinocchio nv={pin_nv}")
        self.pairs = tuple(pairs)
        self.nq, self.nv, self.pin_nq, self.pin_nv = nq, nv, pin_nq, pin_nv
        self.segment_names = dict(segment_names)
        self.findings = list(findings or [])
        by_kind: dict[str, list[JointPair]] = {}
        for p in pairs:
            by_kind.setdefault(p.pin_kind if p.pin_kind in ("unbounded", "planar") else p.kind, []).append(p)
        scal = by_kind.get("hinge", []) + by_kind.get("slide", [])
        unb, balls, frees = (by_kind.get(k, []) for k in ("unbounded", "ball", "free"))
        self._planar = PlanarBlocks.from_pairs(by_kind.get("planar", []))
        ar = np.arange
        self._s_can = np.array([p.qadr for p in scal], dtype=int)
        self._s_pin = np.array([p.pin_qadr for p in scal], dtype=int)
        self._s_off = np.array([p.q_offset for p in scal], dtype=float)
        self._u_can = np.array([p.qadr for p in unb], dtype=int)
        self._u_pin = np.array([p.pin_qadr for p in unb], dtype=int)
        quats = balls + frees
        shift = [0 if p.kind == "ball" else 3 for p in quats]
        pairs_s = list(zip(quats, shift, strict=True))
        self._quat_can = np.array([p.qadr + s + ar(4) for p, s in pairs_s], dtype=int).reshape(-1, 4)
        self._quat_pin = np.array([p.pin_qadr + s + ar(4) for p, s in pairs_s], dtype=int).reshape(-1, 4)
        self._pos_can = np.array([p.qadr + ar(3) for p in frees], dtype=int).reshape(-1, 3)
        self._pos_pin = np.array([p.pin_qadr + ar(3) for p in frees], dtype=int).reshape(-1, 3)
        self._free_quat_can = np.array([p.qadr + 3 + ar(4) for p in frees], dtype=int).reshape(-1, 4)
        self._lin_can = np.array([p.vadr + ar(3) for p in frees], dtype=int).reshape(-1, 3)
        self._lin_pin = np.array([p.pin_vadr + ar(3) for p in frees], dtype=int).reshape(-1, 3)
        placed = [(free_placements or {}).get(p.pin_joint, (np.eye(3), np.zeros(3))) for p in frees]
        self._place_R = np.array([np.asarray(R, dtype=float) for R, _ in placed]).reshape(-1, 3, 3)
        self._place_p = np.array([np.asarray(t, dtype=float) for _, t in placed]).reshape(-1, 3)
        self._placed = bool(np.any(self._place_p)) or not np.allclose(self._place_R, np.eye(3), rtol=0.0, atol=0.0)
        width = {"free": 3, "ball": 3, "hinge": 1, "slide": 1}  # dofs copied as they are
        copy_can, copy_pin = [], []
        for p in (p for p in pairs if p.pin_kind != "planar"):
            start = 3 if p.kind == "free" else 0
            copy_can += [p.vadr + start + k for k in range(width[p.kind])]
            copy_pin += [p.pin_vadr + start + k for k in range(width[p.kind])]
        self._v_can = np.array(copy_can, dtype=int)
        self._v_pin = np.array(copy_pin, dtype=int)

    @property
    def velocity_permutation(self) -> tuple[np.ndarray, np.ndarray]:
        """Return ``(pin_dofs, canonical_dofs)``: dof ``pin_dofs[k]`` of Pinocchio is dof ``canonical_dofs[k]``.

        A free or planar joint's linear dofs pair up to a rotation (world vs local frame).

        Returns
        -------
        tuple of ndarray
        """
        pin_dofs, can_dofs = self._planar.dofs()
        pin_all = np.concatenate([self._v_pin, self._lin_pin.ravel(), pin_dofs]).astype(int)
        return pin_all, np.concatenate([self._v_can, self._lin_can.ravel(), can_dofs]).astype(int)

    # ---------------------------------------------------------------- helpers
    @staticmethod
    def _batch(x: np.ndarray, n: int, what: str) -> tuple[np.ndarray, bool]:
        arr = np.asarray(x, dtype=float)
        single = arr.ndim == 1
        arr = np.atleast_2d(arr)
        if arr.ndim != 2 or arr.shape[1] != n:
            raise ValueError(f"{what}: expected shape (P, {n}) or ({n},), got {np.shape(x)}")
        return arr, single

    def _free_rotations(self, qpos: np.ndarray) -> np.ndarray:
        """World <- body rotation of every free joint, shape (P, F, 3, 3), from canonical qpos."""
        quat = qpos[:, self._free_quat_can]  # (P, F, 4) w,x,y,z
        P, F = quat.shape[:2]
        if F == 0:
            return np.zeros((P, 0, 3, 3))
        mats = Rotation.from_quat(quat.reshape(-1, 4), scalar_first=True).as_matrix()
        return mats.reshape(P, F, 3, 3)

    def _unplace(self, q: np.ndarray) -> None:
        """Free joints' world poses in ``q`` (Pinocchio's layout) made relative to their placements, in place."""
        if not self._placed:
            return
        quats = self._pos_pin[:, :1] + np.arange(3, 7)  # x y z w
        for f, (Rj, pj) in enumerate(zip(self._place_R, self._place_p, strict=True)):
            q[:, quats[f]] = (Rotation.from_matrix(Rj.T) * Rotation.from_quat(q[:, quats[f]])).as_quat()
            q[:, self._pos_pin[f]] = (q[:, self._pos_pin[f]] - pj) @ Rj

    def _place(self, q: np.ndarray) -> np.ndarray:
        """Free joints' coordinates in ``q`` (relative to their placements) as world poses (a copy)."""
        if not self._placed:
            return q
        q = q.copy()
        quats = self._pos_pin[:, :1] + np.arange(3, 7)
        for f, (Rj, pj) in enumerate(zip(self._place_R, self._place_p, strict=True)):
            q[:, quats[f]] = (Rotation.from_matrix(Rj) * Rotation.from_quat(q[:, quats[f]])).as_quat()
            q[:, self._pos_pin[f]] = q[:, self._pos_pin[f]] @ Rj.T + pj
        return q

    # ------------------------------------------------------------- positions
    @overload
    def to_pinocchio(self, qpos: np.ndarray, qvel: None = None) -> np.ndarray: ...
    @overload
    def to_pinocchio(self, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, np.ndarray]: ...
    def to_pinocchio(
        self, qpos: np.ndarray, qvel: np.ndarray | None = None
    ) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
        """Convert canonical states to Pinocchio's ``(q, v)``.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq) or (nq,)
        qvel : ndarray, shape (P, nv) or (nv,), optional

        Returns
        -------
        q : ndarray, shape (P, pin_nq) (or 1-D for 1-D input); quaternions are normalized
        v : ndarray, shape (P, pin_nv), only if ``qvel`` is given
        """
        qpos, single = self._batch(qpos, self.nq, "qpos")
        P = qpos.shape[0]
        q = np.zeros((P, self.pin_nq))
        q[:, self._s_pin] = qpos[:, self._s_can] - self._s_off
        q[:, self._u_pin] = np.cos(qpos[:, self._u_can])
        q[:, self._u_pin + 1] = np.sin(qpos[:, self._u_can])
        quat = qpos[:, self._quat_can]  # (P, Q, 4) w x y z
        quat = quat / np.linalg.norm(quat, axis=-1, keepdims=True)
        q[:, self._quat_pin] = quat[..., [1, 2, 3, 0]]
        q[:, self._pos_pin] = qpos[:, self._pos_can]
        self._planar.positions_to_pinocchio(qpos, q)
        self._unplace(q)
        if qvel is None:
            return q[0] if single else q
        qvel, _ = self._batch(qvel, self.nv, "qvel")
        if qvel.shape[0] != P:
            raise ValueError(f"qvel has {qvel.shape[0]} poses, qpos has {P}")
        v = np.zeros((P, self.pin_nv))
        v[:, self._v_pin] = qvel[:, self._v_can]
        R = self._free_rotations(qpos)
        v[:, self._lin_pin] = np.einsum("pfji,pfj->pfi", R, qvel[:, self._lin_can])
        self._planar.velocities_to_pinocchio(qpos, qvel, v)
        return (q[0], v[0]) if single else (q, v)

    def from_pinocchio(self, q: np.ndarray, v: np.ndarray | None = None) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
        """Convert Pinocchio ``(q, v)`` to canonical states (inverse of :meth:`to_pinocchio`).

        Parameters
        ----------
        q : ndarray, shape (P, pin_nq) or (pin_nq,)
        v : ndarray, shape (P, pin_nv) or (pin_nv,), optional

        Returns
        -------
        qpos : ndarray, shape (P, nq); unbounded angles come back in (-π, π]
        qvel : ndarray, shape (P, nv), only if ``v`` is given
        """
        q, single = self._batch(q, self.pin_nq, "q")
        P = q.shape[0]
        qpos = np.zeros((P, self.nq))
        qpos[:, self._s_can] = q[:, self._s_pin] + self._s_off
        qpos[:, self._u_can] = np.arctan2(q[:, self._u_pin + 1], q[:, self._u_pin])
        self._planar.positions_from_pinocchio(q, qpos)
        q = self._place(q)
        qpos[:, self._quat_can] = q[:, self._quat_pin][..., [3, 0, 1, 2]]
        qpos[:, self._pos_can] = q[:, self._pos_pin]
        if v is None:
            return qpos[0] if single else qpos
        v, _ = self._batch(v, self.pin_nv, "v")
        qvel = np.zeros((P, self.nv))
        qvel[:, self._v_can] = v[:, self._v_pin]
        R = self._free_rotations(qpos)
        qvel[:, self._lin_can] = np.einsum("pfij,pfj->pfi", R, v[:, self._lin_pin])
        self._planar.velocities_from_pinocchio(qpos, v, qvel)
        return (qpos[0], qvel[0]) if single else (qpos, qvel)

    # ------------------------------------------------------------ velocities
    def velocity_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``T`` with ``v_pin = T q̇`` (orthogonal: a permutation with rotated free blocks).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv, nv)
        """
        qpos, _ = self._batch(qpos, self.nq, "qpos")
        P = qpos.shape[0]
        T = np.zeros((P, self.pin_nv, self.nv))
        T[:, self._v_pin, self._v_can] = 1.0
        R = self._free_rotations(qpos)
        for f in range(self._lin_can.shape[0]):
            T[:, self._lin_pin[f][:, None], self._lin_can[f][None, :]] = np.swapaxes(R[:, f], -1, -2)
        self._planar.fill_velocity_matrix(qpos, T)
        return T

    def acceleration_to_pinocchio(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Convert canonical accelerations to Pinocchio's ``a = dv/dt``.

        For a free joint ``v_pin = Rᵀ v_world`` so ``a_pin = Rᵀ a_world - ω_local × (Rᵀ v_world)`` (planar: ω = θ̇ ẑ).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel, qacc : ndarray, shape (P, nv)

        Returns
        -------
        ndarray, shape (P, pin_nv)
        """
        qpos, _ = self._batch(qpos, self.nq, "qpos")
        qvel, _ = self._batch(qvel, self.nv, "qvel")
        qacc, _ = self._batch(qacc, self.nv, "qacc")
        _, a = self.to_pinocchio(qpos, qacc)
        _, v = self.to_pinocchio(qpos, qvel)
        omega_local = qvel[:, self._lin_can + 3]
        a[:, self._lin_pin] -= np.cross(omega_local, v[:, self._lin_pin])
        self._planar.correct_acceleration(qvel, v, a)
        return a


def _relative_rotations_mujoco(mj_model: mujoco.MjModel, qpos: np.ndarray, bodies: list[int]) -> list[np.ndarray]:
    data = mujoco.MjData(mj_model)
    data.qpos[:] = qpos
    mujoco.mj_kinematics(mj_model, data)
    out = []
    for b in bodies:
        parent = int(mj_model.body_parentid[b])
        while parent > 0 and mj_model.body_jntnum[parent] == 0:
            parent = int(mj_model.body_parentid[parent])
        Rp = data.xmat[parent].reshape(3, 3) if parent > 0 else np.eye(3)
        out.append(Rp.T @ data.xmat[b].reshape(3, 3))
    return out


def _relative_rotation_pin(pin_model: pin.Model, q: np.ndarray, i: int) -> np.ndarray:
    data = pin_model.createData()
    pin.forwardKinematics(pin_model, data, q)
    return data.oMi[pin_model.parents[i]].rotation.T @ data.oMi[i].rotation


def build_state_map(mj_model: mujoco.MjModel, pin_model: pin.Model, path: str = "<model>") -> StateMap:
    """Pair the joints of both engines and build the :class:`StateMap`.

    Hinges with a non-zero reference position inside a Pinocchio composite joint are checked
    against MuJoCo's kinematics at ``qpos0`` (relative rotation of the segment to its parent
    segment); where Pinocchio ignored ``ref`` the map offsets the coordinate and adds a note.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    pin_model : pinocchio.Model
    path : str
        File name for messages.

    Returns
    -------
    StateMap

    Raises
    ------
    JointMismatch
        If the joints cannot be paired.
    """
    pairs = match_joints(mj_model, pin_model, path)
    seg_names: dict[int, str] = {}
    for p in pairs:
        seg_names[p.pin_joint] = p.name  # canonical order: the last joint of a body wins
    notes: list[Finding] = planar_notes(pairs, pin_model.names)

    placements = {
        p.pin_joint: (
            np.array(pin_model.jointPlacements[p.pin_joint].rotation),
            pin_model.jointPlacements[p.pin_joint].translation.copy(),
        )
        for p in pairs
        if p.kind == "free" and pin_model.parents[p.pin_joint] == 0
    }

    def make(ps: list[JointPair]) -> StateMap:
        return StateMap(ps, mj_model.nq, mj_model.nv, pin_model.nq, pin_model.nv, seg_names, notes, placements)

    suspects: dict[int, list[int]] = {}
    for k, p in enumerate(pairs):
        if p.kind == "hinge" and p.pin_sub >= 0 and mj_model.qpos0[p.qadr] != 0.0:
            suspects.setdefault(p.pin_joint, []).append(k)
    for joint, ks in suspects.items():
        body = int(mj_model.jnt_bodyid[ks[0]])  # pairs are in MuJoCo joint order
        target = _relative_rotations_mujoco(mj_model, mj_model.qpos0, [body])[0]
        best: tuple[float, tuple[bool, ...]] = (np.inf, ())
        for choice in itertools.product((False, True), repeat=len(ks)):
            trial = list(pairs)
            for k, on in zip(ks, choice, strict=True):
                trial[k] = replace(pairs[k], q_offset=float(mj_model.qpos0[pairs[k].qadr]) if on else 0.0)
            q = make(trial).to_pinocchio(mj_model.qpos0)
            err = float(np.abs(_relative_rotation_pin(pin_model, q, joint) - target).max())
            if err < best[0] - _ROTATION_ATOL:
                best = (err, choice)
        for k, on in zip(ks, best[1], strict=True):
            if on:
                ref = float(mj_model.qpos0[pairs[k].qadr])
                pairs[k] = replace(pairs[k], q_offset=ref)
                notes.append(
                    Finding(
                        Kind.IGNORED_CONSTRUCT,
                        "pinocchio",
                        f"joint {pairs[k].name}",
                        f"MJCF parser ignores the hinge's ref inside composite joint {pin_model.names[joint]!r}; "
                        "the state map offsets that coordinate",
                        {"ref": ref},
                    )
                )
        if best[0] > 1e-6:
            notes.append(
                Finding(
                    Kind.FRAME,
                    "pinocchio",
                    f"joint {pin_model.names[joint]}",
                    "the composite joint's segment does not reproduce MuJoCo's orientation at qpos0",
                    {"max rotation entry error": best[0]},
                    affects_energy=True,
                )
            )
    return make(pairs)
