"""The pipeline at scale: a model's poses cut into chunks, each chunk a pure function, run anywhere.

A :class:`~koenig_check.run.chunk_tasks.ChunkTask` names everything a chunk needs (see
:mod:`koenig_check.run.chunk_tasks`) and :func:`run_chunk` turns it into a
:class:`~koenig_check.run.chunks.ChunkResult`: mergeable statistics and, when asked, records.  The same
tasks run in this process, in local processes (``jobs``) or on a Dask cluster (``client``); the
results are merged in pose order, so every way gives the same summaries and records.
"""

from __future__ import annotations

import multiprocessing
import threading
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import Executor, ProcessPoolExecutor
from typing import Any

import numpy as np

from koenig_check.exceptions import one_line
from koenig_check.run.chunk_tasks import (
    CHUNK_MAX,
    CHUNK_MIN,
    CHUNK_SEGMENT_POSES,
    PROBE_POSES,
    ChunkTask,
    RandomRange,
    WorkerModel,
    chunk_poses_of,
    chunk_size,
    plan,
    probe_normals,
)
from koenig_check.run.chunks import ChunkResult, evaluate_chunk, formula_names
from koenig_check.run.comparison import ModelComparison, finish_comparison
from koenig_check.run.engine_runs import EngineRun, VerdictPoses, run_engine
from koenig_check.run.poses import PoseSet, random_pose_range
from koenig_check.run.records import RecordTable, without_refused

__all__ = [
    "CHUNK_MAX",
    "CHUNK_MIN",
    "CHUNK_SEGMENT_POSES",
    "PROBE_POSES",
    "ChunkTask",
    "RandomRange",
    "WorkerModel",
    "chunk_poses_of",
    "chunk_size",
    "plan",
    "probe_normals",
    "run_chunk",
    "run_model",
    "run_tasks",
]


class _WorkerModels:
    """A worker process's models: each loaded once per process, the last one kept (memory stays bounded).

    Only worker processes (``--jobs``, Dask) hold one: chunks run in the process that loaded the model are
    handed that model (:func:`run_tasks`), and a local worker forked from it starts with it (:func:`_adopt`).
    """

    def __init__(self) -> None:
        self.models: dict[WorkerModel, Any] = {}

    def adopt(self, source: WorkerModel, model: Any) -> None:
        self.models = {source: model}  # one model at a time

    def get(self, source: WorkerModel) -> Any:
        model = self.models.get(source)
        if model is None:
            from koenig_check.engines import load_model

            model = load_model(source.model, source.options)
            self.adopt(source, model)
        return model


#: This process's models when it is a worker (empty in the process that runs the comparison).
_WORKER = _WorkerModels()


def _adopt(source: WorkerModel, model: Any) -> None:
    """A local worker's initializer: the model its parent loaded, inherited by the fork (not loaded again)."""
    _WORKER.adopt(source, model)


def _check_finite(path: Any, runs: dict[str, EngineRun], poses: PoseSet) -> None:
    for name, run in runs.items():
        s = run.states
        for field_name in ("com", "v_com", "rotation", "omega", "pole", "v_pole"):
            arr = getattr(s, field_name)
            if not np.isfinite(arr).all():
                p, b = np.argwhere(~np.isfinite(arr))[0][:2]
                raise ValueError(
                    f"{path}: {name} gives a non-finite {field_name} for segment {s.names[b]!r} at pose {poses.ids[p]}"
                )
        for what in ("rigid", "armature"):
            arr = getattr(run, what)
            if not np.isfinite(arr).all():
                p = int(np.flatnonzero(~np.isfinite(arr))[0])
                raise ValueError(f"{path}: {name} gives a non-finite {what} energy at pose {poses.ids[p]}")


#: Held while a chunk uses the engines of this process's model (see :func:`run_chunk`).
_ENGINES_LOCK = threading.Lock()


def run_chunk(task: ChunkTask, model: Any = None) -> ChunkResult:
    """Evaluate one chunk: both engines' states and energies, every formula, statistics and records.

    Parameters
    ----------
    task : ChunkTask
    model : koenig_check.engines.LoadedModel, optional
        The model of ``task.source``, loaded in this process; a worker loads it once (without it).

    Returns
    -------
    ChunkResult
    """
    # The engines of a process's model are shared by its chunks, and their data (MuJoCo's MjData, Pinocchio's
    # Data) is scratch memory: chunks run in threads (a Dask worker's) take turns with the engines.
    with _ENGINES_LOCK:
        model = model if model is not None else _WORKER.get(task.source)
        poses = task.poses
        if isinstance(poses, RandomRange):
            poses = random_pose_range(model.mujoco.model, poses.start, poses.stop, poses.seed, poses.velocity_scale)
        engines = {name: model.engine(name) for name in task.engines}  # an engine that cannot check it: its reason
        try:
            runs = {name: run_engine(engine, poses) for name, engine in engines.items()}
        except ValueError as err:  # an engine produced an invalid state: name the file
            raise ValueError(f"{model.path}: {one_line(err)}") from err
    _check_finite(model.path, runs, poses)
    result = evaluate_chunk(
        task.label, poses, runs, task.formulas, task.records, task.rtol, task.index, task.planar_normals
    )
    if task.verdict_poses:
        result.verdict = VerdictPoses.of_runs(poses, runs, task.verdict_poses)
    return result


def _windowed(submit: Callable[[ChunkTask], Any], result: Callable[[Any], ChunkResult], tasks, window: int):
    pending: deque = deque()
    for t in tasks:
        pending.append(submit(t))
        if len(pending) >= window:
            yield result(pending.popleft())
    while pending:
        yield result(pending.popleft())


