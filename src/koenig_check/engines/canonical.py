"""Canonical coordinates: MuJoCo's ``qpos``/``qvel`` layout, in which every engine is driven.

The canonical state is MuJoCo's ``qpos``/``qvel`` layout of the MuJoCo model (``nq``/``nv`` of the
``MjModel``, joints in MuJoCo order):

* hinge, slide: one angle/displacement (``qpos0`` holds the joint's ``ref``), one rate;
* ball: ``qpos`` quaternion ``(w, x, y, z)`` of the child relative to the parent, ``qvel`` angular
  velocity in the child (local) frame;
* free: ``qpos`` = world position of the body origin then quaternion ``(w, x, y, z)`` world <- body;
  ``qvel`` = *linear velocity of the body origin in the world frame*, then *angular velocity in the
  body (local) frame* (verified for MuJoCo 4.0 with ``mj_integratePos`` and ``cvel``).

Each engine's state map converts canonical states to the engine's own (:class:`VelocityMapped` carries
forces and mass matrices back); joints are matched by name (:func:`mujoco_joint_names`), never by index.
"""

from __future__ import annotations

import mujoco
import numpy as np


def mujoco_joint_names(model: mujoco.MjModel) -> list[str]:
    """Return the canonical name of every MuJoCo joint.

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    list of str
        The joint's name, or for an unnamed joint the name Pinocchio's MJCF parser gives it
        (``"<body>_free"`` for a free joint, ``"<body>Joint_<k>"`` otherwise, ``k`` counting the
        body's joints; ``<body>`` as :func:`pinocchio_body_name`).
    """
    names = []
    for j in range(model.njnt):
        name = model.joint(j).name
        if not name:
            body = int(model.jnt_bodyid[j])
            bname = pinocchio_body_name(model, body)
            k = j - int(model.body_jntadr[body])
            name = f"{bname}_free" if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE else f"{bname}Joint_{k}"
        names.append(name)
    return names


def pinocchio_body_name(model: mujoco.MjModel, body: int) -> str:
    """The name Pinocchio's MJCF parser gives a MuJoCo body.

    Parameters
    ----------
    model : mujoco.MjModel
    body : int

    Returns
    -------
    str
        The body's own name; for an unnamed body its parent's name followed by ``"Bis"``, a top-level body's
        parent (the world) counting as ``""`` (``"Bis"``, ``"BisBis"`` for an unnamed body in it).
    """
    name = model.body(body).name
    if name or body == 0:
        return name if body else ""
    parent = int(model.body_parentid[body])
    return (pinocchio_body_name(model, parent) if parent else "") + "Bis"


#: (qpos, qvel) sizes of MuJoCo's joint types with more than one coordinate.
_JOINT_SIZES = {int(mujoco.mjtJoint.mjJNT_FREE): (7, 6), int(mujoco.mjtJoint.mjJNT_BALL): (4, 3)}


def joint_sizes(joint_type: int) -> tuple[int, int]:
    """The number of position and velocity coordinates of a MuJoCo joint type.

    Parameters
    ----------
    joint_type : int
        A ``mujoco.mjtJoint`` value (``model.jnt_type[j]``).

    Returns
    -------
    nq, nv : int
        (7, 6) for a free joint, (4, 3) for a ball, (1, 1) for a hinge or a slide.
    """
    return _JOINT_SIZES.get(int(joint_type), (1, 1))


def mujoco_coordinate_names(model: mujoco.MjModel) -> tuple[list[str], list[str]]:
    """Name every canonical position and velocity coordinate after its joint.

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    qpos_names, qvel_names : list of str
        The joint's canonical name (:func:`mujoco_joint_names`) for one-coordinate joints,
        ``"name[k]"`` for the k-th coordinate of a free or ball joint.
    """
    qnames = [""] * model.nq
    vnames = [""] * model.nv
    for j, name in enumerate(mujoco_joint_names(model)):
        nq, nv = joint_sizes(model.jnt_type[j])
        for names, adr, size in ((qnames, model.jnt_qposadr[j], nq), (vnames, model.jnt_dofadr[j], nv)):
            for k in range(size):
                names[adr + k] = name if size == 1 else f"{name}[{k}]"
    return qnames, vnames


class VelocityMapped:
    """Forces and mass matrices carried into canonical coordinates by ``T`` of ``v_engine = T q̇``.

    A state map defines :meth:`velocity_matrix`; power is the same in both coordinates, so
    ``τ = Tᵀ τ_engine`` and ``M = Tᵀ M_engine T``.
    """

    def velocity_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """``T`` with ``v_engine = T q̇``, shape (P, nv_engine, nv)."""
        raise NotImplementedError

    def force_to_canonical(self, qpos: np.ndarray, tau: np.ndarray) -> np.ndarray:
        """Convert the engine's generalized forces to canonical ones, ``τ = Tᵀ τ_engine`` (same power).

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        tau : ndarray, shape (P, nv_engine)

        Returns
        -------
        ndarray, shape (P, nv)
        """
        return np.einsum("pij,pi->pj", self.velocity_matrix(qpos), np.atleast_2d(tau))

    def matrix_to_canonical(self, qpos: np.ndarray, m_engine: np.ndarray) -> np.ndarray:
        """Convert the engine's mass matrix to canonical coordinates, ``M = Tᵀ M_engine T``.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        m_engine : ndarray, shape (P, nv_engine, nv_engine)

        Returns
        -------
        ndarray, shape (P, nv, nv)
        """
        T = self.velocity_matrix(qpos)
        return np.swapaxes(T, -1, -2) @ m_engine @ T


def segment_of_body(mj_model: mujoco.MjModel) -> dict[str, str]:
    """MuJoCo body name -> the segment (name of its carrier's last joint) that moves it ('' if static).

    Parameters
    ----------
    mj_model : mujoco.MjModel

    Returns
    -------
    dict of str to str
    """
    seg = segment_by_body_id(mj_model)
    names = (mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(mj_model.nbody))
    return {name: seg[b] for b, name in enumerate(names) if name}


def segment_by_body_id(mj_model: mujoco.MjModel) -> list[str]:
    """The segment of every MuJoCo body, by body id ('' for the world and static bodies).

    Parameters
    ----------
    mj_model : mujoco.MjModel

    Returns
    -------
    list of str
    """
    names = mujoco_joint_names(mj_model)
    seg = [""] * mj_model.nbody
    for b in range(1, mj_model.nbody):  # parents come before children
        if mj_model.body_jntnum[b] > 0:
            seg[b] = names[mj_model.body_jntadr[b] + mj_model.body_jntnum[b] - 1]
        else:
            seg[b] = seg[mj_model.body_parentid[b]]
    return seg
