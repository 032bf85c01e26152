"""Import parity: whether MuJoCo and Pinocchio see the same robot in the same file.

Everything is measured through the engines' own answers at the canonical reference
configuration (MuJoCo ``qpos0``): segment mass, centre of mass, inertia tensor and pole
from :meth:`segment_states`; joint axes as the angular velocity and pole velocity of a
dof's own segment under a unit rate of that dof (a column of each engine's Jacobian);
armature as the diagonal of the engine's mass matrix minus the rigid-body mass matrix
rebuilt from those Jacobians.  Model-level findings come from the load notes and from
the file's own compiler options.

Root causes come first (:mod:`koenig_check.diagnosis.pair_causes`): a construct Pinocchio's MJCF parser reads
differently (a geom mass from a default class, a dropped root-body pose, ...) is one typed
:class:`~koenig_check.findings.Finding` naming the elements, and the segments it explains are not
listed again as separate reasons.  A dropped root pose is a constant world transform: Pinocchio's
segments are compared after it is removed.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.diagnosis.pair_causes import model_causes
from koenig_check.diagnosis.parity_report import PARITY_RTOL, DofParity, ParityReport, SegmentParity
from koenig_check.engines.canonical import mujoco_coordinate_names
from koenig_check.engines.sampling import random_states
from koenig_check.engines.specs import parity_pair
from koenig_check.findings import Kind
from koenig_check.modelfile.compiler import compiler_findings
from koenig_check.segments import SegmentStates

__all__ = ["PARITY_RTOL", "DofParity", "ParityReport", "SegmentParity", "import_parity", "segment_labels"]


def segment_labels(pair: Any) -> dict[str, str]:
    """Each segment as the user wrote it: ``"link forearm (joint elbow)"``, or ``"body hand"`` when they share a name.

    A segment is keyed by the joint that moves it; the user edits the link (URDF) or body (MJCF) that joint
    moves, the first of the bodies welded together in the segment.

    Parameters
    ----------
    pair : LoadedModel

    Returns
    -------
    dict of str to str
    """
    word = "link" if pair.source.format == "urdf" else "body"
    out = {}
    for segment, body in pair.mujoco.segment_bodies().items():
        if not body:  # an unnamed body: by its place (the body it hangs from) and its joint
            out[segment] = f"unnamed {word} in {_parent_words(pair, segment, word)} (joint {segment})"
        else:
            out[segment] = f"{word} {body}" if body == segment else f"{word} {body} (joint {segment})"
    return out


def _parent_words(pair: Any, segment: str, word: str) -> str:
    """Where the unnamed body that starts a segment hangs: ``body a``, ``the world``, ``an unnamed body``."""
    import mujoco

    model = pair.mujoco.model
    dofs = [d for d, s in enumerate(pair.mujoco.dof_segments()) if s == segment]
    if not dofs:
        return "the model"
    parent = int(model.body_parentid[int(model.dof_bodyid[dofs[0]])])
    name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, parent) or ""
    return "the world" if parent == 0 else f"{word} {name}" if name else f"an unnamed {word}"


def _unit_rate_states(engine: Any, qpos0: np.ndarray, nv: int) -> SegmentStates:
    """Segment states at ``qpos0`` for a unit rate of each dof in turn (one pose per dof)."""
    return engine.segment_states(np.tile(qpos0, (max(nv, 1), 1)), np.eye(max(nv, 1))[:, :nv])


def _rigid_mass_matrix(states: SegmentStates) -> np.ndarray:
    """Σ_b m J_vᵀ J_v + J_ωᵀ I J_ω from the unit-rate states (pose axis = dof)."""
    Jv = states.v_com  # (nv, B, 3)
    Jw = states.omega
    I_world = states.inertia_world()[0]  # same configuration for every row
    return np.einsum("b,ibk,jbk->ij", states.mass, Jv, Jv) + np.einsum("ibk,bkl,jbl->ij", Jw, I_world, Jw)


def import_parity(pair: Any, rtol: float = PARITY_RTOL, extra_poses: int = 3, seed: int = 0) -> ParityReport:
    """Compare what MuJoCo and Pinocchio imported from the same model.

    Parameters
    ----------
    pair : LoadedModel
        From :func:`koenig_check.engines.load_model`.
    rtol : float
        Relative tolerance; lengths are compared with ``rtol`` × the model's size,
        inertias with ``rtol`` × the inertia about the anchor (largest central moment + m d²).
    extra_poses : int
        Random poses (besides ``qpos0``) at which the mass matrices are compared.
    seed : int

    Returns
    -------
    ParityReport
    """
    mj, pn = pair.mujoco, pair.pinocchio
    mj_model = mj.model
    qpos0 = np.array(mj_model.qpos0, dtype=float)
    nv = mj_model.nv
    report = ParityReport(model=str(getattr(pair, "path", getattr(mj, "path", "?"))), rtol=rtol)
    report.causes, offset = model_causes(pair)
    report.frame_offset = offset
    report.segment_labels = segment_labels(pair)
    sa = _unit_rate_states(mj, qpos0, nv)
    sb = _unit_rate_states(pn, qpos0, nv)
    sb = sb if offset is None else offset.segment_states(sb)  # a root pose Pinocchio dropped put back
    report.total_mass = (float(sa.mass.sum()), float(sb.mass.sum()))
    # Pinocchio lumps the links welded to the world into its universe joint: its sum is the file's whole mass
    # (MuJoCo's compiler may have fused them away: fusestatic).
    report.model_mass = float(sum(Y.mass for Y in pn.model.inertias))
    names_a, names_b = list(sa.names), list(sb.names)
    massless = {c.engine: set(c.segments) for c in report.causes if c.kind is Kind.SEGMENTS}
    first, second = parity_pair()  # MuJoCo (sa, names_a) and Pinocchio (sb, names_b)
    report.massless_in_pinocchio = [n for n in names_a if n not in names_b and n in massless.get(second, ())]
    report.massless_in_mujoco = [n for n in names_b if n not in names_a and n in massless.get(first, ())]
    report.only_in_mujoco = [n for n in names_a if n not in names_b and n not in report.massless_in_pinocchio]
    report.only_in_pinocchio = [n for n in names_b if n not in names_a and n not in report.massless_in_mujoco]
    common = [n for n in names_a if n in names_b]
    A, B = sa.select(segments=common), sb.select(segments=common)
    size = max(float(np.abs(A.com[0]).max(initial=0.0)), float(np.abs(A.pole[0]).max(initial=0.0)), 1.0)
    Ia, Ib = A.inertia_world()[0], B.inertia_world()[0]
    about_a, about_b = A.inertia_about_anchor(), B.inertia_about_anchor()
    for k, name in enumerate(common):
        ma, mb = float(A.mass[k]), float(B.mass[k])
        com_d = float(np.linalg.norm(A.com[0, k] - B.com[0, k]))
        pole_d = float(np.linalg.norm(A.pole[0, k] - B.pole[0, k]))
        fro = float(np.linalg.norm(Ia[k] - Ib[k]))
        moments = (np.linalg.eigvalsh(Ia[k]), np.linalg.eigvalsh(Ib[k]))
        scale_I = max(float(about_a[k]), float(about_b[k]), 1e-300)  # the inertia about the anchor
        relative = {
            "mass": abs(ma - mb) / max(ma, mb, 1e-300),
            "com": com_d / size,
            "inertia": fro / scale_I,
            "anchor": pole_d / size,
        }
        causes = tuple(q for q, value in relative.items() if value > rtol)
        report.segments.append(SegmentParity(name, (ma, mb), com_d, fro, moments, pole_d, causes, relative))
    # Dofs: the joint's own segment under a unit rate of the dof (its angular velocity and its pole's
    # velocity: the joint axis, free of any difference in COMs or downstream links) and armature.
    own = {name: k for k, name in enumerate(common)}
    dof_segment = mj.dof_segments()
    jac_scale = max(float(np.abs(np.concatenate([A.omega, A.v_pole], axis=-1)).max(initial=0.0)), 1.0)
    q_check = np.vstack([qpos0, random_states(mj_model, extra_poses, seed)[0]])
    Ma, Mb = mj.mass_matrix(q_check), pn.mass_matrix(q_check)
    denom = max(float(np.abs(Ma).max(initial=0.0)), 1e-300)
    report.mass_matrix_max_rel = float(np.abs(Ma - Mb).max(initial=0.0) / denom)
    arm_a = np.diag(Ma[0]) - np.diag(_rigid_mass_matrix(sa))
    arm_b = np.diag(Mb[0]) - np.diag(_rigid_mass_matrix(sb))
    m_scale = max(float(np.abs(np.diag(Ma[0])).max(initial=0.0)), 1e-300)
    for d, joint in enumerate(mujoco_coordinate_names(mj_model)[1]):
        seg = own.get(dof_segment[d])
        missing = "" if seg is not None else _missing_segment(dof_segment[d], report)
        if seg is None:  # the dof's segment exists in one engine only: reported with the segments
            diff = float("nan")
        else:
            diff = float(
                max(np.abs(A.omega[d, seg] - B.omega[d, seg]).max(), np.abs(A.v_pole[d, seg] - B.v_pole[d, seg]).max())
            )
        relative = {"axis": diff / (jac_scale * size), "armature": abs(arm_a[d] - arm_b[d]) / m_scale}
        causes = tuple(q for q, value in relative.items() if value > rtol)  # nan (segment missing) is no axis cause
        arms = (float(arm_a[d]), float(arm_b[d]))
        report.dofs.append(DofParity(d, joint, arms, diff, causes, relative, missing))
    report.findings = _pair_notes(pair, dropped_root=offset is not None) + compiler_findings(
        Path(str(mj.path)), mj_model
    )
    masses_a = A.mass
    masses_b = B.mass
    if len(common) > 1 and np.all(masses_b > 0):
        ratio = masses_a / masses_b
        if np.ptp(ratio) <= rtol * ratio.max() and abs(ratio[0] - 1) > rtol:
            report.findings.append(
                f"every segment mass differs by the same factor {ratio[0]:.9g} (MuJoCo / Pinocchio): "
                "a total-mass rescaling honoured by one engine only"
            )
    return report


def _missing_segment(segment: str, report: ParityReport) -> str:
    """Why a dof's segment has no counterpart to compare its Jacobian with (``segment j2 massless in Pinocchio``)."""
    for names, where in (
        (report.massless_in_pinocchio, "massless in Pinocchio"),
        (report.massless_in_mujoco, "massless in MuJoCo"),
        (report.only_in_mujoco, "only in MuJoCo"),
        (report.only_in_pinocchio, "only in Pinocchio"),
    ):
        if segment in names:
            return f"segment {segment} {where}"
    return f"segment {segment} has no mass in either engine"


def _pair_notes(pair: Any, dropped_root: bool = False) -> list[str]:
    """The pair's load findings as lines; segment poses that differ only by a dropped root pose say so."""
    lines = []
    for f in getattr(pair, "findings", []):
        text = f.message()
        if dropped_root and f.kind is Kind.FRAME and f.engine == "both":  # the world transform a root cause names
            text += "; the dropped root-body pose explains it (a constant transform, no effect on the energy)"
        lines.append(text)
    return lines
