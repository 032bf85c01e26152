"""One model's comparison: merged statistics, records kept, refusals, notes and findings."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

from koenig_check.engines.registry import required
from koenig_check.findings import Finding
from koenig_check.run.chunks import evaluate_chunk, formula_names
from koenig_check.run.engine_runs import EngineRun
from koenig_check.run.poses import PoseSet
from koenig_check.run.records import RecordTable
from koenig_check.run.stats import DEFAULT_RTOL, ModelStats


@dataclass(frozen=True)
class ModelComparison:
    """Everything the comparison produced for one model and one pose set; immutable once built.

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
    segment_labels : dict of str to str
        Each segment (keyed by the joint that moves it) as the user wrote it: ``"link forearm (joint elbow)"``
        (empty when unknown: the report then names the joint).
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
    engines: tuple[str, ...] = field(default_factory=required)
    segment_labels: dict[str, str] = field(default_factory=dict)

    def __repr__(self) -> str:
        return (
            f"<ModelComparison {self.model!r}: {self.n_poses} {self.pose_kind or ''} poses, engines "
            f"{', '.join(self.engines)}, {len(self.records)} records, {len(self.findings)} findings>"
        )


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
