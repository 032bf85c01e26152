"""The Python API: ``koenig_check.compare(...)`` with the reach of the command line."""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from koenig_check import grid, pipeline, poses
from koenig_check.grid import DEFAULT_RTOL, EngineParity, FormulaSummary, ModelComparison
from koenig_check.records import RecordTable

if TYPE_CHECKING:
    from koenig_check.report import RecordSink

POSE_KINDS = ("random", "keyframes", "grid", "trajectory")


@dataclass
class CrossCheck:
    """Result of :func:`compare` over one or several models.

    Attributes
    ----------
    comparisons : list of ModelComparison
    summaries : list of FormulaSummary
    parities : list of EngineParity
    failures : list of (str, str)
        Models that could not be compared, with a one-line reason each.
    rtol : float
    """

    comparisons: list[ModelComparison] = field(default_factory=list)
    summaries: list[FormulaSummary] = field(default_factory=list)
    parities: list[EngineParity] = field(default_factory=list)
    failures: list[tuple[str, str]] = field(default_factory=list)
    rtol: float = DEFAULT_RTOL

    @property
    def records(self) -> RecordTable:
        """All tidy records of all models (iterate for dicts, index by column name for arrays)."""
        return grid.records_for(self.comparisons)

    @property
    def ok(self) -> bool:
        """True when every model loaded and both engines agree with each other and with ``exact``."""
        return not self.failures and all(p.agrees for p in self.parities)

    def add(self, comparison: ModelComparison) -> EngineParity:
        """Record one model's comparison with its summaries and engine parity.

        Parameters
        ----------
        comparison : ModelComparison

        Returns
        -------
        EngineParity
            The parity just recorded.
        """
        self.comparisons.append(comparison)
        self.summaries += grid.summarize(comparison, self.rtol)
        parity = grid.engine_parity(comparison, self.rtol)
        self.parities.append(parity)
        return parity

    def reason(self) -> str:
        """One line saying why :attr:`ok` is False (empty when it is True)."""
        parts = [f"{m}: {r}" for m, r in self.failures]
        parts += [f"{p.model}: {p.reason}" for p in self.parities if not p.agrees]
        return "; ".join(parts)


def _label(model: str | Path, floating: bool) -> str:
    text = Path(model).name if Path(str(model)).suffix else str(model)
    return f"{text} (floating)" if floating else text


def make_poses(
    mj_model: Any,
    kind: str = "random",
    n_poses: int = 20,
    seed: int = 0,
    velocity_scale: float = 1.0,
    grid_joints: Sequence[str] | None = None,
    duration: float = 1.0,
) -> poses.PoseSet:
    """Draw a pose set of a given kind for a MuJoCo model.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    kind : {"random", "keyframes", "grid", "trajectory"}
    n_poses : int
        Poses (random), samples per joint (grid) or samples along the path (trajectory).
    seed : int
    velocity_scale : float
    grid_joints : sequence of two str, optional
        Required for ``grid``.
    duration : float
        Trajectory duration in seconds.

    Returns
    -------
    PoseSet
    """
    if kind == "random":
        return poses.random_poses(mj_model, n_poses, seed=seed, velocity_scale=velocity_scale)
    if kind == "keyframes":
        keys = poses.keyframe_poses(mj_model, seed=seed, velocity_scale=velocity_scale)
        if keys.n_poses == 0:
            raise ValueError("the model has no keyframe")
        return keys
    if kind == "grid":
        if not grid_joints or len(grid_joints) != 2:
            raise ValueError("a grid sweep needs exactly two joint names")
        return poses.grid_poses(mj_model, grid_joints[0], grid_joints[1], n=n_poses)
    if kind == "trajectory":
        return poses.trajectory_poses(
            mj_model, duration=duration, samples=max(n_poses, 2), seed=seed, velocity_scale=velocity_scale
        )
    raise ValueError(f"unknown pose kind {kind!r}; choose one of {POSE_KINDS}")


