"""What Newton does to the user's robot that the file does not say, measured on this robot with Newton's own arrays.

Each function compares the robot as checked with Newton's model of the file under one of its loading options
(given to it, read from the one parsed builder where the option allows, or loaded again), or reads the file as
written; it compares Newton's own arrays: the body masses and inertias ``finalize()`` leaves, or the mass matrix
``eval_mass_matrix`` gives.  They return plain values; :mod:`koenig_check.engines.newton.findings` turns them into
findings with the catalogue's cause ids.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.newton.state_map import FIXED, short_name
from koenig_check.modelfile.urdf_links import links_without_inertial

#: Poses (besides the file's pose) at which an option's effect on M is measured, and their seed.
EFFECT_POSES = 4
_SEED = 20261128


@dataclass(frozen=True)
class BodyChange:
    """A body whose mass properties Newton changed from what it read.

    Parameters
    ----------
    body : str
        The body (link) as the file names it.
    read_mass, newton_mass : float
    read_inertia, newton_inertia : list of float
        Diagonal of the central inertia (body axes) before and after.
    """

    body: str
    read_mass: float
    newton_mass: float
    read_inertia: list[float]
    newton_inertia: list[float]


def _diag(inertia: np.ndarray) -> list[float]:
    return [float(x) for x in np.round(np.diagonal(inertia), 12)]


def static_bodies(model: Any) -> set[int]:
    """The bodies welded to the world (fixed joints up to the world): they do not move, their mass changes nothing.

    Parameters
    ----------
    model : newton.Model

    Returns
    -------
    set of int
    """
    jtype, parent, child = model.joint_type.numpy(), model.joint_parent.numpy(), model.joint_child.numpy()
    out: set[int] = set()
    for j in range(len(jtype)):  # parents come before children
        if int(jtype[j]) == FIXED and (parent[j] < 0 or int(parent[j]) in out):
            out.add(int(child[j]))
    return out


def validation_changes(raw: Any, model: Any) -> list[BodyChange]:
    """The bodies whose inertia ``finalize()``'s inertia validation changed.

    Zero inertias replaced, 1e-6 kg·m² added, triangle-inequality violations balanced: measured against the same
    file finalized with ``skip_validation_inertia=True``.

    Parameters
    ----------
    raw : newton.Model
        The file finalized with ``skip_validation_inertia=True``.
    model : newton.Model
        The file as Newton users load it (validation on).

    Returns
    -------
    list of BodyChange
    """
    out = []
    m0, m1 = raw.body_mass.numpy(), model.body_mass.numpy()
    i0, i1 = raw.body_inertia.numpy(), model.body_inertia.numpy()
    static = static_bodies(model)
    for b, label in enumerate(model.body_label):
        if b in static:
            continue
        scale = max(float(np.abs(i0[b]).max()), float(np.abs(i1[b]).max()), 1e-300)
        if m0[b] != m1[b] or float(np.abs(i0[b] - i1[b]).max()) > 1e-6 * scale:
            out.append(BodyChange(short_name(label), float(m0[b]), float(m1[b]), _diag(i0[b]), _diag(i1[b])))
    return out


def collision_masses(path: Path, model: Any) -> list[BodyChange]:
    """URDF links that move, without ``<inertial>``, to which Newton gave mass (collision shapes, density 1000).

    Parameters
    ----------
    path : Path
    model : newton.Model

    Returns
    -------
    list of BodyChange
    """
    bare = set(links_without_inertial(path))
    mass, inertia = model.body_mass.numpy(), model.body_inertia.numpy()
    static = static_bodies(model)
    return [
        BodyChange(short_name(label), 0.0, float(mass[b]), [0.0, 0.0, 0.0], _diag(inertia[b]))
        for b, label in enumerate(model.body_label)
        if short_name(label) in bare and mass[b] > 0 and b not in static
    ]


def welded_massive_bodies(model: Any) -> list[str]:
    """Bodies with mass joined to a moving body by a fixed joint: what ``collapse_fixed_joints=True`` merges.

    Parameters
    ----------
    model : newton.Model

    Returns
    -------
    list of str
    """
    jtype, parent, child = model.joint_type.numpy(), model.joint_parent.numpy(), model.joint_child.numpy()
    mass = model.body_mass.numpy()
    return [
        short_name(model.body_label[child[j]])
        for j in range(len(jtype))
        if int(jtype[j]) == FIXED and parent[j] >= 0 and mass[child[j]] > 0
    ]


def effect_poses(model: Any, count: int = EFFECT_POSES) -> np.ndarray:
    """Newton ``joint_q`` rows at which an option's effect is measured: the file's pose and ``count`` random ones.

    Only one-dof joints are moved (uniformly in ±1 rad or m); free and ball joints keep the file's pose.

    Parameters
    ----------
    model : newton.Model
    count : int

    Returns
    -------
    ndarray, shape (count + 1, joint_coord_count)
    """
    q0 = model.joint_q.numpy().astype(float)
    jtype, qs, qds = model.joint_type.numpy(), model.joint_q_start.numpy(), model.joint_qd_start.numpy()
    one = [int(qs[j]) + k for j in range(len(jtype)) if int(jtype[j]) in (0, 1, 6) for k in range(qds[j + 1] - qds[j])]
    rows = np.repeat(q0[None], count + 1, axis=0)
    rows[1:, one] += np.random.default_rng(_SEED).uniform(-1.0, 1.0, (count, len(one)))
    return rows


def mass_matrices(model: Any, joint_q: np.ndarray) -> np.ndarray:
    """Newton's ``eval_mass_matrix`` (armature included) of one-world ``model`` at each row of ``joint_q``.

    Parameters
    ----------
    model : newton.Model
        One world, one articulation or several.
    joint_q : ndarray, shape (P, joint_coord_count)

    Returns
    -------
    ndarray, shape (P, joint_dof_count, joint_dof_count)
    """
    import newton
    import warp as wp

    art, qds = model.articulation_start.numpy(), model.joint_qd_start.numpy()
    blocks = [(int(qds[art[a]]), int(qds[art[a + 1]])) for a in range(len(art) - 1)]
    n = int(model.joint_dof_count)
    out = np.zeros((joint_q.shape[0], n, n))
    for p, q in enumerate(joint_q):
        state = model.state()
        newton.eval_fk(model, wp.array(q.astype(np.float32), dtype=wp.float32, device="cpu"), model.joint_qd, state)
        H = newton.eval_mass_matrix(model, state).numpy()  # type: ignore[union-attr]  # Warp's array types
        for k, (lo, hi) in enumerate(blocks):
            out[p, lo:hi, lo:hi] = H[k, : hi - lo, : hi - lo]
    return out


def option_effect(model: Any, other: Any) -> float:
    """How much another loading of the same file changes Newton's M, on the dof it changes most.

    ``max_i |ΔM_ii| / M_ii`` and ``max |ΔM| / max |M|`` over :func:`effect_poses`, the larger: a gripper joint
    whose M entry changes by 4 % is a difference even where the base's entries dwarf it.

    Parameters
    ----------
    model, other : newton.Model
        The same robot's dofs in the same order (``collapse_fixed_joints`` keeps every moving joint).

    Returns
    -------
    float
        ``nan`` when the two do not have the same dofs.
    """
    if int(model.joint_dof_count) != int(other.joint_dof_count):
        return float("nan")
    rows = effect_poses(model)
    M, M2 = mass_matrices(model, rows), mass_matrices(other, rows)
    whole = float(np.abs(M2 - M).max() / max(float(np.abs(M).max()), 1e-300))
    d, d2 = np.diagonal(M, axis1=1, axis2=2), np.diagonal(M2, axis1=1, axis2=2)
    floor = 1e-9 * max(float(np.abs(d).max()), 1e-300)  # a dof that moves nothing (zero M entry) is not measured
    per_dof = float((np.abs(d2 - d) / np.maximum(np.abs(d), floor)).max()) if d.size else 0.0
    return max(whole, per_dof)


def joints_lost(model: Any, other: Any) -> list[str]:
    """The moving joints of ``model`` that ``other`` (the same file loaded otherwise) does not have.

    Parameters
    ----------
    model, other : newton.Model

    Returns
    -------
    list of str
    """

    def moving(m: Any) -> list[str]:
        qds = m.joint_qd_start.numpy()
        return [short_name(m.joint_label[j]) for j in range(len(m.joint_label)) if qds[j + 1] > qds[j]]

    kept = set(moving(other))
    return [j for j in moving(model) if j not in kept]


def moved_anchors(mj_model: Any, model: Any, pairs: list[Any]) -> list[tuple[str, list[float], list[float]]]:
    """MuJoCo joints that Newton turns about another point of their body (a D6 joint has one anchor).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    model : newton.Model
    pairs : list of NewtonJointPair

    Returns
    -------
    list of (joint, MuJoCo's anchor, Newton's anchor)
        Anchors in the body frame (MuJoCo's ``jnt_pos``, Newton's ``joint_X_c``), for hinges and balls.
    """
    from koenig_check.engines.canonical import mujoco_joint_names

    names = mujoco_joint_names(mj_model)
    index = {n: k for k, n in enumerate(names)}
    X_c = model.joint_X_c.numpy()
    out = []
    for p in pairs:
        if p.kind not in ("hinge", "ball"):
            continue
        mine = np.asarray(mj_model.jnt_pos[index[p.name]], dtype=float)
        theirs = np.asarray(X_c[p.joint][:3], dtype=float)
        if np.abs(mine - theirs).max() > 1e-6 * max(1.0, float(np.abs(mine).max())):
            out.append((p.name, np.round(mine, 9).tolist(), np.round(theirs, 9).tolist()))
    return out
