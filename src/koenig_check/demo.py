"""The main job: every built-in model in both engines, plus the gimbal map and a trajectory."""

from __future__ import annotations

import importlib.resources
from collections.abc import Sequence
from pathlib import Path
from typing import TypedDict

from koenig_check.api import CrossCheck, compare_model, failure_line, failure_parts, one_line
from koenig_check.report.progress import Progress
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.stats import DEFAULT_RTOL

#: Built-in models that are a single free body: loaded with a floating base.
FLOATING_MODELS = frozenset({"free_body.urdf"})
#: The paper's section-3 gimbal and its two joints.
GIMBAL = ("gimbal.xml", ("outer_z", "inner_x"))


class _DemoModel(TypedDict):
    model: Path


class _DemoRun(_DemoModel, total=False):
    """The keyword arguments of :func:`compare_model` for one demo run (``floating`` goes to the loader)."""

    pose_kind: str
    n_poses: int
    seed: int
    floating: bool
    grid_joints: Sequence[str]
    duration: float
    velocity_scale: float


def builtin_models() -> list[Path]:
    """The project's own model files shipped with the package, MJCF then URDF.

    Returns
    -------
    list of Path
    """
    root = importlib.resources.files("koenig_check.models")
    files = [Path(str(p)) for p in root.iterdir() if p.name.endswith((".xml", ".urdf"))]
    return sorted(files, key=lambda p: (p.stem, p.suffix != ".xml"))


def run_demo(
    n_poses: int = 20,
    seed: int = 0,
    rtol: float = DEFAULT_RTOL,
    grid_samples: int = 25,
    trajectory_samples: int = 200,
    quiet: bool = False,
) -> tuple[CrossCheck, dict[str, ModelComparison]]:
    """Cross-check every built-in model, sweep the gimbal's two angles and follow a trajectory.

    Parameters
    ----------
    n_poses : int
        Random poses per model.
    seed : int
    rtol : float
    grid_samples : int
        Samples per gimbal angle.
    trajectory_samples : int
        Samples along the simulated gimbal trajectory (2 s from the reference pose).
    quiet : bool
        No progress bar (it is drawn on a terminal only).

    Returns
    -------
    check : CrossCheck
    figures : dict
        ``grid_comparison`` and ``trajectory_comparison`` for :func:`koenig_check.report.write_report`.
    """
    models = builtin_models()
    by_name = {p.name: p for p in models}
    gimbal_path, gimbal_joints = by_name[GIMBAL[0]], GIMBAL[1]
    jobs: list[tuple[str, _DemoRun]] = [
        (p.name, {"model": p, "n_poses": n_poses, "seed": seed, "floating": p.name in FLOATING_MODELS}) for p in models
    ]
    jobs.append(
        (
            f"{GIMBAL[0]} angle grid",
            {
                "model": gimbal_path,
                "pose_kind": "grid",
                "n_poses": grid_samples,
                "grid_joints": gimbal_joints,
            },
        )
    )
    jobs.append(
        (
            f"{GIMBAL[0]} trajectory",
            {
                "model": gimbal_path,
                "pose_kind": "trajectory",
                "n_poses": trajectory_samples,
                "seed": seed,
                "duration": 2.0,
                "velocity_scale": 2.0,
            },
        )
    )
    check = CrossCheck(rtol=rtol)
    figures: dict[str, ModelComparison] = {}
    with Progress(len(jobs), "models", quiet=quiet) as bar:
        for label, options in jobs:
            bar.step(label)
            check.settings[label] = {"seed": seed, "velocity_scale": 1.0, **options}
            check.settings[label].pop("model")
            try:
                comp = compare_model(label=label, rtol=rtol, on_chunk=bar.advance, **options)
            except Exception as err:  # the other models still report
                check.failures.append((label, one_line(err)))
                check.failure_lines[label] = failure_line(err, options["model"], label)
                check.failure_parts[label] = failure_parts(err, options["model"])
                check.failure_causes[label] = tuple(getattr(err, "causes", ()))
                continue
            check.add(comp)
            if options.get("pose_kind") == "grid":
                figures["grid_comparison"] = comp
            elif options.get("pose_kind") == "trajectory":
                figures["trajectory_comparison"] = comp
    return check, figures