def compare_model(
    model: str | Path,
    *,
    pose_kind: str = "random",
    n_poses: int = 20,
    seed: int = 0,
    formulas: Sequence[str] | None = None,
    floating: bool = False,
    balance_inertia: bool = False,
    allow_coupled: bool = False,
    velocity_scale: float = 1.0,
    grid_joints: Sequence[str] | None = None,
    duration: float = 1.0,
    pose_set: poses.PoseSet | None = None,
    pose_file: str | Path | None = None,
    pinocchio_model: str | Path | None = None,
    label: str | None = None,
    rtol: float = DEFAULT_RTOL,
    records: str = "totals",
    jobs: int = 1,
    client: Any = None,
    sink: RecordSink | None = None,
    keep_records: bool | None = None,
    chunk_poses: int | None = None,
) -> ModelComparison:
    """Load one model into both engines and run the comparison grid on it.

    Parameters
    ----------
    model : str or Path
        A model file or a known model name (``koenig-check models``).
    pose_kind, n_poses, seed, velocity_scale, grid_joints, duration
        See :func:`make_poses`.
    formulas : sequence of str, optional
    floating : bool
        Free-floating base (URDF).
    balance_inertia : bool
        Let MuJoCo balance inertias that violate the triangle inequality (noted).
    allow_coupled : bool
        Load models with coupled joints (mimic, equalities), treating the joints as independent (noted).
    pose_set : PoseSet, optional
        Use these canonical states instead of drawing poses.
    pose_file : str or Path, optional
        Read the canonical states from a file (see :mod:`koenig_check.pose_file`).
    pinocchio_model : str or Path, optional
        A different file of the same robot for Pinocchio (e.g. the URDF twin of an MJCF).
    label : str, optional
    rtol : float
        Tolerance of the over/under counts in the summaries.
    records : {"totals", "segments", "none"}
        Which records to keep: totals per pose, also per segment, or none (summaries only).
    jobs : int
        Run the pose chunks in this many local processes (same results as one process).
    client : dask.distributed.Client, optional
        Run the pose chunks on a Dask cluster (extra ``[cluster]``).
    sink : RecordSink, optional
        Receives the records chunk by chunk as they are computed (e.g. a Parquet file).
    keep_records : bool, optional
        Keep the records in memory too (default: only without a sink).
    chunk_poses : int, optional
        Poses per chunk (default: about 32,768 segment-poses per chunk).

    Returns
    -------
    ModelComparison

    Raises
    ------
    Exception
        Any load or comparison failure, with a one-line message.
    """
    from koenig_check.engines import load_model
    from koenig_check.parity import import_parity

    pair = load_model(
        model,
        floating=floating,
        balance_inertia=balance_inertia,
        allow_coupled=allow_coupled,
        pinocchio_source=pinocchio_model,
    )
    source = pipeline.ModelSource.of(
        model,
        floating=floating,
        balance_inertia=balance_inertia,
        allow_coupled=allow_coupled,
        pinocchio_source=pinocchio_model,
    )
    pipeline.remember(source, pair)
    if pose_file is not None:
        from koenig_check.pose_file import load_pose_file

        pose_set = load_pose_file(pose_file, pair.mujoco.model)
    random = None
    if pose_set is None and pose_kind == "random":
        poses.check_random(n_poses, seed, velocity_scale)
        random = pipeline.RandomRange(0, n_poses, seed, velocity_scale)
    elif pose_set is None:
        pose_set = make_poses(
            pair.mujoco.model,
            pose_kind,
            n_poses=n_poses,
            seed=seed,
            velocity_scale=velocity_scale,
            grid_joints=grid_joints,
            duration=duration,
        )
    comp = pipeline.run_model(
        pair,
        source,
        label or _label(model, floating),
        formulas,
        pose_set=pose_set,
        random=random,
        records=records,
        rtol=rtol,
        jobs=jobs,
        client=client,
        sink=sink,
        keep_records=keep_records,
        chunk_poses=chunk_poses,
    )
    comp.import_summary = import_parity(pair).headline()
    return comp


def compare(
    models: str | Path | Sequence[str | Path],
    *,
    rtol: float = DEFAULT_RTOL,
    progress: Callable[[str], None] | None = None,
    debug: bool = False,
    **options: Any,
) -> CrossCheck:
    """Cross-check kinetic energy for one or several models; a failing model never loses the others.

    Parameters
    ----------
    models : str, Path or sequence of them
        Model files or names.
    rtol : float
        Tolerance of "agrees" (engines with each other and with ``exact``; formulas).
    progress : callable, optional
        Called with a short message as each model starts.
    debug : bool
        Re-raise a model's failure instead of recording it (to see its traceback).
    **options
        Passed to :func:`compare_model` (``pose_kind``, ``n_poses``, ``seed``, ``formulas``,
        ``floating``, ``balance_inertia``, ``allow_coupled``, ``velocity_scale``, ``grid_joints``, ``duration``,
        ``pose_set``, ``pose_file``, ``records``, ``jobs``, ``client``, ``sink``, ``chunk_poses``).

    Returns
    -------
    CrossCheck
    """
    if isinstance(models, str | Path):
        models = [models]
    result = CrossCheck(rtol=rtol)
    for model in models:
        label = _label(model, bool(options.get("floating")))
        if progress:
            progress(label)
        try:
            comp = compare_model(model, label=label, rtol=rtol, **options)
        except Exception as err:  # recorded with its reason; the batch goes on
            if debug:
                raise
            result.failures.append((label, one_line(err)))
            continue
        result.add(comp)
    return result


def one_line(err: BaseException) -> str:
    """A one-line description of an exception (its type when it has no message).

    Parameters
    ----------
    err : BaseException

    Returns
    -------
    str
    """
    text = " ".join(str(err).split())
    return text or type(err).__name__


def stderr_progress(message: str) -> None:
    """Print a progress line on standard error.

    Parameters
    ----------
    message : str
    """
    print(f"  … {message}", file=sys.stderr, flush=True)
