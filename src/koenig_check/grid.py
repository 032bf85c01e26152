"""The comparison grid: model × pose × formula × state source × reference engine → tidy records.

For each model, each engine produces its own :class:`SegmentStates` (the *state source*)
and its own kinetic energy (the *reference*).  Every formula is evaluated on each
source's states and compared with each engine's rigid-body energy (armature excluded,
totals) and, segment by segment, with ``exact`` on the same source's states.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from koenig_check.findings import Finding, Kind, root_causes
from koenig_check.formulas import FORMULAS, NotPlaneParallelError, integrate_angular_velocity
from koenig_check.formulas.point_masses import equimomental_points
from koenig_check.poses import PoseSet
from koenig_check.records import RECORD_FIELDS, RecordTable
from koenig_check.segments import SegmentStates

#: Default relative tolerance for "agrees".
DEFAULT_RTOL = 1e-9
ENGINES = ("mujoco", "pinocchio")


class EngineModel(Protocol):
    """What the grid needs from an engine adapter."""

    engine: str

    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates: ...  # noqa: D102

    def point_velocities(self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray) -> np.ndarray: ...  # noqa: D102

    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> Any: ...  # noqa: D102


@dataclass
class EngineRun:
    """One engine's view of a pose set."""

    engine: str
    states: SegmentStates
    rigid: np.ndarray  # (P,) engine's rigid-body kinetic energy
    armature: np.ndarray  # (P,) engine's armature energy
    point_velocities: np.ndarray | None  # (P, B, 6, 3) from the engine's kinematics


@dataclass
class ModelComparison:
    """Everything the grid produced for one model and one pose set.

    Attributes
    ----------
    model : str
        Model label.
    poses : PoseSet
    records : RecordTable
        Tidy records with the columns of :data:`RECORD_FIELDS`.
    refusals : list of dict
        Formulas that refused (e.g. ``planar`` on non-plane-parallel motion), with reasons.
    runs : dict
        Engine name to :class:`EngineRun`.
    notes : list of str
        Load notes and decisions (skipped formulas, unmatched segments).
    findings : list of Finding
        What is known about the model: the load findings and the import-parity differences; the
        one-line reason of a disagreement is chosen from these (:func:`disagreement_cause`).
    """

    model: str
    poses: PoseSet
    records: RecordTable = field(default_factory=RecordTable)
    refusals: list[dict[str, Any]] = field(default_factory=list)
    runs: dict[str, EngineRun] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)


