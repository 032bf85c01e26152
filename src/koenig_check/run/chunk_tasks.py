"""A model's poses cut into chunk tasks, each naming everything its chunk needs (so that it runs anywhere).

A :class:`ChunkTask` holds the model a worker loads (:class:`WorkerModel`: the file or name and its load
options), the formulas, the record mode, the tolerance and the pose range (seeded random poses ``start`` to
``stop``, or the poses themselves); :func:`plan` cuts a model's poses into such tasks, :func:`probe_normals`
fixes once what every chunk must share.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.registry import required
from koenig_check.run.engine_runs import VERDICT_POSES
from koenig_check.run.poses import PoseSet, random_pose_range

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
    poses = int(np.clip(CHUNK_SEGMENT_POSES // max(n_segments, 1), CHUNK_MIN, CHUNK_MAX))
    # The nearest power of two: a chunk of random poses then covers whole blocks of the seeded sequence, or a
    # part of one block (RANDOM_BLOCK, 1024), instead of straddling two and drawing both (Talos: 992 → 1024).
    return int(2 ** round(np.log2(poses)))


@dataclass(frozen=True)
class WorkerModel:
    """How a worker process gets the model of its chunks: the model file or name, and how it is loaded.

    Hashable: a worker process loads each once (:mod:`koenig_check.run.pipeline`).  Not where a model file comes
    from: that is :class:`koenig_check.sources.catalogue.ModelSource`.

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
    source : WorkerModel
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
    verdict_poses : int
        How many of the chunk's first poses are among the run's first :data:`VERDICT_POSES` (the poses the
        verdicts compare): the chunk returns them with its engines' energies on them.
    """

    source: WorkerModel
    label: str
    formulas: tuple[str, ...]
    records: str
    rtol: float
    index: int
    poses: RandomRange | PoseSet
    planar_normals: dict[str, np.ndarray] | None = None
    engines: tuple[str, ...] = field(default_factory=required)
    verdict_poses: int = 0


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
    source: WorkerModel,
    label: str,
    formulas: Iterable[str],
    records: str,
    rtol: float,
    n_segments: int,
    poses: PoseSet | None = None,
    random: RandomRange | None = None,
    size: int | None = None,
    planar_normals: dict[str, np.ndarray] | None = None,
    engines: tuple[str, ...] | None = None,
) -> list[ChunkTask]:
    """Cut a model's poses into chunk tasks.

    Parameters
    ----------
    source : WorkerModel
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
    engines = required() if engines is None else engines
    if size < 1:
        raise ValueError(f"chunk size must be >= 1, got {size}")
    formulas = tuple(formulas)

    def task(index: int, chunk: RandomRange | PoseSet, offset: int) -> ChunkTask:
        verdict = max(VERDICT_POSES - offset, 0)  # a chunk returns at most its own poses
        return ChunkTask(source, label, formulas, records, rtol, index, chunk, planar_normals, tuple(engines), verdict)

    if poses is not None:
        if poses.times is not None or poses.n_poses <= size:
            return [task(0, poses, 0)]
        return [
            task(k, poses.slice(start, min(start + size, poses.n_poses)), start)
            for k, start in enumerate(range(0, poses.n_poses, size))
        ]
    if random is None:
        raise ValueError("plan needs poses or a random range")
    return [
        task(
            k,
            RandomRange(start, min(start + size, random.stop), random.seed, random.velocity_scale),
            start - random.start,
        )
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
