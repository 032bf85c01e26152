"""Pair the joints of two MuJoCo models by name: which coordinates of one are which of the other."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from koenig_check.engines.canonical import joint_sizes, mujoco_joint_names
from koenig_check.engines.mujoco.loader import root_free_joint


@dataclass(frozen=True)
class JointPairing:
    """Index maps from the original's canonical coordinates to the export's.

    Parameters
    ----------
    qpos_original, qpos_export : ndarray of int
        ``qpos_export[:, qpos_export_idx] = qpos_original[:, qpos_original_idx]``.
    dof_original, dof_export : ndarray of int
        Paired velocity coordinates.
    problems : tuple of str
        Joints only one side has, or joints of different kinds (empty when the pairing is complete).
    """

    qpos_original: np.ndarray
    qpos_export: np.ndarray
    dof_original: np.ndarray
    dof_export: np.ndarray
    problems: tuple[str, ...]

    def export_states(
        self, qpos: np.ndarray, qvel: np.ndarray, export: mujoco.MjModel
    ) -> tuple[np.ndarray, np.ndarray]:
        """The original's canonical states written in the export's layout.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq original)
        qvel : ndarray, shape (P, nv original)
        export : mujoco.MjModel

        Returns
        -------
        qpos, qvel : ndarrays in the export's layout
        """
        q = np.tile(np.asarray(export.qpos0, dtype=float), (qpos.shape[0], 1))
        v = np.zeros((qvel.shape[0], export.nv))
        q[:, self.qpos_export] = qpos[:, self.qpos_original]
        v[:, self.dof_export] = qvel[:, self.dof_original]
        return q, v


def _joints(model: mujoco.MjModel) -> dict[str, int]:
    return {name: j for j, name in enumerate(mujoco_joint_names(model))}


def pair_joints(original: mujoco.MjModel, export: mujoco.MjModel) -> JointPairing:
    """Pair joints by name; a root free joint pairs with the other side's root free joint whatever its name.

    Parameters
    ----------
    original, export : mujoco.MjModel

    Returns
    -------
    JointPairing
    """
    a, b = _joints(original), _joints(export)
    root_a, root_b = root_free_joint(original), root_free_joint(export)
    if root_a and root_b and root_a != root_b:
        b[root_a] = b.pop(root_b)
    problems = []
    qa: list[int] = []
    qb: list[int] = []
    da: list[int] = []
    db: list[int] = []
    only_a, only_b = sorted(set(a) - set(b)), sorted(set(b) - set(a))
    if only_a:
        problems.append("joints missing in the export: " + ", ".join(only_a))
    if only_b:
        problems.append("joints only in the export: " + ", ".join(only_b))
    for name, ja in a.items():
        if name not in b:
            continue
        jb = b[name]
        ta, tb = int(original.jnt_type[ja]), int(export.jnt_type[jb])
        if ta != tb:
            problems.append(f"joint {name}: type {ta} in the original, {tb} in the export")
            continue
        nq, nv = joint_sizes(ta)
        qa += range(int(original.jnt_qposadr[ja]), int(original.jnt_qposadr[ja]) + nq)
        qb += range(int(export.jnt_qposadr[jb]), int(export.jnt_qposadr[jb]) + nq)
        da += range(int(original.jnt_dofadr[ja]), int(original.jnt_dofadr[ja]) + nv)
        db += range(int(export.jnt_dofadr[jb]), int(export.jnt_dofadr[jb]) + nv)
    return JointPairing(np.array(qa, int), np.array(qb, int), np.array(da, int), np.array(db, int), tuple(problems))
