"""The comparison grid: model × pose × formula × state source × reference engine → statistics and records.

For each model, each engine produces its own :class:`SegmentStates` (the *state source*)
and its own kinetic energy (the *reference*).  Every formula is evaluated on each
source's states and compared with each engine's rigid-body energy (armature excluded,
totals) and, segment by segment, with ``exact`` on the same source's states.

A chunk of poses is evaluated by :func:`evaluate_chunk` into mergeable statistics
(:class:`~koenig_check.stats.ModelStats`) and, when asked, records; the summaries and the engine
parity of a model are read from the merged statistics.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pyarrow as pa

from koenig_check.diagnosis.reason import disagreement_cause
from koenig_check.engines.base import Engine
from koenig_check.engines.registry import REQUIRED as ENGINES
from koenig_check.findings import Finding
from koenig_check.formulas import FORMULAS, NotPlaneParallelError, integrate_angular_velocity
from koenig_check.formulas.cache import SharedStates
from koenig_check.formulas.point_masses import equimomental_points
from koenig_check.poses import PoseSet
from koenig_check.records import RECORD_FIELDS, STORED_SCHEMA, RecordTable, categorical
from koenig_check.segments import SegmentStates
from koenig_check.stats import Extreme, ModelStats, relative_error

__all__ = [
    "DEFAULT_RTOL",
    "RECORD_FIELDS",
    "RECORD_MODES",
    "EngineParity",
    "EngineRun",
    "FormulaSummary",
    "ModelComparison",
    "compare_runs",
    "engine_parity",
    "evaluate_chunk",
    "relative_error",
    "run_engine",
    "summarize",
    "summarize_records",
]

#: Default relative tolerance for "agrees".
DEFAULT_RTOL = 1e-9
#: Which records a run keeps: per segment and totals, totals only, or none.
RECORD_MODES = ("segments", "totals", "none")


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
    poses : PoseSet or None
        The poses, when they were held in memory (grids, trajectories, keyframes, pose files,
        synthetic runs); ``None`` for random poses drawn chunk by chunk.
    records : RecordTable
        Tidy records with the columns of :data:`RECORD_FIELDS` kept in memory (empty when they
        were streamed to a file or not asked for).
    refusals : list of dict
        Formulas that refused (e.g. ``planar`` on non-plane-parallel motion), with reasons.
    runs : dict
        Engine name to :class:`EngineRun`, for a comparison computed in one piece from given runs.
    notes : list of str
        Load notes and decisions (skipped formulas, unmatched segments).
    findings : list of Finding
        What is known about the model: the load findings and the import-parity differences; the
        one-line reason of a disagreement is chosen from these (:func:`disagreement_cause`).
    stats : ModelStats, optional
        The merged statistics of every chunk (summaries and engine parity are read from them).
    n_poses : int
    pose_kind : str
    engines : tuple of str
        The engines that produced states and energies.
    """

    model: str
    poses: PoseSet | None
    records: RecordTable = field(default_factory=RecordTable)
    refusals: list[dict[str, Any]] = field(default_factory=list)
    runs: dict[str, EngineRun] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    stats: ModelStats | None = None
    n_poses: int = 0
    pose_kind: str = ""
    engines: tuple[str, ...] = ENGINES


def run_engine(engine: Engine, poses: PoseSet) -> EngineRun:
    """Evaluate one engine on a pose set: segment states, its energy, point velocities (one sweep).

    Parameters
    ----------
    engine : Engine
    poses : PoseSet

    Returns
    -------
    EngineRun
    """
    states, pv, rigid, armature = engine.sweep(poses.qpos, poses.qvel, _points_for(engine))
    return EngineRun(engine.engine, states, rigid, armature, pv)


#: Equimomental points of the last models' segments, keyed by their mass properties (see :func:`_points_for`).
_POINTS: dict[tuple, np.ndarray | None] = {}


def _points_for(engine: Engine) -> np.ndarray | None:
    """The equimomental points of an engine's segments, or None; computed once per set of mass properties.

    The mass properties are constant over the poses, so every chunk of a model asks for the same
    points: they are kept, keyed by the masses, inertias and names they come from.
    """
    mass, inertia = (np.asarray(a, dtype=float) for a in engine.mass_properties())
    key = (mass.tobytes(), inertia.tobytes(), tuple(engine.segment_names))
    if key in _POINTS:
        return _POINTS[key]
    try:
        offsets, _ = equimomental_points(mass, inertia, engine.segment_names)
    except ValueError:  # a non-physical inertia: point_masses will refuse, with the reason
        offsets = None
    else:
        offsets.setflags(write=False)
    if len(_POINTS) >= 8:  # a few engines of a few models; a long run over many models starts afresh
        _POINTS.clear()
    _POINTS[key] = offsets
    return offsets


