"""The pipeline at scale: a model's poses cut into chunks, each chunk a pure function, run anywhere.

A :class:`ChunkTask` names everything a chunk needs — the model source and its load options, the
formulas, the record mode, the tolerance and the pose range (seeded random poses ``start`` to
``stop``, or the poses themselves) — and :func:`run_chunk` turns it into a
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
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.registry import REQUIRED as ENGINES
from koenig_check.exceptions import one_line
from koenig_check.run.chunks import ChunkResult, evaluate_chunk, formula_names
from koenig_check.run.comparison import ModelComparison, finish_comparison
from koenig_check.run.engine_runs import EngineRun, run_engine
from koenig_check.run.poses import PoseSet, random_pose_range
from koenig_check.run.records import RecordTable, without_refused

#: Segment-poses per chunk (poses × segments): memory per chunk stays near constant across models.
CHUNK_SEGMENT_POSES = 32_768
#: Bounds on the poses of a chunk.
CHUNK_MIN, CHUNK_MAX = 256, 4096


def chunk_size(n_segments: int) -> int:
    """The default number of poses per chunk for a model with ``n_segments`` segments.

    Parameters
    ----------
    n_segments : int

    Returns
    -------
    int
    """
    return int(np.clip(CHUNK_SEGMENT_POSES // max(n_segments, 1), CHUNK_MIN, CHUNK_MAX))


@dataclass(frozen=True)
class ModelSource:
    """A model file or name and how it is loaded (hashable: a process loads each source once).

    Attributes
    ----------
    model : str
    options : LoadOptions
    """

    model: str
    options: LoadOptions = field(default_factory=LoadOptions)


@dataclass(frozen=True)
class RandomRange:
    """Poses ``start`` to ``stop − 1`` of the seeded random sequence (see :func:`random_pose_range`)."""

    start: int
    stop: int
    seed: int
    velocity_scale: float


@dataclass(frozen=True)
class ChunkTask:
    """Everything one chunk needs; :func:`run_chunk` of it is a pure function.

    Attributes
    ----------
    source : ModelSource
    label : str
        Model label written in the records.
    formulas : tuple of str
        Formulas to evaluate (already resolved, see :func:`koenig_check.run.chunks.formula_names`).
    records : {"segments", "totals", "none"}
    rtol : float
    index : int
        Position of the chunk in the model's poses.
    poses : RandomRange or PoseSet
    planar_normals : dict, optional
        Per engine, the plane normals of eq. (16) for every chunk of the model (see :func:`probe_normals`).
    engines : tuple of str
        The engines run on every pose (MuJoCo, Pinocchio, and Drake when asked for).
    """

    source: ModelSource
    label: str
    formulas: tuple[str, ...]
    records: str
    rtol: float
    index: int
    poses: RandomRange | PoseSet
    planar_normals: dict[str, np.ndarray] | None = None
    engines: tuple[str, ...] = ENGINES


_MODELS: dict[ModelSource, Any] = {}


def remember(source: ModelSource, model: Any) -> None:
    """Let this process's chunks reuse a model already loaded (with the optional engines attached to it).

    Parameters
    ----------
    source : ModelSource
    model : koenig_check.engines.LoadedModel
    """
    _MODELS.clear()  # one model at a time: memory stays bounded over many models
    _MODELS[source] = model


def forget() -> None:
    """Drop the model this process remembered: once its run is over, its engines are memory held for nothing."""
    _MODELS.clear()


def loaded(source: ModelSource) -> Any:
    """The model of a source, loaded once per process (its optional engines are attached on first use).

    Parameters
    ----------
    source : ModelSource

    Returns
    -------
    koenig_check.engines.LoadedModel
    """
    model = _MODELS.get(source)
    if model is None:
        from koenig_check.engines import load_model

        model = load_model(source.model, source.options)
        remember(source, model)
    return model


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


def run_chunk(task: ChunkTask) -> ChunkResult:
    """Evaluate one chunk: both engines' states and energies, every formula, statistics and records.

    Parameters
    ----------
    task : ChunkTask

    Returns
    -------
    ChunkResult
    """
    # The engines of a process's model are shared by its chunks, and their data (MuJoCo's MjData, Pinocchio's
    # Data) is scratch memory: chunks run in threads (a Dask worker's) take turns with the engines.
    with _ENGINES_LOCK:
        model = loaded(task.source)
        poses = task.poses
        if isinstance(poses, RandomRange):
            poses = random_pose_range(model.mujoco.model, poses.start, poses.stop, poses.seed, poses.velocity_scale)
        engines = {name: model.engine(name) for name in task.engines}  # an engine that cannot check it: its reason
        try:
            runs = {name: run_engine(engine, poses) for name, engine in engines.items()}
        except ValueError as err:  # an engine produced an invalid state: name the file
            raise ValueError(f"{model.path}: {one_line(err)}") from err
    _check_finite(model.path, runs, poses)
    return evaluate_chunk(
        task.label, poses, runs, task.formulas, task.records, task.rtol, task.index, task.planar_normals
    )


#: Poses from which the plane normals of eq. (16) are inferred, the same for every chunking.
PROBE_POSES = 256


def probe_normals(pair: Any, poses: PoseSet | None, random: RandomRange | None) -> dict[str, np.ndarray]:
    """Per engine, the plane normals of eq. (16) inferred from the model's first poses.

    ``planar`` infers its normal from a batch; a model cut into chunks fixes it once, from the
    first :data:`PROBE_POSES` poses, so that every chunking refuses or accepts alike.

    Parameters
    ----------
    pair : koenig_check.engines.LoadedModel
    poses : PoseSet, optional
    random : RandomRange, optional

    Returns
    -------
    dict of str to ndarray (B, 3)
    """
    from koenig_check.formulas.planar import infer_normals

    if poses is not None:
        probe = poses.slice(0, min(poses.n_poses, PROBE_POSES))
    elif random is None:
        raise ValueError("probe_normals needs poses or a random range")
    else:
        stop = min(random.stop, random.start + PROBE_POSES)
        probe = random_pose_range(pair.mujoco.model, random.start, stop, random.seed, random.velocity_scale)
    return {name: infer_normals(e.segment_states(probe.qpos, probe.qvel)) for name, e in pair.engines.items()}


def plan(
    source: ModelSource,
    label: str,
    formulas: Iterable[str],
    records: str,
    rtol: float,
    n_segments: int,
    poses: PoseSet | None = None,
    random: RandomRange | None = None,
    size: int | None = None,
    planar_normals: dict[str, np.ndarray] | None = None,
    engines: tuple[str, ...] = ENGINES,
) -> list[ChunkTask]:
    """Cut a model's poses into chunk tasks.

    Parameters
    ----------
    source : ModelSource
    label : str
    formulas : iterable of str
    records : {"segments", "totals", "none"}
    rtol : float
    n_segments : int
        Sets the default chunk size (:func:`chunk_size`).
    poses : PoseSet, optional
        Poses held in memory, sliced into chunks; a path (``times``) stays one chunk, because
        the ``integrated`` angles integrate along all of it.
    random : RandomRange, optional
        Otherwise: the range of seeded random poses.
    size : int, optional
        Poses per chunk.
    planar_normals : dict, optional
        See :func:`probe_normals`.
    engines : tuple of str
        The engines run on every pose.

    Returns
    -------
    list of ChunkTask
    """
    size = size or chunk_size(n_segments)
    if size < 1:
        raise ValueError(f"chunk size must be >= 1, got {size}")
    formulas = tuple(formulas)

    def task(index: int, chunk: RandomRange | PoseSet) -> ChunkTask:
        return ChunkTask(source, label, formulas, records, rtol, index, chunk, planar_normals, tuple(engines))

    if poses is not None:
        if poses.times is not None or poses.n_poses <= size:
            return [task(0, poses)]
        return [
            task(k, poses.slice(start, min(start + size, poses.n_poses)))
            for k, start in enumerate(range(0, poses.n_poses, size))
        ]
    if random is None:
        raise ValueError("plan needs poses or a random range")
    return [
        task(k, RandomRange(start, min(start + size, random.stop), random.seed, random.velocity_scale))
        for k, start in enumerate(range(random.start, random.stop, size))
    ]


def chunk_poses_of(task: ChunkTask) -> int:
    """The number of poses of a chunk task.

    Parameters
    ----------
    task : ChunkTask

    Returns
    -------
    int
    """
    chunk = task.poses
    return chunk.stop - chunk.start if isinstance(chunk, RandomRange) else chunk.n_poses


def _windowed(submit: Callable[[ChunkTask], Any], result: Callable[[Any], ChunkResult], tasks, window: int):
    pending: deque = deque()
    for t in tasks:
        pending.append(submit(t))
        if len(pending) >= window:
            yield result(pending.popleft())
    while pending:
        yield result(pending.popleft())


def run_tasks(tasks: list[ChunkTask], jobs: int = 1, client: Any = None) -> Iterator[ChunkResult]:
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
            yield run_chunk(t)
        return
    with _pool(jobs) as pool:
        yield from _windowed(lambda t: pool.submit(run_chunk, t), lambda f: f.result(), tasks, 2 * jobs)


def _pool(jobs: int) -> Executor:
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    return ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context(method))


def run_model(
    pair: Any,
    source: ModelSource,
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
) -> ModelComparison:
    """Run a loaded model's poses chunk by chunk; merge the statistics, stream the records.

    Parameters
    ----------
    pair : koenig_check.engines.LoadedModel
        The model, loaded here, with the engines to run on every pose (chunks run here reuse it; other
        processes load ``source`` and attach the same engines).
    source : ModelSource
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
    ModelComparison
    """
    remember(source, pair)
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
    for result in run_tasks(tasks, jobs=jobs, client=client):
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
    return finish_comparison(label, pose_set, stats, kept_records, notes, tuple(pair.engines), pose_kind=kind)
