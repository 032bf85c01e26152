"""The Newton state map: canonical (MuJoCo) (q, q̇) <-> Newton ``(joint_q, joint_qd)``, joint by joint, by name.

Newton 1.8's conventions (verified against MuJoCo's kinematics, energy and mass matrix):

* revolute, prismatic: one coordinate; an MJCF joint's coordinate is ``qpos − ref`` (Newton's MJCF parser puts the
  file's pose at ``q = 0``; MuJoCo's ``qpos0`` holds ``ref``): the map subtracts MuJoCo's ``qpos0``.
* free: ``q = (p, quaternion x y z w)`` of the body (world <- body), ``q̇ = (v_COM, ω)`` *both in the world frame*,
  ``v_COM`` the velocity of the body's centre of mass; MuJoCo's ``qvel = (v_origin world, ω body)``.  So
  ``ω_W = R ω_B`` and ``v_COM = v_O − [R c]× R ω_B`` (``c`` the COM in the body frame), and the acceleration gains
  ``ω_W × (ω_W × R c)``.
* ball: ``q`` = quaternion ``x y z w`` of the child relative to the parent (MuJoCo's ``w x y z``), ``q̇`` = angular
  velocity in the parent's joint frame, ``R(q) ω_child`` (MuJoCo's is in the child frame); ``d/dt (R ω) = R ω̇``.
* A body with several MJCF joints is one Newton D6 joint whose dofs are its slides, then its hinges, each in the
  file's order (:func:`d6_position`; measured: brax's prismaversal_2dof_joint.xml, a hinge written before a slide).

``q̇_N = T(q) q̇`` with ``T`` a block matrix per joint; mass matrices convert with ``Tᵀ M T``, forces with ``Tᵀ τ``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.engines.joint_pairs import MJ_KIND, mismatch_message
from koenig_check.engines.newton.loader import NewtonLoadError

#: Newton's ``JointType`` values.
PRISMATIC, REVOLUTE, BALL, FIXED, FREE, D6 = 0, 1, 2, 3, 4, 6
_SIZES = {"free": (7, 6), "ball": (4, 3), "hinge": (1, 1), "slide": (1, 1)}
_COMPATIBLE = {"free": {FREE}, "ball": {BALL}, "hinge": {REVOLUTE, D6}, "slide": {PRISMATIC, D6}}


def d6_position(mj_model: mujoco.MjModel, body: int, k: int) -> int:
    """The dof of MuJoCo joint ``k`` within the D6 joint Newton makes of its body's joints: slides first, then hinges.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    body : int
        The body joint ``k`` moves.
    k : int
        MuJoCo joint index.

    Returns
    -------
    int
        Newton lists a D6 joint's linear axes before its angular ones, each group in the file's order.
    """
    first, count = int(mj_model.body_jntadr[body]), int(mj_model.body_jntnum[body])
    joints = range(first, first + count)
    slide = int(mujoco.mjtJoint.mjJNT_SLIDE)
    ordered = [i for i in joints if int(mj_model.jnt_type[i]) == slide] + [
        i for i in joints if int(mj_model.jnt_type[i]) != slide
    ]
    return ordered.index(k)


def short_name(label: str) -> str:
    """A Newton label without its path (``"serial7/worldbody/link1/j1"`` -> ``"j1"``).

    Parameters
    ----------
    label : str

    Returns
    -------
    str
    """
    return label.rsplit("/", 1)[-1]


@dataclass(frozen=True)
class NewtonJointPair:
    """One MuJoCo joint and the Newton coordinates it maps to.

    Parameters
    ----------
    name : str
        Canonical (MuJoCo) joint name.
    kind : str
        MuJoCo type: ``"free"``, ``"ball"``, ``"hinge"`` or ``"slide"``.
    joint : int
        Newton's joint index.
    qadr, vadr : int
        Canonical position/velocity addresses.
    nq, nv : int
        Newton's coordinate/dof addresses (in one world).
    q_offset : float
        ``q_newton = q_canonical − q_offset`` (hinge/slide only).
    """

    name: str
    kind: str
    joint: int
    qadr: int
    vadr: int
    nq: int
    nv: int
    q_offset: float = 0.0


def match_joints(mj_model: mujoco.MjModel, model: Any, path: str, mjcf: bool) -> list[NewtonJointPair]:
    """Pair every MuJoCo joint with Newton's coordinates, by name, else by the body the joint moves.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    model : newton.Model
        One world.
    path : str
        For messages.
    mjcf : bool
        The file is MJCF (an MJCF hinge or slide's Newton coordinate is ``qpos − ref``).

    Returns
    -------
    list of NewtonJointPair
        In canonical order.

    Raises
    ------
    NewtonLoadError
        Naming the joints found in one engine only and those of incompatible types.
    """
    names = mujoco_joint_names(mj_model)
    jtype = model.joint_type.numpy()
    q_start, qd_start = model.joint_q_start.numpy(), model.joint_qd_start.numpy()
    child = model.joint_child.numpy()
    labels = [short_name(x) for x in model.joint_label]
    bodies = [short_name(x) for x in model.body_label]
    moving = [j for j in range(len(labels)) if qd_start[j + 1] > qd_start[j]]
    by_name = {labels[j]: j for j in moving}
    by_body = {bodies[child[j]]: j for j in moving}
    for welded, carrier in _welded_below_free(model).items():  # a massless "world" link floated in place of base_link
        by_body.setdefault(bodies[welded], carrier)
    pairs: list[NewtonJointPair] = []
    missing: list[str] = []
    mismatch: list[str] = []
    used: set[int] = set()
    for k, name in enumerate(names):
        kind = MJ_KIND[int(mj_model.jnt_type[k])]
        body = int(mj_model.jnt_bodyid[k])
        found = by_name.get(name)
        j = by_body.get(mj_model.body(body).name) if found is None else found
        if j is None:
            missing.append(name)
            continue
        if int(jtype[j]) not in _COMPATIBLE[kind]:
            mismatch.append(f"{name}: mujoco {kind} vs newton type {int(jtype[j])}")
            continue
        within = d6_position(mj_model, body, k) if int(jtype[j]) == D6 else 0
        used.add(j)
        offset = float(mj_model.qpos0[mj_model.jnt_qposadr[k]]) if mjcf and kind in ("hinge", "slide") else 0.0
        pairs.append(
            NewtonJointPair(
                name,
                kind,
                j,
                int(mj_model.jnt_qposadr[k]),
                int(mj_model.jnt_dofadr[k]),
                int(q_start[j]) + within,
                int(qd_start[j]) + within,
                offset,
            )
        )
    extra = [labels[j] for j in moving if j not in used]
    n_dof = sum(_SIZES[p.kind][1] for p in pairs)
    failure = mismatch_message(path, "Newton", missing, extra, mismatch)
    if failure is None and n_dof != int(model.joint_dof_count):
        dofs = f"Newton has {int(model.joint_dof_count)} dofs, MuJoCo {mj_model.nv}"
        failure = mismatch_message(path, "Newton", [], [], [], dofs)
    if failure is not None:
        raise NewtonLoadError(failure)
    return pairs


def _welded_below_free(model: Any) -> dict[int, int]:
    """Body -> free joint, for the bodies welded at the identity (fixed joints, no offset) below a free joint's body.

    Newton floats a URDF's root link; when that link is a massless ``world`` link welded to ``base_link``, MuJoCo
    floats ``base_link``: the same motion, since the weld is the identity.
    """
    jtype, parent, child = model.joint_type.numpy(), model.joint_parent.numpy(), model.joint_child.numpy()
    X_p, X_c = model.joint_X_p.numpy(), model.joint_X_c.numpy()
    identity = np.array([0, 0, 0, 0, 0, 0, 1.0])
    carrier = {int(child[j]): j for j in range(len(jtype)) if int(jtype[j]) == FREE}
    out: dict[int, int] = {}
    for j in range(len(jtype)):  # parents come before children
        p = int(parent[j])
        if int(jtype[j]) == FIXED and p in carrier and np.allclose(X_p[j], identity) and np.allclose(X_c[j], identity):
            carrier[int(child[j])] = carrier[p]
            out[int(child[j])] = carrier[p]
    return out


def _skew(v: np.ndarray) -> np.ndarray:
    out = np.zeros((*v.shape[:-1], 3, 3))
    out[..., 0, 1], out[..., 0, 2], out[..., 1, 2] = -v[..., 2], v[..., 1], -v[..., 0]
    out[..., 1, 0], out[..., 2, 0], out[..., 2, 1] = v[..., 2], -v[..., 1], v[..., 0]
    return out


def _rotation_wxyz(quat: np.ndarray) -> np.ndarray:
    """Rotation matrices of unit quaternions ``(w, x, y, z)``, shape (P, 3, 3)."""
    q = quat / np.linalg.norm(quat, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ],
        -2,
    )


class NewtonStateMap:
    """Canonical <-> Newton states of one world, batched over poses.

    Parameters
    ----------
    pairs : list of NewtonJointPair
    nq, nv : int
        Canonical sizes.
    n_coords, n_dofs : int
        Newton's sizes (one world).
    free_com : dict of int to ndarray
        Newton joint index of each free joint -> its child body's COM in the body frame (Newton's ``body_com``).
    """

    def __init__(
        self, pairs: list[NewtonJointPair], nq: int, nv: int, n_coords: int, n_dofs: int, free_com: dict[int, Any]
    ) -> None:
        self.pairs = pairs
        self.nq, self.nv = nq, nv
        self.n_coords, self.n_dofs = n_coords, n_dofs
        self._free_com = {j: np.asarray(c, dtype=float) for j, c in free_com.items()}

    def positions(self, qpos: np.ndarray) -> np.ndarray:
        """Newton's ``joint_q`` (P, n_coords) of canonical positions (P, nq)."""
        out = np.zeros((qpos.shape[0], self.n_coords))
        for p in self.pairs:
            if p.kind in ("hinge", "slide"):
                out[:, p.nq] = qpos[:, p.qadr] - p.q_offset
            elif p.kind == "free":
                out[:, p.nq : p.nq + 3] = qpos[:, p.qadr : p.qadr + 3]
                out[:, p.nq + 3 : p.nq + 7] = qpos[:, [p.qadr + 4, p.qadr + 5, p.qadr + 6, p.qadr + 3]]
            else:  # ball: (w, x, y, z) -> (x, y, z, w)
                out[:, p.nq : p.nq + 4] = qpos[:, [p.qadr + 1, p.qadr + 2, p.qadr + 3, p.qadr]]
        return out

    def jacobian(self, qpos: np.ndarray) -> np.ndarray:
        """``T`` (P, n_dofs, nv): Newton's ``joint_qd = T q̇`` at canonical positions."""
        P = qpos.shape[0]
        T = np.zeros((P, self.n_dofs, self.nv))
        for p in self.pairs:
            if p.kind in ("hinge", "slide"):
                T[:, p.nv, p.vadr] = 1.0
            elif p.kind == "ball":  # Newton's rate is in the parent's joint frame: R(q) ω_child
                T[:, p.nv : p.nv + 3, p.vadr : p.vadr + 3] = _rotation_wxyz(qpos[:, p.qadr : p.qadr + 4])
            else:
                R = _rotation_wxyz(qpos[:, p.qadr + 3 : p.qadr + 7])
                r = R @ self._free_com[p.joint]
                T[:, p.nv : p.nv + 3, p.vadr : p.vadr + 3] = np.eye(3)
                T[:, p.nv : p.nv + 3, p.vadr + 3 : p.vadr + 6] = -_skew(r) @ R
                T[:, p.nv + 3 : p.nv + 6, p.vadr + 3 : p.vadr + 6] = R
        return T

    def to_newton(
        self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray | None = None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]:
        """Newton's ``(joint_q, joint_qd)``, ``T`` and, given ``qacc``, ``joint_qdd`` (``T q̈ + Ṫ q̇``).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)
        qacc : ndarray, shape (P, nv), optional

        Returns
        -------
        joint_q, joint_qd, T, joint_qdd
        """
        T = self.jacobian(qpos)
        qd = np.einsum("pij,pj->pi", T, qvel)
        qdd = None
        if qacc is not None:
            qdd = np.einsum("pij,pj->pi", T, qacc)
            for p in self.pairs:
                if p.kind == "free":
                    R = _rotation_wxyz(qpos[:, p.qadr + 3 : p.qadr + 7])
                    r = R @ self._free_com[p.joint]
                    w = qd[:, p.nv + 3 : p.nv + 6]
                    qdd[:, p.nv : p.nv + 3] += np.cross(w, np.cross(w, r))
        return self.positions(qpos), qd, T, qdd
