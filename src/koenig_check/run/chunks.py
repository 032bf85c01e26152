"""One chunk of poses: every formula on every engine's states against every engine's energy, from arrays.

For each model, each engine produces its own :class:`SegmentStates` (the *state source*) and its own kinetic
energy (the *reference*).  Every formula is evaluated on each source's states and compared with each engine's
rigid-body energy (armature excluded, totals) and, segment by segment, with ``exact`` on the same source's
states.  :func:`evaluate_chunk` turns a chunk into mergeable statistics (:class:`~koenig_check.run.stats.ModelStats`)
and, when asked, records.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pyarrow as pa

from koenig_check.arguments import RECORD_MODES as RECORD_MODES  # its home: what a user may ask for
from koenig_check.engines.specs import parity_pair
from koenig_check.formulas import FORMULAS, NotPlaneParallelError, integrate_angular_velocity
from koenig_check.formulas.cache import SharedStates
from koenig_check.run.arrow_arrays import numbers
from koenig_check.run.engine_runs import EngineRun, VerdictPoses
from koenig_check.run.poses import PoseSet
from koenig_check.run.records import STORED_SCHEMA, categorical, empty_records
from koenig_check.run.stats import (
    DEFAULT_RTOL,
    Extreme,
    GroupStats,
    ModelStats,
    absolute_relative_error,
    relative_error,
)


def _evaluate(name: str, run: EngineRun, states: Any, angles: np.ndarray | None, normal=None, ids=None) -> np.ndarray:
    if name == "planar" and (normal is not None or ids is not None):
        return FORMULAS[name].func(states, normal=normal, pose_labels=ids)
    if name == "point_masses":
        if run.point_velocities is None:
            return FORMULAS[name].func(run.states)  # raises, naming the non-physical segment
        return FORMULAS[name].func(states, point_velocities=run.point_velocities)
    return FORMULAS[name](states, angles=angles)


def _totals(per_segment: np.ndarray) -> np.ndarray:
    """Per-segment energies (P, B) summed over the segments, left to right.

    ``einsum`` adds the short rows in a few passes where ``sum(axis=1)`` runs a reduction per row, three to
    four times slower at a few dozen segments; the two agree to rounding, not bit for bit.
    """
    return np.einsum("pb->p", per_segment)


def formula_names(formulas: Iterable[str] | None, path: bool) -> tuple[list[str], list[str]]:
    """The formulas to evaluate and the notes on those skipped.

    Parameters
    ----------
    formulas : iterable of str, optional
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
    """What one chunk of poses contributes: its statistics, its records when asked, its verdict poses.

    ``verdict``: the chunk's share of the run's first poses, which the verdicts compare
    (:class:`~koenig_check.run.engine_runs.VerdictPoses`).
    """

    index: int
    stats: ModelStats
    records: pa.Table | None
    verdict: VerdictPoses | None = None


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
    pending: list[tuple[GroupStats, np.ndarray, np.ndarray]] = []  # (group, totals, reference energies)
    for s_code, (source, run) in enumerate(runs.items()):
        shared = SharedStates(run.states)
        angles = integrate_angular_velocity(run.states.omega, poses.times) if poses.times is not None else None
        exact_seg = FORMULAS["exact"](shared)
        exact_totals[source] = _totals(exact_seg)
        seg_names = run.states.names
        seg_codes = np.array([scopes.setdefault(n, len(scopes)) for n in seg_names], dtype=np.int64)
        B = len(seg_names)
        seg_err = np.empty(exact_seg.shape)  # each formula's |error| per segment, in turn
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
            total = _totals(per_segment)
            for r_code, (reference, ref_run) in enumerate(runs.items()):
                pending.append((stats.group((name, source, reference)), total, ref_run.rigid))
                if records != "none":
                    blocks.append((f_code, s_code, r_code, None, total, ref_run.rigid))
            np.abs(np.subtract(per_segment, exact_seg, out=seg_err), out=seg_err)
            stats.worst_segments.setdefault((name, source), Extreme()).offer(
                seg_err.ravel(), lambda k, seg_names=seg_names, B=B: f"{seg_names[k % B]} @ {ids[k // B]}"
            )
            if records == "segments":
                blocks.append((f_code, s_code, len(engines) + s_code, seg_codes, per_segment, exact_seg))
    if pending:  # every group's totals against its reference at once (add_rows)
        groups, totals, references_of = zip(*pending, strict=True)
        add_rows(list(groups), np.array(totals), np.array(references_of), rtol, ids)
    if set(parity_pair()) <= runs.keys():
        _agreement_stats(stats, runs, ids, exact_totals)
    table = None
    if records != "none":
        table = _chunk_table(label, ids, P, blocks, list(names), engines, references, list(scopes))
    return ChunkResult(index, stats, table)