def relative_error(value: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """Signed relative error ``(value − reference)/|reference|``; 0/0 is 0 and x/0 is ±inf.

    Parameters
    ----------
    value, reference : ndarray

    Returns
    -------
    ndarray
    """
    diff = np.asarray(value, dtype=float) - np.asarray(reference, dtype=float)
    ref = np.abs(np.asarray(reference, dtype=float))
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = diff / ref
    return np.where(ref > 0, rel, np.where(diff == 0, 0.0, np.copysign(np.inf, diff)))


def run_engine(engine: EngineModel, poses: PoseSet) -> EngineRun:
    """Evaluate one engine on a pose set: segment states, its energy, point velocities.

    Parameters
    ----------
    engine : EngineModel
    poses : PoseSet

    Returns
    -------
    EngineRun
    """
    states = engine.segment_states(poses.qpos, poses.qvel)
    energy = engine.kinetic_energy(poses.qpos, poses.qvel)
    try:
        offsets, _ = equimomental_points(states.mass, states.inertia_body, states.names)
    except ValueError:  # a non-physical inertia has no point set: point_masses will refuse, with the reason
        pv = None
    else:
        pv = engine.point_velocities(poses.qpos, poses.qvel, offsets)
    return EngineRun(engine.engine, states, np.asarray(energy.rigid), np.asarray(energy.armature), pv)


def _evaluate(name: str, run: EngineRun, angles: np.ndarray | None) -> np.ndarray:
    if name == "point_masses":
        if run.point_velocities is None:
            return FORMULAS[name].func(run.states)  # raises, naming the non-physical segment
        return FORMULAS[name].func(run.states, point_velocities=run.point_velocities)
    return FORMULAS[name](run.states, angles=angles)


def compare_runs(
    label: str,
    poses: PoseSet,
    runs: dict[str, EngineRun],
    formulas: Sequence[str] | None = None,
    segments: bool = True,
) -> ModelComparison:
    """Build the tidy records of one model from its engine runs.

    Parameters
    ----------
    label : str
        Model label written in every record.
    poses : PoseSet
    runs : dict of str to EngineRun
    formulas : sequence of str, optional
        Formula names (default: all).  Path-dependent variants are skipped, with a note,
        unless the poses form a trajectory.
    segments : bool
        Also emit per-segment records (reference: ``exact`` on the same source's states).

    Returns
    -------
    ModelComparison
    """
    names = list(FORMULAS) if formulas is None else list(formulas)
    unknown = [n for n in names if n not in FORMULAS]
    if unknown:
        raise ValueError(f"unknown formulas {unknown}; known: {list(FORMULAS)}")
    result = ModelComparison(label, poses, runs=runs)
    for n in names:
        if FORMULAS[n].needs_path and poses.times is None:
            result.notes.append(f"{n}: skipped, the poses are not a path (use a trajectory)")
    names = [n for n in names if not (FORMULAS[n].needs_path and poses.times is None)]
    pose_ids = np.asarray(poses.ids)
    columns: dict[str, list[np.ndarray]] = {k: [] for k in RECORD_FIELDS}

    def emit(formula: str, source: str, reference: str, scope: np.ndarray, ids: np.ndarray, value, ref) -> None:
        value = np.asarray(value, dtype=float).ravel()
        ref = np.asarray(ref, dtype=float).ravel()
        n = value.size
        signed = value - ref
        columns["model"].append(np.full(n, label))
        columns["pose"].append(ids)
        columns["formula"].append(np.full(n, formula))
        columns["source"].append(np.full(n, source))
        columns["reference"].append(np.full(n, reference))
        columns["scope"].append(scope)
        columns["value"].append(value)
        columns["reference_value"].append(ref)
        columns["abs_error"].append(np.abs(signed))
        columns["rel_error"].append(np.abs(relative_error(value, ref)))
        columns["signed_error"].append(signed)

    for source, run in runs.items():
        angles = integrate_angular_velocity(run.states.omega, poses.times) if poses.times is not None else None
        exact_seg = FORMULAS["exact"](run.states)
        B = run.states.n_segments
        seg_scope = np.tile(np.asarray(run.states.names), poses.n_poses)
        seg_ids = np.repeat(pose_ids, B)
        for name in names:
            try:
                per_segment = _evaluate(name, run, angles)
            except NotPlaneParallelError as err:
                result.refusals.append({"model": label, "formula": name, "source": source, "reason": str(err)})
                continue
            except ValueError as err:  # only point_masses may refuse otherwise: a non-physical inertia
                if name != "point_masses":
                    raise
                result.refusals.append({"model": label, "formula": name, "source": source, "reason": str(err)})
                continue
            total = per_segment.sum(axis=1)
            for reference, ref_run in runs.items():
                emit(
                    name,
                    source,
                    reference,
                    np.full(poses.n_poses, "total"),
                    pose_ids,
                    total,
                    ref_run.rigid,
                )
            if segments:
                emit(name, source, f"exact@{source}", seg_scope, seg_ids, per_segment, exact_seg)
    if columns["model"]:
        result.records = RecordTable({k: np.concatenate(v) for k, v in columns.items()})
    return result


@dataclass(frozen=True)
class FormulaSummary:
    """Summary of one formula against one reference, totals over all poses of a model."""

    model: str
    formula: str
    source: str
    reference: str
    max_rel_error: float
    median_rel_error: float
    over_fraction: float
    under_fraction: float
    worst_pose: str
    worst_segment: str | None
    agrees: bool


def summarize(comparison: ModelComparison, rtol: float = DEFAULT_RTOL) -> list[FormulaSummary]:
    """Per formula, source and reference: max/median relative error, over/under fractions, worst pose/segment.

    Parameters
    ----------
    comparison : ModelComparison
    rtol : float
        A formula over- (under-) estimates at a pose when its signed relative error is
        above ``rtol`` (below ``-rtol``); it agrees when every pose is within ``rtol``.

    Returns
    -------
    list of FormulaSummary
    """
    out = []
    rec = comparison.records
    total = rec["scope"] == "total"
    for formula in dict.fromkeys(rec["formula"].tolist()):
        f_mask = rec["formula"] == formula
        for source in dict.fromkeys(rec["source"][f_mask].tolist()):
            fs = f_mask & (rec["source"] == source)
            seg = fs & ~total
            worst_segment = None
            if seg.any():
                k = int(np.flatnonzero(seg)[np.argmax(rec["abs_error"][seg])])
                if rec["abs_error"][k] > 0:
                    worst_segment = f"{rec['scope'][k]} @ {rec['pose'][k]}"
            for reference in dict.fromkeys(rec["reference"][fs & total].tolist()):
                rows = np.flatnonzero(fs & total & (rec["reference"] == reference))
                rel = rec["rel_error"][rows]
                signed = rec["signed_error"][rows]
                ref = np.abs(rec["reference_value"][rows])
                out.append(
                    FormulaSummary(
                        model=comparison.model,
                        formula=formula,
                        source=source,
                        reference=reference,
                        max_rel_error=float(rel.max()),
                        median_rel_error=float(np.median(rel)),
                        over_fraction=float(np.mean(signed > rtol * ref)),
                        under_fraction=float(np.mean(signed < -rtol * ref)),
                        worst_pose=str(rec["pose"][rows[int(np.argmax(rel))]]),
                        worst_segment=worst_segment,
                        agrees=bool(rel.max() <= rtol),
                    )
                )
    return out


@dataclass(frozen=True)
class EngineParity:
    """Engine-versus-engine and engine-versus-exact agreement of one model."""

    model: str
    rigid_max_rel: float  # MuJoCo rigid energy vs Pinocchio rigid energy
    armature_max_abs: float  # |armature energy difference| (J)
    exact_vs_engine: dict[str, float]  # per engine: exact on its states vs its own energy
    worst_pose: str
    agrees: bool
    reason: str


def engine_parity(comparison: ModelComparison, rtol: float = DEFAULT_RTOL) -> EngineParity:
    """Check that the engines agree with each other and each with ``exact`` on its own states.

    Parameters
    ----------
    comparison : ModelComparison
    rtol : float

    Returns
    -------
    EngineParity
        ``agrees`` with a one-line ``reason`` when it does not.
    """
    runs = comparison.runs
    mj, pin = runs["mujoco"], runs["pinocchio"]
    rel = np.abs(relative_error(pin.rigid, mj.rigid))
    arm = np.abs(pin.armature - mj.armature)
    scale = np.maximum(np.abs(mj.rigid) + np.abs(mj.armature), 1e-300)
    self_rel = {
        name: float(np.abs(relative_error(FORMULAS["exact"](run.states).sum(axis=1), run.rigid)).max())
        for name, run in runs.items()
    }
    worst = int(np.argmax(rel))
    pose = comparison.poses.ids[worst]
    reasons = []
    if rel.max() > rtol:
        reasons.append(
            f"MuJoCo and Pinocchio rigid-body energies differ by {rel.max():.3g} relative at pose {pose} "
            f"(MuJoCo {mj.rigid[worst]:.9g} J, Pinocchio {pin.rigid[worst]:.9g} J)"
        )
    if (arm / scale).max() > rtol:
        k = int(np.argmax(arm))
        reasons.append(
            f"armature energies differ by {arm[k]:.3g} J at pose {comparison.poses.ids[k]} "
            f"(MuJoCo {mj.armature[k]:.6g} J, Pinocchio {pin.armature[k]:.6g} J)"
        )
    for name, value in self_rel.items():
        if value > rtol:
            reasons.append(f"{name}: exact on its own segment states differs from its own energy by {value:.3g}")
    cause = disagreement_cause(comparison.findings) if reasons else ""
    if cause:
        reasons.append(f"cause: {cause}")
    return EngineParity(
        comparison.model,
        float(rel.max()),
        float(arm.max()),
        self_rel,
        pose,
        not reasons,
        "; ".join(reasons),
    )


#: Kinds of per-segment import differences (symptoms, after the root causes in a reason).
_SYMPTOMS = (Kind.MASS, Kind.COM, Kind.INERTIA, Kind.ANCHOR, Kind.AXIS, Kind.ARMATURE, Kind.SEGMENTS, Kind.FRAME)


def disagreement_cause(findings: Sequence[Finding], limit: int = 3) -> str:
    """The cause of an engine disagreement, chosen from the findings, for the one-line reason.

    Root causes that change the energy come first (a repaired or compiler-altered inertia, a
    construct one parser ignores), then the per-segment import differences, then each engine's
    inconsistencies with itself.

    Parameters
    ----------
    findings : sequence of Finding
    limit : int
        At most this many findings are named (the count of the others is given).

    Returns
    -------
    str
        Empty when no finding explains a change of energy.
    """
    energy = [f for f in findings if f.affects_energy]
    roots = [f for f in root_causes(energy) if f.affects_energy]
    symptoms = [f for f in energy if f.kind in _SYMPTOMS and f not in roots]
    selves = [f for f in energy if f.kind is Kind.SELF_CONSISTENCY and f not in roots]
    chosen: list[Finding] = []
    for f in roots + symptoms + selves:
        if f not in chosen:
            chosen.append(f)
    text = "; ".join(f.message() for f in chosen[:limit])
    if len(chosen) > limit:
        text += f"; and {len(chosen) - limit} more finding(s)"
    return text


def records_for(comparisons: Iterable[ModelComparison]) -> RecordTable:
    """Concatenate the records of several comparisons.

    Parameters
    ----------
    comparisons : iterable of ModelComparison

    Returns
    -------
    RecordTable
    """
    return RecordTable.concat(c.records for c in comparisons)
