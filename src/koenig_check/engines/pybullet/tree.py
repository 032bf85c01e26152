"""A body loaded in PyBullet read as numpy arrays: its links, joints, masses and inertial frames.

Row 0 is the base (PyBullet's link ``-1``), row ``k`` PyBullet's link ``k - 1``.  PyBullet keeps every URDF link
(a fixed joint is a link of its own) unless ``URDF_MERGE_FIXED_LINKS`` merges them.  Per link it holds the mass,
the principal moments of inertia (``getDynamicsInfo``'s "local inertia diagonal": it diagonalizes every
``<inertial>``, a rotation of about 1e-8 lost on the way) and the inertial frame (the principal axes at the COM) in
the link's frame.  Its kinematics answer for the inertial frame: ``getLinkState`` gives the COM and the principal
axes in the world, ``getBasePositionAndOrientation`` the same for the base.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from koenig_check.engines.pybullet.client import Client

#: PyBullet's joint types (``getJointInfo``'s third entry) by value.
JOINT_TYPES = {0: "revolute", 1: "prismatic", 2: "spherical", 3: "planar", 4: "fixed"}


@dataclass(frozen=True)
class BodyTree:
    """One PyBullet body's links, base first.

    Parameters
    ----------
    link_names : tuple of str
        The URDF link each row is (row 0: the base).
    joint_names : tuple of str
        The joint that moves each link (row 0: ``""``).
    joint_types : tuple of str
        ``"revolute"``, ``"prismatic"``, ``"fixed"``, ... (row 0: ``"base"``).
    parent : ndarray of int, shape (L,)
        Each row's parent row (row 0: -1).
    u_index : ndarray of int, shape (L,)
        The joint's velocity coordinate in PyBullet's joint velocities (-1 for a fixed joint and the base).
    mass : ndarray, shape (L,)
    principal : ndarray, shape (L, 3)
        Principal moments of inertia about the COM.
    inertial_pos : ndarray, shape (L, 3)
        The COM in the link's frame.
    inertial_rot : ndarray, shape (L, 3, 3)
        The principal axes in the link's frame (link <- inertial).
    """

    link_names: tuple[str, ...]
    joint_names: tuple[str, ...]
    joint_types: tuple[str, ...]
    parent: np.ndarray
    u_index: np.ndarray
    mass: np.ndarray
    principal: np.ndarray
    inertial_pos: np.ndarray
    inertial_rot: np.ndarray

    @property
    def n_dofs(self) -> int:
        """The number of joint velocity coordinates (the base's left out)."""
        return int((self.u_index >= 0).sum())

    def central_inertia(self) -> np.ndarray:
        """Each link's inertia about its COM in the link's frame, shape (L, 3, 3)."""
        R = self.inertial_rot
        return np.einsum("lij,lj,lkj->lik", R, self.principal, R)


def read_tree(client: Client, body: int) -> BodyTree:
    """Read a loaded body's links, joints and inertial data from PyBullet.

    Parameters
    ----------
    client : Client
    body : int

    Returns
    -------
    BodyTree
    """
    base_name = client.call("getBodyInfo", body)[0].decode()
    n = int(client.call("getNumJoints", body))
    links, joints, types = [base_name], [""], ["base"]
    parent, u_index = [-1], [-1]
    for j in range(n):
        info = client.call("getJointInfo", body, j)
        joints.append(info[1].decode())
        types.append(JOINT_TYPES.get(int(info[2]), str(info[2])))
        links.append(info[12].decode())
        parent.append(int(info[16]) + 1)
        u_index.append(int(info[4]) if int(info[2]) != 4 else -1)
    mass, principal, pos, rot = [], [], [], []
    for link in range(-1, n):
        dyn = client.call("getDynamicsInfo", body, link)
        mass.append(float(dyn[0]))
        principal.append(np.asarray(dyn[2], dtype=float))
        pos.append(np.asarray(dyn[3], dtype=float))
        rot.append(quat_matrix(np.asarray(dyn[4], dtype=float)))
    u = np.asarray(u_index, dtype=int)
    offset = u[u >= 0].min() if (u >= 0).any() else 0
    u[u >= 0] -= offset  # PyBullet counts the base's 6 (floating or not); the joints' velocities start at 0 here
    return BodyTree(
        tuple(links),
        tuple(joints),
        tuple(types),
        np.asarray(parent, dtype=int),
        u,
        np.asarray(mass, dtype=float),
        np.asarray(principal, dtype=float).reshape(-1, 3),
        np.asarray(pos, dtype=float).reshape(-1, 3),
        np.asarray(rot, dtype=float).reshape(-1, 3, 3),
    )


def quat_matrix(quat_xyzw: np.ndarray) -> np.ndarray:
    """Rotation matrices of PyBullet's quaternions ``(x, y, z, w)``, normalized in double precision.

    Parameters
    ----------
    quat_xyzw : ndarray, shape (..., 4)

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    q = np.asarray(quat_xyzw, dtype=float)
    return Rotation.from_quat(q.reshape(-1, 4)).as_matrix().reshape(*q.shape[:-1], 3, 3)


def matrix_quat(matrix: np.ndarray) -> np.ndarray:
    """PyBullet's quaternions ``(x, y, z, w)`` of rotation matrices.

    Parameters
    ----------
    matrix : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 4)
    """
    m = np.asarray(matrix, dtype=float)
    return Rotation.from_matrix(m.reshape(-1, 3, 3)).as_quat().reshape(*m.shape[:-2], 4)