def _evaluate(name: str, run: EngineRun, states: Any, angles: np.ndarray | None, normal=None, ids=None) -> np.ndarray:
    if name == "planar" and (normal is not None or ids is not None):
        return FORMULAS[name].func(states, normal=normal, pose_labels=ids)
    if name == "point_masses":
        if run.point_velocities is None:
            return FORMULAS[name].func(run.states)  # raises, naming the non-physical segment
        return FORMULAS[name].func(states, point_velocities=run.point_velocities)
    return FORMULAS[name](states, angles=angles)


def formula_names(formulas: Sequence[str] | None, path: bool) -> tuple[list[str], list[str]]:
    """The formulas to evaluate and the notes on those skipped.

    Parameters
    ----------
    formulas : sequence of str, optional
        Formula names (default: all).
    path : bool
        Whether the poses form a path (path-dependent variants are skipped otherwise).

    Returns
    -------
    names : list of str
    notes : list of str
    """
    names = list(FORMULAS) if formulas is None else list(formulas)
    unknown = [n for n in names if n not in FORMULAS]
    if unknown:
        raise ValueError(f"unknown formulas {unknown}; known: {list(FORMULAS)}")
    notes = [
        f"{n}: skipped, the poses are not a path (use a trajectory)"
        for n in names
        if FORMULAS[n].needs_path and not path
    ]
    return [n for n in names if path or not FORMULAS[n].needs_path], notes


@dataclass
class ChunkResult:
    """What one chunk of poses contributes: its statistics and, when asked, its records."""

    index: int
    stats: ModelStats
    records: pa.Table | None


def evaluate_chunk(
    label: str,
    poses: PoseSet,
    runs: dict[str, EngineRun],
    names: Sequence[str],
    records: str = "totals",
    rtol: float = DEFAULT_RTOL,
    index: int = 0,
    planar_normals: dict[str, np.ndarray] | None = None,
) -> ChunkResult:
    """Every formula on every engine's states of one chunk: statistics and records, from arrays.

    Parameters
    ----------
    label : str
        Model label written in every record.
    poses : PoseSet
        The chunk's poses (their ids label the records).
    runs : dict of str to EngineRun
    names : sequence of str
        Formulas to evaluate (see :func:`formula_names`).
    records : {"segments", "totals", "none"}
        Which records to build: per-segment and totals, totals only, or none.
    rtol : float
    index : int
        The chunk's position, kept in the result.
    planar_normals : dict of str to ndarray (B, 3), optional
        Per state source, the plane normals of eq. (16), fixed for every chunk of a model (by
        default ``planar`` infers them from the chunk's own states).

    Returns
    -------
    ChunkResult
    """
    if records not in RECORD_MODES:
        raise ValueError(f"records must be one of {RECORD_MODES}, got {records!r}")
    stats = ModelStats(rtol, n_poses=poses.n_poses)
    ids = poses.ids
    P = poses.n_poses
    blocks: list[tuple[int, int, int, np.ndarray | None, np.ndarray, np.ndarray]] = []
    engines = list(runs)
    references = engines + [f"exact@{e}" for e in engines]
    scopes: dict[str, int] = {"total": 0}
    exact_totals: dict[str, np.ndarray] = {}
    for s_code, (source, run) in enumerate(runs.items()):
        shared = SharedStates(run.states)
        angles = integrate_angular_velocity(run.states.omega, poses.times) if poses.times is not None else None
        exact_seg = FORMULAS["exact"](shared)
        exact_totals[source] = exact_seg.sum(axis=1)
        seg_names = run.states.names
        seg_codes = np.array([scopes.setdefault(n, len(scopes)) for n in seg_names], dtype=np.int64)
        B = len(seg_names)
        for f_code, name in enumerate(names):
            try:
                normal = (planar_normals or {}).get(source)
                # exact is the segments' reference: evaluated once above, not again as a formula
                per_segment = exact_seg if name == "exact" else _evaluate(name, run, shared, angles, normal, ids)
            except NotPlaneParallelError as err:
                stats.refusals[(name, source)] = str(err)
                continue
            except ValueError as err:  # only point_masses may refuse otherwise: a non-physical inertia
                if name != "point_masses":
                    raise
                stats.refusals[(name, source)] = str(err)
                continue
            total = per_segment.sum(axis=1)
            for r_code, (reference, ref_run) in enumerate(runs.items()):
                stats.group((name, source, reference)).add(total, ref_run.rigid, rtol, ids)
                if records != "none":
                    blocks.append((f_code, s_code, r_code, None, total, ref_run.rigid))
            err = np.abs(per_segment - exact_seg).ravel()
            stats.worst_segments.setdefault((name, source), Extreme()).offer(
                err, lambda k, seg_names=seg_names, B=B: f"{seg_names[k % B]} @ {ids[k // B]}"
            )
            if records == "segments":
                blocks.append((f_code, s_code, len(engines) + s_code, seg_codes, per_segment, exact_seg))
    if "mujoco" in runs and "pinocchio" in runs:
        _parity_stats(stats, runs, ids, exact_totals)
    table = None
    if records != "none":
        table = _chunk_table(label, ids, P, blocks, list(names), engines, references, list(scopes))
    return ChunkResult(index, stats, table)