def add_rows(groups: list[GroupStats], values: np.ndarray, references: np.ndarray, rtol: float, pose_labels) -> None:
    """:meth:`GroupStats.add` for several groups at once: row ``g`` of the arrays is group ``g``'s chunk.

    The same numbers as ``groups[g].add(values[g], references[g], rtol, pose_labels)``, with the arithmetic of
    every group in one pass over a (G, P) array.

    Parameters
    ----------
    groups : list of GroupStats
    values, references : ndarray, shape (G, P)
    rtol : float
    pose_labels : sequence or callable
    """
    signed = values - references
    magnitude = np.abs(references)
    rel = absolute_relative_error(signed, magnitude)
    scale = rtol * magnitude
    over = np.count_nonzero(signed > scale, axis=1)
    under = np.count_nonzero(signed < -scale, axis=1)
    for g, group in enumerate(groups):
        group.n += values.shape[1]
        group.over += int(over[g])
        group.under += int(under[g])
        group.worst.offer(rel[g], pose_labels)
        group.sketch.add(rel[g], copy=False)


def _agreement_stats(
    stats: ModelStats, runs: dict[str, EngineRun], ids: Sequence[str], exact_totals: dict[str, np.ndarray]
) -> None:
    reference, other = parity_pair()
    mj, pn = runs[reference], runs[other]
    agreement = stats.agreement
    agreement.rigid.offer(np.abs(relative_error(pn.rigid, mj.rigid)), ids, extra=(mj.rigid, pn.rigid))
    arm = np.abs(pn.armature - mj.armature)
    agreement.armature.offer(arm, ids, extra=(mj.armature, pn.armature))
    scale = np.maximum(np.abs(mj.rigid) + np.abs(mj.armature), 1e-300)
    agreement.armature_scaled = max(agreement.armature_scaled, float((arm / scale).max()))
    for name, run in runs.items():
        agreement.self_rel[name] = float(np.abs(relative_error(exact_totals[name], run.rigid)).max())
        if name != reference:  # each engine's gap to MuJoCo (Drake's too, when it runs on every pose)
            agreement.gaps.setdefault(name, Extreme()).offer(np.abs(relative_error(run.rigid, mj.rigid)), ids)


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
        return empty_records()
    values = np.concatenate([b[4].reshape(P, -1) for b in blocks], axis=1)
    refs = np.concatenate([b[5].reshape(P, -1) for b in blocks], axis=1)
    model, pose, f, s, r, sc = _record_columns(P, blocks, label, formulas, sources, references, scopes)
    pose_column = categorical(pose, list(ids), "pose")
    arrays = [model, pose_column, f, s, r, sc, numbers(values), numbers(refs)]
    return pa.Table.from_arrays(arrays, schema=STORED_SCHEMA)


#: The columns of the last chunk layouts but the values (every chunk of a model but its last has the same).
_CODES: dict[tuple, tuple[Any, ...]] = {}


def _record_columns(
    P: int, blocks: list, label: str, formulas: list[str], sources: list[str], references: list[str], scopes: list[str]
) -> tuple[Any, ...]:
    """The model, formula, source, reference and scope columns of a chunk's P × K records, and its pose codes.

    They depend only on the number of poses, the layout of the blocks and the names, so they are built once
    per layout and reused by every chunk of that layout (Arrow arrays are immutable; the pose codes are
    read-only); only the pose column's words, the chunk's pose ids, are the chunk's own.
    """
    key = (
        P,
        tuple((b[0], b[1], b[2], None if b[3] is None else b[3].tobytes()) for b in blocks),
        label,
        *(tuple(names) for names in (formulas, sources, references, scopes)),
    )
    columns = _CODES.get(key)
    if columns is None:
        model, pose, f, s, r, sc = _record_codes(P, blocks)
        columns = (
            categorical(model, [label], "model"),
            pose,
            categorical(f, formulas, "formula"),
            categorical(s, sources, "source"),
            categorical(r, references, "reference"),
            categorical(sc, scopes, "scope"),
        )
        if len(_CODES) >= 4:  # a model's full chunks and its last one; a new model starts afresh
            _CODES.clear()
        _CODES[key] = columns
    return columns


def _record_codes(P: int, blocks: list) -> tuple[np.ndarray, ...]:
    """The model, pose, formula, source, reference and scope codes of a chunk's P × K records."""
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
    return codes
