"""The Python API: ``koenig_check.compare(...)`` with the reach of the command line.

Its result is :class:`~koenig_check.run.cross_check.CrossCheck`; poses are drawn by
:func:`~koenig_check.run.pose_kinds.make_poses`, the load options merged by
:func:`~koenig_check.engines.load_options.load_options_from`.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from koenig_check.arguments import check_compare_arguments, keywords_of, suggest_keywords
from koenig_check.diagnosis import policy, reason
from koenig_check.engines.cross_readings import cross_readings
from koenig_check.engines.load_options import LoadOptions, load_options_from
from koenig_check.engines.registry import check_engines
from koenig_check.exceptions import one_line
from koenig_check.run import pipeline, poses
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.cross_check import CrossCheck
from koenig_check.run.labels import unique_labels
from koenig_check.run.pose_kinds import make_poses
from koenig_check.run.stats import DEFAULT_RTOL

if TYPE_CHECKING:
    from koenig_check.report import RecordSink


def compare_model(
    model: str | Path,
    *,
    pose_kind: str = "random",
    n_poses: int = 20,
    seed: int = 0,
    formulas: Sequence[str] | None = None,
    velocity_scale: float = 1.0,
    grid_joints: Sequence[str] | None = None,
    duration: float = 1.0,
    pose_set: poses.PoseSet | None = None,
    pose_file: str | Path | None = None,
    label: str | None = None,
    load_options: LoadOptions | None = None,
    rtol: float = DEFAULT_RTOL,
    records: str = "totals",
    jobs: int = 1,
    client: Any = None,
    sink: RecordSink | None = None,
    keep_records: bool | None = None,
    chunk_poses: int | None = None,
    on_chunk: Callable[[int, int], None] | None = None,
    **load_kwargs: Any,
) -> ModelComparison:
    """Load one model into both engines and run the comparison on it.

    Parameters
    ----------
    model : str or Path
        A model file or a known model name (``koenig-check models``).
    pose_kind, n_poses, seed, velocity_scale, grid_joints, duration
        See :func:`make_poses`.
    formulas : sequence of str, optional
    pose_set : PoseSet, optional
        Use these canonical states instead of drawing poses.
    pose_file : str or Path, optional
        Read the canonical states from a file (see :mod:`koenig_check.run.pose_file`).
    label : str, optional
    load_options : LoadOptions, optional
        How the model is loaded (see :class:`koenig_check.engines.load_options.LoadOptions`); its
        ``engines`` decide whether Drake runs (:mod:`koenig_check.diagnosis.policy`).
    rtol : float
        Tolerance under which engines agree (the over/under counts of the summaries, and whether
        Drake is consulted by default).
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
    on_chunk : callable, optional
        Called as ``on_chunk(poses, total)`` after each chunk: its poses and the model's total.
    **load_kwargs
        The load options as keywords (``floating``, ``balance_inertia``, ``pinocchio_model``, ...);
        they override ``load_options``.

    Returns
    -------
    ModelComparison

    Raises
    ------
    Exception
        Any load or comparison failure, with a one-line message.
    """
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.engines import load_model

    options = load_options_from(load_options, load_kwargs)
    loaded = load_model(model, options)
    policy.attach_engines(loaded)  # the engines the user named run on every pose
    if pose_file is not None:
        from koenig_check.run.pose_file import load_pose_file

        pose_set = load_pose_file(pose_file, loaded.mujoco.model)
    random = None
    if pose_set is None and pose_kind == "random":
        poses.check_random(n_poses, seed, velocity_scale)
        random = pipeline.RandomRange(0, n_poses, seed, velocity_scale)
    elif pose_set is None:
        pose_set = make_poses(
            loaded.mujoco.model,
            pose_kind,
            n_poses=n_poses,
            seed=seed,
            velocity_scale=velocity_scale,
            grid_joints=grid_joints,
            duration=duration,
        )
    run, sample = pipeline.run_model(
        loaded,
        pipeline.WorkerModel(str(model), options),
        label or unique_labels([model], options.floating)[0],
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
        on_chunk=on_chunk,
    )
    disagree = run.stats is not None and run.stats.agreement.rigid.value > rtol
    diagnosis = diagnose(
        loaded,
        disagree=disagree,
        qpos=sample.qpos if sample is not None else None,
        qvel=sample.qvel if sample is not None else None,
        energies=sample.energies if sample is not None else None,
        rtol=rtol,
    )
    return replace(
        run,
        findings=diagnosis.findings,
        gravity=diagnosis.gravity,
        segment_labels=diagnosis.parity.segment_labels if diagnosis.parity is not None else {},
        notes=[reason.as_note(f) for f in diagnosis.verdicts]
        + [f.message() for f in diagnosis.optional_findings]
        + run.notes,
    )


@dataclass(frozen=True)
class PreparedModels:
    """Models checked and fetched once (:func:`prepare_models`): :func:`compare` does not prepare them again.

    Attributes
    ----------
    models : tuple of str or Path
    """

    models: tuple[str | Path, ...]


def prepare_models(
    models: Sequence[str | Path], pinocchio_model: str | os.PathLike[str] | None = None
) -> PreparedModels:
    """Check and fetch the models of a batch before any is loaded (extras, names, downloads), once.

    Parameters
    ----------
    models : sequence of str or Path
    pinocchio_model : str or Path, optional
        The file Pinocchio reads instead (``--pinocchio-model``), fetched too.

    Returns
    -------
    PreparedModels
        To pass to :func:`compare` as its ``models``.

    Raises
    ------
    koenig_check.sources.ModelSourceError
        The first model that cannot be had.
    """
    from koenig_check.sources.external import prepare

    prepare([*models, *([pinocchio_model] if pinocchio_model else [])])
    return PreparedModels(tuple(models))


@suggest_keywords
def compare(
    models: str | Path | Sequence[str | Path] | Mapping[str, str | Path] | PreparedModels,
    *,
    rtol: float = DEFAULT_RTOL,
    progress: Callable[[str], None] | None = None,
    debug: bool = False,
    pose_kind: str = "random",
    n_poses: int = 20,
    seed: int = 0,
    formulas: Sequence[str] | None = None,
    velocity_scale: float = 1.0,
    grid_joints: Sequence[str] | None = None,
    duration: float = 1.0,
    pose_set: poses.PoseSet | None = None,
    pose_file: str | Path | None = None,
    records: str = "totals",
    jobs: int = 1,
    client: Any = None,
    sink: RecordSink | None = None,
    keep_records: bool | None = None,
    chunk_poses: int | None = None,
    load_options: LoadOptions | None = None,
    floating: bool | None = None,
    balance_inertia: bool | None = None,
    repair_inertia: bool | None = None,
    pinocchio_model: str | Path | None = None,
    allow_coupled: bool | None = None,
    engines: Sequence[str] | None = None,
    xacro_args: Mapping[str, Any] | Sequence[str] | None = None,
) -> CrossCheck:
    """Cross-check kinetic energy for one or several models; a failing model never loses the others.

    Parameters
    ----------
    models : str, Path, sequence of them, mapping of label to them, or PreparedModels
        Model files or names (``koenig-check models``); labelled by :func:`koenig_check.run.labels.unique_labels`
        unless given as ``{label: model}`` (the pytest plugin labels each model as the whole run does).  Models
        given as :class:`PreparedModels` (:func:`prepare_models`) were fetched already: not prepared again.
    rtol : float
        Tolerance of "agrees" (engines with each other and with ``exact``; formulas).
    progress : callable, optional
        Called as ``progress(label)`` as each model starts.  If it also has a method
        ``advance(poses, total)``, that is called after each chunk of poses with the number of poses
        just compared and the model's total (:class:`koenig_check.report.progress.Progress` does both).
    debug : bool
        Re-raise a model's failure instead of recording it (to see its traceback).
    pose_kind : {"random", "keyframes", "grid", "trajectory"}
    n_poses : int
        Poses (random), samples per joint (grid) or samples along the path (trajectory).
    seed : int
    formulas : sequence of str, optional
        Default: every formula (``koenig-check compare --help`` lists them).
    velocity_scale : float
        Standard deviation of the random joint rates.
    grid_joints : sequence of two str, optional
        The two joints of a ``grid`` sweep.
    duration : float
        Trajectory duration in seconds.
    pose_set : PoseSet, optional
        Use these canonical states instead of drawing poses.
    pose_file : str or Path, optional
        Read the canonical states from a ``.npz`` or ``.csv`` file.
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
    load_options : LoadOptions, optional
        How the models are loaded; the load keywords below override its fields.
    floating, balance_inertia, repair_inertia, pinocchio_model, allow_coupled, engines, xacro_args
        The fields of :class:`koenig_check.engines.load_options.LoadOptions` (see there); ``None`` keeps the
        value of ``load_options`` (its default when not given).

    Returns
    -------
    CrossCheck

    Raises
    ------
    TypeError
        A keyword :func:`compare` does not take (the message names the closest one), or an argument of the
        wrong type (:class:`koenig_check.arguments.ArgumentTypeError`), before any model is loaded.
    ValueError
        An argument out of range (``rtol <= 0``, ``n_poses < 1``, an unknown formula, a grid without its
        two joints: :class:`koenig_check.arguments.ArgumentValueError`), before any model is loaded; or a
        model named by its source that cannot be had (:class:`koenig_check.sources.ModelSourceError`: extra
        missing, unknown name, download impossible), before any model is loaded.
    """
    given = dict(locals())
    options = {name: given[name] for name in RUN_OPTIONS}
    overrides = {name: given[name] for name in LoadOptions.names() if given[name] is not None}
    prepared = isinstance(models, PreparedModels)
    if isinstance(models, PreparedModels):
        models = list(models.models)
    if isinstance(models, str | Path):
        models = [models]
    given_labels = list(models.keys()) if isinstance(models, Mapping) else None
    models = list(models.values()) if isinstance(models, Mapping) else models
    check_compare_arguments(rtol, options)
    load = load_options_from(load_options, overrides)
    check_engines(load.engines)
    models = list(models)
    if not prepared:
        prepare_models(models, load.pinocchio_model)  # extras, names, downloads
    result = CrossCheck(rtol=rtol, not_named=policy.not_named(load.engines))
    advance = getattr(progress, "advance", None)
    labels = given_labels or unique_labels(models, load.floating, load.xacro_args)
    for model, label in zip(models, labels, strict=True):
        if progress:
            progress(label)
        result.settings[label] = {k: options[k] for k in _SETTINGS}
        try:
            comp = compare_model(model, label=label, load_options=load, rtol=rtol, on_chunk=advance, **options)
        except Exception as err:  # recorded with its reason; the batch goes on
            if debug:
                raise
            result.failures.append((label, one_line(err)))
            result.failure_lines[label] = failure_line(err, model, label)
            result.failure_parts[label] = failure_parts(err, model)
            causes = tuple(getattr(err, "causes", ()))  # and what the engines asked for misread among them
            result.failure_causes[label] = causes + tuple(cross_readings(causes, load.engines or ()))
            continue
        result.add(comp)
    return result


def failure_line(err: BaseException, model: Any, label: str) -> str:
    """Why a model could not be compared, in one sentence of at most 200 characters with ``koenig-check: ``.

    Parameters
    ----------
    err : BaseException
    model : str or path
        The model as the user gave it.
    label : str
        Its label, which names the file: the path (as given, or resolved from a name) is left out.

    Returns
    -------
    str
        ``label: <error>; root cause: ...``.
    """
    from koenig_check.sources.shown_paths import as_given

    def given(text: str) -> str:
        return as_given(text, [model])

    def named(text: str) -> str:  # the label names the file: its path goes, as given or resolved from a name
        text = given(text).replace(f"{model}: ", "").replace(str(model), label)
        leading = re.match(r"/\S+?([^/\s]+)\.\w+: ", text)  # a source name's resolved file (menagerie:...:scene)
        return text[leading.end() :] if leading and leading.group(1) in label else text

    width = reason.REASON_WIDTH - len(label) - 2
    whole = reason.short_error(err, 10**6, given).removeprefix(f"{label}: ")  # the file named once
    return f"{label}: {whole if len(whole) <= width else reason.short_error(err, width, named)}"


def failure_parts(err: BaseException, model: Any) -> dict[str, Any]:
    """What a model's failure message is made of (its whole message, the engine's words, the hint), paths as given.

    Parameters
    ----------
    err : BaseException
    model : str or path
        The model as the user gave it.

    Returns
    -------
    dict
        :func:`koenig_check.diagnosis.message.error_parts`, the file named as the user gave it.
    """
    from koenig_check.diagnosis.message import error_parts
    from koenig_check.sources.shown_paths import as_given

    parts = error_parts(err)
    parts["whole"] = as_given(str(parts["whole"]), [model])
    return parts


#: The keywords of :func:`compare` passed on to :func:`compare_model` for every model.
RUN_OPTIONS = tuple(sorted(keywords_of(compare_model) - {"model", "label", "rtol", "load_options", "on_chunk"}))


#: The pose settings recorded per model for the report (see :attr:`CrossCheck.settings`).
_SETTINGS = ("pose_kind", "n_poses", "seed", "velocity_scale", "duration", "grid_joints")
