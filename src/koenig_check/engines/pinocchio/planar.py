"""URDF ``planar`` joints: MuJoCo's three joints <-> Pinocchio's one ``JointModelPlanar``.

MuJoCo 4.0's URDF import makes a planar joint ``name`` three joints of the child body, in this order:
slides ``name_TX`` and ``name_TY`` and hinge ``name_RZ`` (anchored at the body origin), along a frame whose
third axis is the URDF ``<axis>`` (the plane's normal).  Pinocchio 4.1 makes it one ``JointModelPlanar``
that ignores the URDF axis (always the joint frame's z): ``q = (x, y, cos θ, sin θ)`` and
``v = (vx, vy, ω)`` with ``(vx, vy)`` the origin's velocity *in the joint's local (rotated) frame*, as a
free flyer's (verified with ``pin.integrate``: ``v = (1, 0, 0)`` moves ``(x, y)`` along ``(cos θ, sin θ)``).
The two readings are the same mechanism only when MuJoCo's axes are the body's x, y and z, i.e. the URDF
axis is ``0 0 1``; :func:`planar_targets` pairs only those.  Then ``(x, y, θ)`` are shared and

* ``v_xy = Rz(θ)ᵀ (ẋ, ẏ)``, ``ω = θ̇``;
* ``a_xy = Rz(θ)ᵀ (ẍ, ÿ) − θ̇ ẑ × v_xy`` (``d/dt Rz(θ)ᵀ = −θ̇ [ẑ]× Rz(θ)ᵀ``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind

if TYPE_CHECKING:
    from koenig_check.engines.pinocchio.joint_pairing import JointPair

#: MuJoCo's joints of a URDF planar joint ``name``: ``name + suffix``, with their MuJoCo type and axis.
PLANAR_PARTS = (
    ("_TX", mujoco.mjtJoint.mjJNT_SLIDE, (1.0, 0.0, 0.0)),
    ("_TY", mujoco.mjtJoint.mjJNT_SLIDE, (0.0, 1.0, 0.0)),
    ("_RZ", mujoco.mjtJoint.mjJNT_HINGE, (0.0, 0.0, 1.0)),
)


def planar_targets(mj_model: mujoco.MjModel, index: dict[str, int], name: str) -> list[int] | None:
    """MuJoCo's joints ``name_TX, name_TY, name_RZ`` that read Pinocchio's planar joint ``name``, or None.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    index : dict of str to int
        Canonical joint name -> MuJoCo joint id.
    name : str
        The Pinocchio planar joint's name.

    Returns
    -------
    list of int or None
        The three MuJoCo joint ids (x, y, θ), when they are the whole joint list of one body, in that order,
        with the types and axes (and the hinge anchored at the body origin) of a planar joint about z; None
        otherwise (Pinocchio's joint then stays unpaired).
    """
    ids = [index.get(name + suffix) for suffix, _, _ in PLANAR_PARTS]
    if any(j is None for j in ids):
        return None
    joints = [int(j) for j in ids if j is not None]
    body = int(mj_model.jnt_bodyid[joints[0]])
    start, count = int(mj_model.body_jntadr[body]), int(mj_model.body_jntnum[body])
    if joints != list(range(start, start + 3)) or count != 3:
        return None
    for j, (_, kind, axis) in zip(joints, PLANAR_PARTS, strict=True):
        if mj_model.jnt_type[j] != kind or not np.allclose(mj_model.jnt_axis[j], axis, rtol=0.0, atol=1e-12):
            return None
    if np.any(mj_model.jnt_pos[joints[2]] != 0.0):
        return None
    return joints


def planar_notes(pairs: Sequence[JointPair], pin_names: Sequence[str]) -> list[Finding]:
    """One ``LOAD`` note per paired planar joint: how each engine reads it (not a difference between them).

    Parameters
    ----------
    pairs : sequence of JointPair
        The state map's pairs, MuJoCo order.
    pin_names : sequence of str
        Pinocchio's joint names (``model.names``).

    Returns
    -------
    list of Finding
    """
    parts: dict[int, list[str]] = {}
    for p in pairs:
        if p.pin_kind == "planar":
            parts.setdefault(p.pin_joint, []).append(p.name)
    return [
        Finding(
            Kind.LOAD,
            "both",
            f"joint {pin_names[i]}",
            f"URDF planar joint: MuJoCo's import makes it three joints ({', '.join(names)}: slide x, slide y, hinge "
            "z), Pinocchio one JointModelPlanar (q = x, y, cos θ, sin θ; v = the velocity in the joint's own "
            "frame, ω); the state map pairs them",
            {reference(): tuple(names), "pinocchio": (pin_names[i],)},
        )
        for i, names in parts.items()
    ]


class PlanarBlocks:
    """The planar joints of a state map: canonical ``(x, y, θ)`` <-> Pinocchio ``(x, y, cos θ, sin θ)``, ``v``.

    Parameters
    ----------
    qadr, vadr : sequence of sequence of int
        Per planar joint, the canonical position and velocity addresses of x, y and θ.
    pin_qadr, pin_vadr : sequence of int
        Per planar joint, Pinocchio's ``idx_q`` and ``idx_v``.
    """

    def __init__(
        self,
        qadr: Sequence[Sequence[int]],
        vadr: Sequence[Sequence[int]],
        pin_qadr: Sequence[int],
        pin_vadr: Sequence[int],
    ) -> None:
        self.can_q = np.array(qadr, dtype=int).reshape(-1, 3)
        self.can_v = np.array(vadr, dtype=int).reshape(-1, 3)
        self.pin_q = np.array(pin_qadr, dtype=int).reshape(-1)
        self.pin_v = np.array(pin_vadr, dtype=int).reshape(-1)
        #: Pinocchio's linear dofs (P: vx, vy) and the canonical ones they pair with up to a rotation.
        self.lin_pin = self.pin_v[:, None] + np.arange(2)
        self.lin_can = self.can_v[:, :2]

    @classmethod
    def from_pairs(cls, pairs: Sequence[JointPair]) -> PlanarBlocks:
        """Build the blocks from the joint pairs of ``pin_kind`` ``"planar"`` (x, y, θ of each, MuJoCo order).

        Parameters
        ----------
        pairs : sequence of JointPair

        Returns
        -------
        PlanarBlocks
        """
        joints = [pairs[k : k + 3] for k in range(0, len(pairs), 3)]
        return cls(
            [[p.qadr for p in xyt] for xyt in joints],
            [[p.vadr for p in xyt] for xyt in joints],
            [xyt[0].pin_qadr for xyt in joints],
            [xyt[0].pin_vadr for xyt in joints],
        )

    def dofs(self) -> tuple[np.ndarray, np.ndarray]:
        """Pinocchio's dofs and the canonical ones they pair with (x, y up to a rotation; θ as it is).

        Returns
        -------
        pin_dofs, canonical_dofs : ndarray of int
        """
        return (
            np.concatenate([self.lin_pin.ravel(), self.pin_v + 2]),
            np.concatenate([self.lin_can.ravel(), self.can_v[:, 2]]),
        )

    def rotations(self, qpos: np.ndarray) -> np.ndarray:
        """``Rz(θ)`` (2 × 2) of every planar joint, shape (P, K, 2, 2), from canonical ``qpos`` (P, nq)."""
        theta = qpos[:, self.can_q[:, 2]]
        c, s = np.cos(theta), np.sin(theta)
        return np.stack([np.stack([c, -s], axis=-1), np.stack([s, c], axis=-1)], axis=-2)

    def positions_to_pinocchio(self, qpos: np.ndarray, q: np.ndarray) -> None:
        """Write ``(x, y, cos θ, sin θ)`` into Pinocchio's ``q`` (P, pin_nq), in place."""
        theta = qpos[:, self.can_q[:, 2]]
        q[:, self.pin_q] = qpos[:, self.can_q[:, 0]]
        q[:, self.pin_q + 1] = qpos[:, self.can_q[:, 1]]
        q[:, self.pin_q + 2] = np.cos(theta)
        q[:, self.pin_q + 3] = np.sin(theta)

    def positions_from_pinocchio(self, q: np.ndarray, qpos: np.ndarray) -> None:
        """Write canonical ``(x, y, θ)`` (θ in (−π, π]) from Pinocchio's ``q`` into ``qpos``, in place."""
        qpos[:, self.can_q[:, 0]] = q[:, self.pin_q]
        qpos[:, self.can_q[:, 1]] = q[:, self.pin_q + 1]
        qpos[:, self.can_q[:, 2]] = np.arctan2(q[:, self.pin_q + 3], q[:, self.pin_q + 2])

    def velocities_to_pinocchio(self, qpos: np.ndarray, qvel: np.ndarray, v: np.ndarray) -> None:
        """Write ``(Rz(θ)ᵀ (ẋ, ẏ), θ̇)`` into Pinocchio's ``v`` (P, pin_nv), in place."""
        R = self.rotations(qpos)
        v[:, self.lin_pin] = np.einsum("pkji,pkj->pki", R, qvel[:, self.lin_can])
        v[:, self.pin_v + 2] = qvel[:, self.can_v[:, 2]]

    def velocities_from_pinocchio(self, qpos: np.ndarray, v: np.ndarray, qvel: np.ndarray) -> None:
        """Write canonical ``(ẋ, ẏ, θ̇) = (Rz(θ) v_xy, ω)`` into ``qvel``, in place (``qpos`` already canonical)."""
        R = self.rotations(qpos)
        qvel[:, self.lin_can] = np.einsum("pkij,pkj->pki", R, v[:, self.lin_pin])
        qvel[:, self.can_v[:, 2]] = v[:, self.pin_v + 2]

    def fill_velocity_matrix(self, qpos: np.ndarray, T: np.ndarray) -> None:
        """Write the planar blocks of ``T`` (``v_pin = T q̇``, shape (P, pin_nv, nv)), in place."""
        R = self.rotations(qpos)
        for k in range(self.pin_v.shape[0]):
            T[:, self.lin_pin[k][:, None], self.lin_can[k][None, :]] = np.swapaxes(R[:, k], -1, -2)
            T[:, self.pin_v[k] + 2, self.can_v[k, 2]] = 1.0

    def correct_acceleration(self, qvel: np.ndarray, v: np.ndarray, a: np.ndarray) -> None:
        """Add ``−θ̇ ẑ × v_xy`` to Pinocchio's ``a`` (already ``Rz(θ)ᵀ (ẍ, ÿ)``), in place.

        Parameters
        ----------
        qvel : ndarray, shape (P, nv)
            Canonical rates.
        v : ndarray, shape (P, pin_nv)
            Pinocchio's velocity of the same state.
        a : ndarray, shape (P, pin_nv)
        """
        rate = qvel[:, self.can_v[:, 2]]
        a[:, self.pin_v] += rate * v[:, self.pin_v + 1]
        a[:, self.pin_v + 1] -= rate * v[:, self.pin_v]
