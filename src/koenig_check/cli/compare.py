"""``koenig-check compare`` and ``koenig-check demo``: cross-check models, print the verdict, write the report."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from koenig_check.cli.parsing import (
    DEFAULT_OUT,
    add_command,
    add_out,
    check_models,
    check_out,
    load_options_of,
    positive,
    tolerance,
    usage_error,
)
from koenig_check.engines.load_options import add_load_arguments


def add(sub: argparse._SubParsersAction) -> None:
    """Add the ``demo`` and ``compare`` sub-commands.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    from koenig_check.arguments import RECORD_MODES
    from koenig_check.run.stats import DEFAULT_RTOL

    p = add_command(
        sub,
        "demo",
        "the main job: every built-in model in both engines, a verdict table and a report directory",
        "koenig-check demo --out report",
    )
    add_out(p, f"report directory (default {DEFAULT_OUT})", DEFAULT_OUT)
    p.add_argument("--poses", type=positive, default=20, help="random poses per model (default 20)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument(
        "--rtol", type=tolerance, default=DEFAULT_RTOL, help=f"agreement tolerance (default {DEFAULT_RTOL:g})"
    )
    _add_quiet(p)
    p.set_defaults(func=_cmd_demo)

    p = add_command(
        sub,
        "compare",
        "cross-check one or several models (files or names from `koenig-check models`)",
        "koenig-check compare gimbal.xml ur5 --poses 50 --out ur5-report",
        _formulas_epilog(),
    )
    p.add_argument("models", nargs="+", metavar="MODEL", help="model file or name")
    p.add_argument("--poses", type=positive, default=20, help="number of poses / grid samples per joint (default 20)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument("--formulas", nargs="+", metavar="NAME", help="formulas to evaluate (default: all; names below)")
    add_out(p, "write a report directory here")
    p.add_argument(
        "--rtol", type=tolerance, default=DEFAULT_RTOL, help=f"agreement tolerance (default {DEFAULT_RTOL:g})"
    )
    p.add_argument(
        "--pose-kind",
        choices=("random", "keyframes", "grid", "trajectory"),
        default="random",
        help="pose sampler (default random; see below)",
    )
    p.add_argument("--grid-joints", nargs=2, metavar=("A", "B"), help="the two joints of a grid sweep")
    p.add_argument("--duration", type=float, default=1.0, help="trajectory duration in seconds (default 1)")
    p.add_argument("--velocity-scale", type=float, default=1.0, help="std of random joint velocities (default 1)")
    p.add_argument("--pose-file", help="canonical poses from a .npz (qpos, qvel) or .csv (qpos then qvel per row)")
    add_load_arguments(p)
    p.add_argument(
        "--records",
        choices=RECORD_MODES,
        default="totals",
        help="records written with --out: per segment and totals, totals (default) or none",
    )
    p.add_argument("--jobs", type=positive, default=1, help="run pose chunks in N local processes (default 1)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run pose chunks on this Dask scheduler (extra [cluster])")
    _add_quiet(p)
    p.set_defaults(func=_cmd_compare)


def _add_quiet(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--quiet",
        action="store_true",
        help="no progress bar (it is drawn on a terminal only, over the poses of each model, for runs over 2 s)",
    )


def _formulas_epilog() -> str:
    from koenig_check.arguments import POSE_KIND_HELP
    from koenig_check.formulas import FORMULAS
    from koenig_check.line_width import hanging

    lines = ["formulas (--formulas NAME ...; the paper's equation numbers in brackets):"]
    lines += [f"  {name:30s} {f.equations}" for name, f in FORMULAS.items()]
    lines.append("pose kinds (--pose-kind):")
    lines += [line for kind, text in POSE_KIND_HELP.items() for line in hanging(f"  {kind:11s} ", text)]
    return "\n".join(lines)


def _finish(check, out: str | None, extra_figures: dict | None = None, records=None) -> int:
    from koenig_check.report.terminal import terminal_table

    print(terminal_table(check))
    if out:
        from koenig_check.report import write_report
        from koenig_check.report.output_dir import file_listing, finish_out_dir

        written = finish_out_dir(out, write_report(Path(out), check, **(extra_figures or {}), records=records))
        print("\n" + file_listing(out, written))
    if check.ok:
        return 0
    for message in check.messages(cli=True):  # one per failing model: a sentence, then the whole of it indented
        print(f"koenig-check: {message}", file=sys.stderr)
    return 1


def _check_compare_usage(args: argparse.Namespace) -> None:
    """Every usage error of ``compare`` / ``demo``, before any model is loaded or any file written."""
    from koenig_check.arguments import ArgumentTypeError, ArgumentValueError, check_formulas, check_pose_file

    try:
        check_formulas(getattr(args, "formulas", None))
        check_pose_file(getattr(args, "pose_file", None))
    except (ArgumentValueError, ArgumentTypeError) as err:
        usage_error(args, str(err))
    if getattr(args, "pose_kind", None) == "grid" and not args.grid_joints and not args.pose_file:
        usage_error(args, "--pose-kind grid needs --grid-joints A B (the names of two joints)")
    if getattr(args, "grid_joints", None) and args.pose_kind != "grid":
        usage_error(args, "--grid-joints is only used with --pose-kind grid")
    for name in ("duration", "velocity_scale"):
        value = getattr(args, name, None)
        if value is not None and not (0 < value < float("inf")):
            usage_error(args, f"--{name.replace('_', '-')} must be a finite number > 0, got {value}")
    if getattr(args, "seed", 0) < 0:
        usage_error(args, f"--seed must be >= 0, got {args.seed}")
    check_out(args)


def _cmd_compare(args: argparse.Namespace) -> int:
    from koenig_check.api import compare, prepare_models
    from koenig_check.report.progress import Progress

    _check_compare_usage(args)
    load_options = load_options_of(args)
    check_models(args, [*args.models, *([load_options.pinocchio_model] if load_options.pinocchio_model else [])])
    models = prepare_models(args.models, load_options.pinocchio_model)  # once, before any file is written
    client = None
    if args.scheduler:
        try:
            from distributed import Client
        except ImportError:
            hint = "pip install 'koenig-check[cluster]'"
            print(f"koenig-check: error: --scheduler needs the [cluster] extra: {hint}", file=sys.stderr)
            return 2
        client = Client(args.scheduler)
    sink = None
    if args.out:
        from koenig_check.report import RecordFiles
        from koenig_check.report.output_dir import clean_out_dir

        clean_out_dir(args.out)
        sink = RecordFiles(Path(args.out))
    figures_need_records = args.pose_kind in ("grid", "trajectory")
    with Progress(len(args.models), "models", quiet=args.quiet) as bar, _aborted_on_error(sink):
        check = compare(
            models,
            rtol=args.rtol,
            progress=bar,
            pose_kind=args.pose_kind,
            n_poses=args.poses,
            seed=args.seed,
            formulas=args.formulas,
            load_options=load_options,
            velocity_scale=args.velocity_scale,
            grid_joints=args.grid_joints,
            duration=args.duration,
            pose_file=args.pose_file,
            debug=args.debug,
            records=args.records if args.out or figures_need_records else "none",  # nothing else reads them
            jobs=args.jobs,
            client=client,
            sink=sink,
            keep_records=figures_need_records,
        )
    if client is not None:
        client.close()
    figures = {}
    if args.pose_kind in ("grid", "trajectory") and check.comparisons:
        figures[f"{args.pose_kind}_comparison"] = check.comparisons[0]
    return _finish(check, args.out, figures, records=sink)


@contextmanager
def _aborted_on_error(sink: Any) -> Iterator[None]:
    """Abort the record files if the run stops with an exception (an interruption): no partial records file."""
    try:
        yield
    except BaseException:
        if sink is not None:
            sink.abort()
        raise


def _cmd_demo(args: argparse.Namespace) -> int:
    from koenig_check.demo import run_demo
    from koenig_check.report.output_dir import clean_out_dir

    _check_compare_usage(args)
    check, figures = run_demo(n_poses=args.poses, seed=args.seed, rtol=args.rtol, quiet=args.quiet)
    clean_out_dir(args.out)
    return _finish(check, args.out, figures)
