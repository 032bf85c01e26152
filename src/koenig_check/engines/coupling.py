"""Joints that are not independent: URDF mimic joints, MJCF equality constraints, closed loops.

The kinetic energy T(q, q̇) is defined on the tree's coordinates whatever constraints act on them,
and both engines compute it that way (Pinocchio is built with ``mimic=False``; MuJoCo keeps
equality constraints out of ``M``), so a coupled model is loaded and each coupling is recorded as a
:class:`~koenig_check.findings.Finding` of kind ``COUPLING``.

Joint-to-joint relations (URDF ``<mimic>``, which MuJoCo's importer turns into a joint equality, and
MJCF ``<equality><joint polycoef=...>``) are applied to sampled states by
:func:`apply_joint_relations`, so that the states compared are states the mechanism can reach:
``y − y0 = a0 + a1 (x − x0) + … + a4 (x − x0)⁴`` (``y0``, ``x0`` the joints' ``qpos0``) and, by the
chain rule, ``ẏ = (a1 + 2 a2 (x − x0) + … + 4 a4 (x − x0)³) ẋ``.  Other couplings (tendons,
connect, weld) are not projected onto.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass

import mujoco
import numpy as np

from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.validate import parse_xml
from koenig_check.sources.catalogue import ModelSource

_LOOP = (mujoco.mjtEq.mjEQ_CONNECT, mujoco.mjtEq.mjEQ_WELD)
#: Number of polynomial coefficients of a MuJoCo joint equality.
POLY_DEGREE = 5


@dataclass(frozen=True)
class JointRelation:
    """``q[follower] − q0[follower] = Σ_k coef[k] (q[leader] − q0[leader])^k`` (``leader`` −1: a constant).

    Attributes
    ----------
    name : str
        The equality's name (or ``#i``).
    follower, leader : int
        MuJoCo joint ids.
    coefficients : tuple of float
        ``a0 … a4``.
    """

    name: str
    follower: int
    leader: int
    coefficients: tuple[float, ...]

    def positions(self, x: np.ndarray) -> np.ndarray:
        """``Σ a_k x^k`` for leader displacements ``x``."""
        return np.polynomial.polynomial.polyval(x, self.coefficients)

    def rates(self, x: np.ndarray) -> np.ndarray:
        """The derivative ``Σ k a_k x^(k-1)`` for leader displacements ``x``."""
        return np.polynomial.polynomial.polyval(x, np.polynomial.polynomial.polyder(self.coefficients))


def _name(model: mujoco.MjModel, obj: mujoco.mjtObj, i: int) -> str:
    return (mujoco.mj_id2name(model, obj, int(i)) or f"#{int(i)}") if i >= 0 else "world"


def _tendon_joints(model: mujoco.MjModel, tendon: int) -> list[str]:
    start, count = int(model.tendon_adr[tendon]), int(model.tendon_num[tendon])
    return [
        _name(model, mujoco.mjtObj.mjOBJ_JOINT, model.wrap_objid[w])
        for w in range(start, start + count)
        if model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_JOINT
    ]


def joint_relations(model: mujoco.MjModel) -> list[JointRelation]:
    """The active joint-to-joint equalities of a compiled model (URDF mimic joints included).

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    list of JointRelation
    """
    out = []
    for e in range(model.neq):
        if mujoco.mjtEq(model.eq_type[e]) != mujoco.mjtEq.mjEQ_JOINT or not model.eq_active0[e]:
            continue
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_EQUALITY, e) or f"#{e}"
        coef = tuple(float(c) for c in model.eq_data[e, :POLY_DEGREE])
        out.append(JointRelation(name, int(model.eq_obj1id[e]), int(model.eq_obj2id[e]), coef))
    return out


def apply_joint_relations(
    model: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray
) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """Make canonical states satisfy the model's joint-to-joint relations (followers follow their leaders).

    Parameters
    ----------
    model : mujoco.MjModel
    qpos : ndarray, shape (P, nq)
    qvel : ndarray, shape (P, nv)

    Returns
    -------
    qpos, qvel : ndarray
        Copies with every follower's position and velocity set from its leader's.
    notes : list of str
        What was imposed (one line per relation), and followers pushed outside their range.
    """
    relations = joint_relations(model)
    if not relations:
        return qpos, qvel, []
    qpos, qvel = np.array(qpos, dtype=float), np.array(qvel, dtype=float)
    q0 = np.asarray(model.qpos0, dtype=float)
    joint = mujoco.mjtObj.mjOBJ_JOINT
    notes = []
    # A follower may lead another relation: apply in dependency order (leaders settled first).
    pending, done = list(relations), set()
    followers = {r.follower for r in relations}
    while pending:
        ready = [r for r in pending if r.leader < 0 or r.leader not in followers or r.leader in done]
        if not ready:  # a cycle of relations: apply in file order once
            ready = pending[:1]
        for r in ready:
            ya, yv = int(model.jnt_qposadr[r.follower]), int(model.jnt_dofadr[r.follower])
            if r.leader < 0:
                qpos[:, ya] = q0[ya] + r.coefficients[0]
                qvel[:, yv] = 0.0
                how = f"held at {q0[ya] + r.coefficients[0]:.6g}"
            else:
                xa, xv = int(model.jnt_qposadr[r.leader]), int(model.jnt_dofadr[r.leader])
                x = qpos[:, xa] - q0[xa]
                qpos[:, ya] = q0[ya] + r.positions(x)
                qvel[:, yv] = r.rates(x) * qvel[:, xv]
                how = f"set from {_name(model, joint, r.leader)!r}"
            notes.append(
                f"coupling {r.name!r}: joint {_name(model, joint, r.follower)!r} {how} "
                f"(polynomial {list(r.coefficients)}), position and velocity"
            )
            lo, hi = model.jnt_range[r.follower]
            outside = (qpos[:, ya] < lo) | (qpos[:, ya] > hi)
            if model.jnt_limited[r.follower] and hi > lo and outside.any():
                notes.append(
                    f"coupling {r.name!r}: joint {_name(model, joint, r.follower)!r} outside its range "
                    f"[{lo:g}, {hi:g}] in {int(outside.sum())} pose(s) (first: row {int(np.argmax(outside))})"
                )
            done.add(r.follower)
            pending.remove(r)
    return qpos, qvel, notes


def _equality_findings(model: mujoco.MjModel) -> list[Finding]:
    out = []
    for e in range(model.neq):
        kind = mujoco.mjtEq(model.eq_type[e])
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_EQUALITY, e) or f"#{e}"
        a, b = int(model.eq_obj1id[e]), int(model.eq_obj2id[e])
        active = bool(model.eq_active0[e])
        values: dict[str, object] = {} if active else {"active": False}
        hint = ""
        if kind in _LOOP:
            obj = mujoco.mjtObj(model.eq_objtype[e])
            what = "sites" if obj == mujoco.mjtObj.mjOBJ_SITE else "bodies"
            summary = f"{kind.name[5:].lower()} closes a loop between {what}"
            values |= {"between": [_name(model, obj, a), _name(model, obj, b) if b >= 0 else "world"]}
            hint = "T is evaluated on the tree's coordinates; sampled states are not projected onto the loop"
        elif kind == mujoco.mjtEq.mjEQ_JOINT:
            j = mujoco.mjtObj.mjOBJ_JOINT
            summary = "couples joint to joint (joint equality)"
            values |= {
                "follower": _name(model, j, a),
                "leader": _name(model, j, b) if b >= 0 else "a constant",
                "polycoef": [float(c) for c in model.eq_data[e, :POLY_DEGREE]],
            }
            if active:
                hint = "sampled states satisfy it (positions, and velocities through the polynomial's derivative)"
        elif kind == mujoco.mjtEq.mjEQ_TENDON:
            tendons = [t for t in (a, b) if t >= 0]
            summary = "constrains tendon length, coupling its joints"
            values |= {
                "tendons": [_name(model, mujoco.mjtObj.mjOBJ_TENDON, t) for t in tendons],
                "joints": [j for t in tendons for j in _tendon_joints(model, t)],
            }
            hint = "T is evaluated on the tree's coordinates; sampled states are not projected onto it"
        else:
            summary = f"{kind.name} equality constrains the model"
        out.append(Finding(Kind.COUPLING, "both", f"equality {name}", summary, values, hint=hint))
    return out


def _mimic_findings(source: ModelSource, model: mujoco.MjModel) -> list[Finding]:
    out = []
    try:
        root = parse_xml(source.path).getroot()
    except ET.ParseError as err:  # TinyXML2 (MuJoCo) reads what Expat refuses, e.g. "--" inside a comment
        why = f"not looked for: Python's XML reader refuses the file ({err}); MuJoCo reads it"
        return [Finding(Kind.LOAD, "file", "mimic joints", why, {"reason": str(err)})]
    for joint in root.findall("joint"):
        mimic = joint.find("mimic")
        if mimic is None:
            continue
        follower = joint.get("name", "?")
        active = any(_name(model, mujoco.mjtObj.mjOBJ_JOINT, r.follower) == follower for r in joint_relations(model))
        out.append(
            Finding(
                Kind.COUPLING,
                "both",
                f"joint {follower}",
                "URDF mimic joint: q_follower = multiplier × q_leader + offset",
                {
                    "leader": mimic.get("joint", "?"),
                    "multiplier": float(mimic.get("multiplier", 1.0)),
                    "offset": float(mimic.get("offset", 0.0)),
                },
                hint="sampled states satisfy it (positions and velocities)"
                if active
                else "MuJoCo's importer did not turn it into a joint equality: sampled states do not satisfy it",
            )
        )
    return out


def coupling_findings(source: ModelSource, model: mujoco.MjModel) -> list[Finding]:
    """One ``COUPLING`` finding per constraint that makes joints dependent.

    Parameters
    ----------
    source : ModelSource
        The file (URDF ``<mimic>`` tags are read from it).
    model : mujoco.MjModel
        The compiled model (MJCF ``<equality>`` constraints are read from it).

    Returns
    -------
    list of Finding
        Naming the joints, bodies or tendons; none affects the kinetic energy T(q, q̇), which is
        defined on the tree's coordinates.
    """
    if source.format == "urdf":
        return _mimic_findings(source, model)
    return _equality_findings(model)