def _parity_stats(
    stats: ModelStats, runs: dict[str, EngineRun], ids: Sequence[str], exact_totals: dict[str, np.ndarray]
) -> None:
    mj, pn = runs["mujoco"], runs["pinocchio"]
    parity = stats.parity
    parity.rigid.offer(np.abs(relative_error(pn.rigid, mj.rigid)), ids, extra=(mj.rigid, pn.rigid))
    arm = np.abs(pn.armature - mj.armature)
    parity.armature.offer(arm, ids, extra=(mj.armature, pn.armature))
    scale = np.maximum(np.abs(mj.rigid) + np.abs(mj.armature), 1e-300)
    parity.armature_scaled = max(parity.armature_scaled, float((arm / scale).max()))
    for name, run in runs.items():
        parity.self_rel[name] = float(np.abs(relative_error(exact_totals[name], run.rigid)).max())


def _chunk_table(
    label: str,
    ids: Sequence[str],
    P: int,
    blocks: list,
    formulas: list[str],
    sources: list[str],
    references: list[str],
    scopes: list[str],
) -> pa.Table:
    """The chunk's records, pose by pose: a (P, K) matrix of values, K records per pose."""
    if not blocks:
        return STORED_SCHEMA.empty_table()
    values = np.concatenate([b[4].reshape(P, -1) for b in blocks], axis=1)
    refs = np.concatenate([b[5].reshape(P, -1) for b in blocks], axis=1)
    model, pose, f, s, r, sc = _record_codes(P, blocks)
    arrays = [
        categorical(model, [label], "model"),
        categorical(pose, list(ids), "pose"),
        categorical(f, formulas, "formula"),
        categorical(s, sources, "source"),
        categorical(r, references, "reference"),
        categorical(sc, scopes, "scope"),
        pa.array(values.ravel()),
        pa.array(refs.ravel()),
    ]
    return pa.Table.from_arrays(arrays, schema=STORED_SCHEMA)


#: The code columns of the last chunk layouts (every chunk of a model but its last has the same).
_CODES: dict[tuple, tuple[np.ndarray, ...]] = {}


def _record_codes(P: int, blocks: list) -> tuple[np.ndarray, ...]:
    """The model, pose, formula, source, reference and scope codes of a chunk's P × K records.

    They depend only on the number of poses and the layout of the blocks, so they are built once
    per layout and reused (read-only) by every chunk of that layout.
    """
    key = (P, tuple((b[0], b[1], b[2], None if b[3] is None else b[3].tobytes()) for b in blocks))
    codes = _CODES.get(key)
    if codes is not None:
        return codes
    widths = [1 if b[3] is None else len(b[3]) for b in blocks]
    # Codes built in their stored widths (the columns' index types), so that no column is converted.
    f = np.repeat(np.array([b[0] for b in blocks], dtype=np.int8), widths)
    s = np.repeat(np.array([b[1] for b in blocks], dtype=np.int8), widths)
    r = np.repeat(np.array([b[2] for b in blocks], dtype=np.int8), widths)
    sc = np.concatenate([np.zeros(1, dtype=np.int16) if b[3] is None else b[3].astype(np.int16) for b in blocks])
    K = len(sc)
    codes = (
        np.zeros(P * K, dtype=np.int16),
        np.repeat(np.arange(P, dtype=np.int32), K),
        np.tile(f, P),
        np.tile(s, P),
        np.tile(r, P),
        np.tile(sc, P),
    )
    for c in codes:
        c.setflags(write=False)
    if len(_CODES) >= 4:  # a model's full chunks and its last one; a new model starts afresh
        _CODES.clear()
    _CODES[key] = codes
    return codes


def compare_runs(
    label: str,
    poses: PoseSet,
    runs: dict[str, EngineRun],
    formulas: Sequence[str] | None = None,
    segments: bool = True,
    rtol: float = DEFAULT_RTOL,
) -> ModelComparison:
    """Build the statistics and tidy records of one model from its engine runs, in one piece.

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
    rtol : float
        Tolerance of the over/under counts of the statistics.

    Returns
    -------
    ModelComparison
    """
    names, notes = formula_names(formulas, poses.times is not None)
    chunk = evaluate_chunk(label, poses, runs, names, "segments" if segments else "totals", rtol)
    return finish_comparison(label, poses, chunk.stats, RecordTable(chunk.records), notes, tuple(runs), runs=runs)