def run_tasks(tasks: list[ChunkTask], jobs: int = 1, client: Any = None, model: Any = None) -> Iterator[ChunkResult]:
    """Run chunk tasks and yield their results in task order.

    At most about two chunks per worker are in flight, so memory stays bounded whatever the
    number of chunks.

    Parameters
    ----------
    tasks : list of ChunkTask
    jobs : int
        Local processes (1: this process).
    client : dask.distributed.Client, optional
        Run the chunks on this Dask cluster instead.
    model : koenig_check.engines.LoadedModel, optional
        The tasks' model, loaded in this process: the chunks run here use it, and local workers forked from
        this process inherit it (otherwise each worker loads it once).

    Yields
    ------
    ChunkResult
    """
    if client is not None:
        workers = max(len(client.scheduler_info().get("workers", {})), 1)
        yield from _windowed(
            lambda t: client.submit(run_chunk, t, pure=False), lambda f: f.result(), tasks, 2 * workers
        )
        return
    if jobs <= 1 or len(tasks) <= 1:
        for t in tasks:
            yield run_chunk(t, model)
        return
    with _pool(jobs, tasks[0].source, model) as pool:
        yield from _windowed(lambda t: pool.submit(run_chunk, t), lambda f: f.result(), tasks, 2 * jobs)


def _pool(jobs: int, source: WorkerModel, model: Any) -> Executor:
    if "fork" not in multiprocessing.get_all_start_methods():
        return ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn"))
    context = multiprocessing.get_context("fork")  # the workers inherit the loaded model: not pickled, not loaded
    if model is None:
        return ProcessPoolExecutor(max_workers=jobs, mp_context=context)
    return ProcessPoolExecutor(max_workers=jobs, mp_context=context, initializer=_adopt, initargs=(source, model))


def run_model(
    pair: Any,
    source: WorkerModel,
    label: str,
    formulas: Iterable[str] | None = None,
    *,
    pose_set: PoseSet | None = None,
    random: RandomRange | None = None,
    records: str = "totals",
    rtol: float = 1e-9,
    jobs: int = 1,
    client: Any = None,
    sink: Any = None,
    keep_records: bool | None = None,
    chunk_poses: int | None = None,
    on_chunk: Callable[[int, int], None] | None = None,
) -> tuple[ModelComparison, VerdictPoses | None]:
    """Run a loaded model's poses chunk by chunk; merge the statistics, stream the records.

    Parameters
    ----------
    pair : koenig_check.engines.LoadedModel
        The model, loaded here, with the engines to run on every pose (chunks run here reuse it; other
        processes load ``source`` and attach the same engines).
    source : WorkerModel
    label : str
    formulas : iterable of str, optional
        Default: all (path-dependent ones only on a path).
    pose_set : PoseSet, optional
        Poses held in memory; otherwise ``random``.
    random : RandomRange, optional
    records : {"totals", "segments", "none"}
    rtol : float
    jobs : int
        Local processes.
    client : dask.distributed.Client, optional
    sink : RecordSink, optional
        Receives each chunk's records in pose order.
    keep_records : bool, optional
        Keep the records in memory too (default: only without a sink).
    chunk_poses : int, optional
        Poses per chunk (default :func:`chunk_size`).
    on_chunk : callable, optional
        Called as ``on_chunk(poses, total)`` after each chunk is merged: the chunk's number of poses and the
        model's (a progress bar over poses).

    Returns
    -------
    comparison : ModelComparison
    verdict : VerdictPoses or None
        The run's first poses with each engine's energies there (what the verdicts compare).
    """
    names, skipped = formula_names(formulas, pose_set is not None and pose_set.times is not None)
    tasks = plan(
        source,
        label,
        names,
        records,
        rtol,
        len(pair.mujoco.segment_names),
        poses=pose_set,
        random=random,
        size=chunk_poses,
        planar_normals=probe_normals(pair, pose_set, random) if "planar" in names else None,
        engines=tuple(pair.engines),
    )
    keep = sink is None if keep_records is None else keep_records
    stats, kept = None, []
    sizes = [chunk_poses_of(t) for t in tasks]
    verdict = []
    for result in run_tasks(tasks, jobs=jobs, client=client, model=pair):
        if result.verdict is not None:
            verdict.append(result.verdict)
        if on_chunk is not None:
            on_chunk(sizes[result.index], sum(sizes))
        if stats is None:
            stats = result.stats
        else:
            stats.merge(result.stats)
        if result.records is not None:
            if sink is not None:
                sink.write(result.records)
            if keep:
                kept.append(result.records)
    if sink is not None and hasattr(sink, "flush"):
        # A failed write of this model's last chunk is this model's failure, not the next one's; and no
        # writing thread is alive when the next model's --jobs workers are forked.
        sink.flush()
    if stats is None:
        raise ValueError(f"{label}: no poses to compare (empty pose range)")
    stats.compact()
    # A refusal holds for the whole model: rows of the chunks that accepted the formula do not count.
    refused = [{"model": label, "formula": f, "source": e, "reason": r} for (f, e), r in stats.refusals.items()]
    if sink is not None and hasattr(sink, "refuse"):  # those rows are in the file already: listed there
        for entry in refused:
            sink.refuse(**entry)
    kept_records = without_refused(RecordTable.concat(RecordTable(t) for t in kept), refused)
    notes = list(pair.notes) + list(pose_set.notes if pose_set is not None else ()) + skipped
    kind = pose_set.kind if pose_set is not None else "random"
    comparison = finish_comparison(label, pose_set, stats, kept_records, notes, tuple(pair.engines), pose_kind=kind)
    return comparison, VerdictPoses.concat(verdict)