def finish_comparison(
    label: str,
    poses: PoseSet | None,
    stats: ModelStats,
    records: RecordTable,
    notes: list[str],
    engines: tuple[str, ...],
    runs: dict[str, EngineRun] | None = None,
    pose_kind: str | None = None,
) -> ModelComparison:
    """A :class:`ModelComparison` from merged statistics and the records kept.

    Parameters
    ----------
    label : str
    poses : PoseSet or None
    stats : ModelStats
    records : RecordTable
    notes : list of str
    engines : tuple of str
    runs : dict, optional
    pose_kind : str, optional
        Defaults to the kind of ``poses``.

    Returns
    -------
    ModelComparison
    """
    refusals = [
        {"model": label, "formula": f, "source": s, "reason": reason} for (f, s), reason in stats.refusals.items()
    ]
    return ModelComparison(
        label,
        poses,
        records=records,
        refusals=refusals,
        runs=runs or {},
        notes=list(notes),
        stats=stats,
        n_poses=stats.n_poses,
        pose_kind=pose_kind or (poses.kind if poses is not None else ""),
        engines=engines,
    )


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

    Read from the comparison's merged statistics when they were accumulated at this ``rtol``,
    otherwise from its records (see :func:`summarize_records`).

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
    if comparison.stats is not None and comparison.stats.rtol == rtol:
        return summaries_from_stats(comparison.model, comparison.stats)
    return summarize_records(comparison.records, rtol, comparison.model)


def summaries_from_stats(model: str, stats: ModelStats) -> list[FormulaSummary]:
    """The summaries of one model from its merged statistics.

    Parameters
    ----------
    model : str
    stats : ModelStats

    Returns
    -------
    list of FormulaSummary
        Formula by formula (in order of first appearance), then source, then reference.
    """
    out = []
    for (formula, source, reference), g in stats.kept_groups().items():
        seg = stats.worst_segments.get((formula, source))
        out.append(
            FormulaSummary(
                model=model,
                formula=formula,
                source=source,
                reference=reference,
                max_rel_error=g.worst.value,
                median_rel_error=g.sketch.median(),
                over_fraction=g.over / g.n,
                under_fraction=g.under / g.n,
                worst_pose=g.worst.where,
                worst_segment=seg.where if seg is not None and seg.value > 0 else None,
                agrees=bool(g.worst.value <= stats.rtol),
            )
        )
    rank = {f: k for k, f in enumerate(dict.fromkeys(s.formula for s in out))}
    return sorted(out, key=lambda s: rank[s.formula])


def summarize_records(
    records: RecordTable, rtol: float = DEFAULT_RTOL, model: str | None = None
) -> list[FormulaSummary]:
    """The summaries computed from a full record table (the reference route for the streamed ones).

    Parameters
    ----------
    records : RecordTable
        One model's records; ``worst_segment`` needs its per-segment records.
    rtol : float
    model : str, optional
        The label written in the summaries (default: the records' model column).

    Returns
    -------
    list of FormulaSummary
    """
    out: list[FormulaSummary] = []
    if not len(records):
        return out
    rec = records.columns
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
                        model=model or str(rec["model"][rows[0]]),
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
    if comparison.stats is None:
        raise ValueError(f"{comparison.model}: no statistics to read the engine parity from")
    p = comparison.stats.parity
    reasons = []
    if p.rigid.value > rtol:
        mj, pn = p.rigid.extra
        reasons.append(
            f"MuJoCo and Pinocchio rigid-body energies differ by {p.rigid.value:.3g} relative at pose "
            f"{p.rigid.where} (MuJoCo {mj:.9g} J, Pinocchio {pn:.9g} J)"
        )
    if p.armature_scaled > rtol:
        mj, pn = p.armature.extra
        reasons.append(
            f"armature energies differ by {p.armature.value:.3g} J at pose {p.armature.where} "
            f"(MuJoCo {mj:.6g} J, Pinocchio {pn:.6g} J)"
        )
    for name, value in p.self_rel.items():
        if value > rtol:
            reasons.append(f"{name}: exact on its own segment states differs from its own energy by {value:.3g}")
    cause = disagreement_cause(comparison.findings) if reasons else ""
    if cause:
        reasons.append(f"cause: {cause}")
    return EngineParity(
        comparison.model,
        float(p.rigid.value),
        float(p.armature.value),
        dict(p.self_rel),
        p.rigid.where,
        not reasons,
        "; ".join(reasons),
    )


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
