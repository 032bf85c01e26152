"""The ``koenig-check`` command line.

Exit status: 0 when both engines agree with each other and with ``exact`` within
tolerance on every model, 1 with a one-line reason otherwise (a model that fails to
load counts), 2 for a usage error.  Disagreements of the paper's formulas are findings
reported in the tables, not failures.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

from koenig_check import __version__
from koenig_check.engines.load_options import ALLOW_COUPLED_DEPRECATION, LoadOptions, add_load_arguments

DEFAULT_OUT = "koenig-check-report"


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line and exit with status 2."""

    def error(self, message: str) -> None:  # type: ignore[override]
        self.exit(2, f"{self.prog}: error: {message} (see --help)\n")


def _tolerance(text: str) -> float:
    """A relative tolerance: a finite number > 0."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (value > 0 and value < float("inf")):
        raise argparse.ArgumentTypeError(f"tolerance must be a finite number > 0, got {text}")
    return value


def _positive(text: str) -> int:
    """A whole number >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be >= 1, got {text}")
    return value


def _formatter(prog: str) -> argparse.HelpFormatter:
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=32)


def _add(sub: argparse._SubParsersAction, name: str, help_: str, example: str) -> argparse.ArgumentParser:
    p = sub.add_parser(name, help=help_, description=help_, epilog=f"example:\n  {example}", formatter_class=_formatter)
    p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="show Python tracebacks on errors")
    return p


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser with one sub-command per job.

    Returns
    -------
    argparse.ArgumentParser
    """
    from koenig_check.grid import DEFAULT_RTOL, RECORD_MODES

    parser = _Parser(
        prog="koenig-check",
        description="Cross-check rigid-body kinetic energy: MuJoCo, Pinocchio and the formulas of "
        "Alyushin's correction of Koenig's formula.",
        epilog="example:\n  koenig-check demo",
        formatter_class=_formatter,
    )
    parser.add_argument("--version", action="version", version=f"koenig-check {__version__}")
    parser.add_argument("--debug", action="store_true", help="show Python tracebacks on errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    p = _add(
        sub,
        "demo",
        "the main job: every built-in model in both engines, a verdict table and a report directory",
        "koenig-check demo --out report",
    )
    p.add_argument("--out", default=DEFAULT_OUT, help=f"report directory (default {DEFAULT_OUT})")
    p.add_argument("--poses", type=int, default=20, help="random poses per model (default 20)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument(
        "--rtol", type=_tolerance, default=DEFAULT_RTOL, help=f"agreement tolerance (default {DEFAULT_RTOL:g})"
    )
    p.set_defaults(func=_cmd_demo)

    p = _add(
        sub,
        "compare",
        "cross-check one or several models (files or names from `koenig-check models`)",
        "koenig-check compare gimbal.xml ur5 --poses 50 --out ur5-report",
    )
    p.add_argument("models", nargs="+", metavar="MODEL", help="model file or name")
    p.add_argument("--poses", type=int, default=20, help="number of poses / grid samples per joint (default 20)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument("--formulas", nargs="+", metavar="NAME", help="formulas to evaluate (default: all)")
    p.add_argument("--out", help="write a report directory here")
    p.add_argument(
        "--rtol", type=_tolerance, default=DEFAULT_RTOL, help=f"agreement tolerance (default {DEFAULT_RTOL:g})"
    )
    p.add_argument(
        "--pose-kind",
        choices=("random", "keyframes", "grid", "trajectory"),
        default="random",
        help="pose sampler",
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
    p.add_argument("--jobs", type=_positive, default=1, help="run pose chunks in N local processes (default 1)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="run pose chunks on this Dask scheduler (extra [cluster])")
    p.set_defaults(func=_cmd_compare)

    p = _add(
        sub,
        "parity",
        "import parity only: do MuJoCo and Pinocchio see the same robot in the same file?",
        "koenig-check parity serial7.urdf",
    )
    p.add_argument("model", metavar="MODEL", help="model file or name")
    add_load_arguments(p)
    p.set_defaults(func=_cmd_parity)

    p = _add(sub, "models", "list every model name koenig-check can load, with its format", "koenig-check models")
    p.set_defaults(func=_cmd_models)

    p = _add(
        sub,
        "selfcheck",
        "run every formula on analytic cases and print how far each is from the exact energy",
        "koenig-check selfcheck --rtol 1e-12",
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")
    p.add_argument("--rtol", type=_tolerance, default=1e-9, help="agreement tolerance (default 1e-9)")
    p.set_defaults(func=_cmd_selfcheck)

    _add_dynamics_command(sub)
    return parser


# ----------------------------------------------------------------------------- commands
def _cmd_selfcheck(args: argparse.Namespace) -> int:
    from koenig_check.selfcheck import format_table, run_selfcheck

    print(format_table(run_selfcheck(seed=args.seed), rtol=args.rtol))
    return 0


def _cmd_models(args: argparse.Namespace) -> int:
    from koenig_check.engines import list_models

    for source in list_models():
        print(f"{source.name:40s} {source.format:5s} {source.origin:20s} {source.path}")
    return 0


def _finish(check, out: str | None, extra_figures: dict | None = None, records=None) -> int:
    from koenig_check.verdict import verdict_table

    print(verdict_table(check))
    if out:
        from koenig_check.report import write_report

        written = write_report(Path(out), check, **(extra_figures or {}), records=records)
        print(f"\nreport: {Path(out).resolve()} ({len(written)} files)")
    if check.ok:
        return 0
    print(f"koenig-check: engines disagree or a model failed: {check.reason()}", file=sys.stderr)
    return 1


def _load_options(args: argparse.Namespace) -> LoadOptions:
    """The load options of a command; ``--allow-coupled`` is accepted with a note and ignored."""
    from koenig_check.tiebreak import DrakeUnavailableError, check_engines

    options = LoadOptions.from_namespace(args)
    try:
        check_engines(options.engines)
    except DrakeUnavailableError as err:  # a usage error: refused before any work
        print(f"koenig-check: error: {err}", file=sys.stderr)
        raise SystemExit(2) from None
    if options.allow_coupled:
        print(f"koenig-check: note: {ALLOW_COUPLED_DEPRECATION}", file=sys.stderr)
        options = replace(options, allow_coupled=False)
    return options


def _cmd_compare(args: argparse.Namespace) -> int:
    from koenig_check.api import compare
    from koenig_check.progress import Progress

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

        sink = RecordFiles(Path(args.out))
    figures_need_records = args.pose_kind in ("grid", "trajectory")
    with Progress(len(args.models), "models") as bar:
        check = compare(
            args.models,
            rtol=args.rtol,
            progress=bar.step,
            pose_kind=args.pose_kind,
            n_poses=args.poses,
            seed=args.seed,
            formulas=args.formulas,
            load_options=_load_options(args),
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


def _cmd_demo(args: argparse.Namespace) -> int:
    from koenig_check.demo import run_demo

    check, figures = run_demo(n_poses=args.poses, seed=args.seed, rtol=args.rtol)
    return _finish(check, args.out, figures)


def _cmd_parity(args: argparse.Namespace) -> int:
    from koenig_check.engines import load_model
    from koenig_check.parity import format_parity, import_parity
    from koenig_check.tiebreak import parity_verdicts

    options = _load_options(args)
    pair = load_model(args.model, options)
    report = import_parity(pair)
    verdicts, drake_findings = parity_verdicts(pair, options.engines, disagree=not report.clean)
    for f in verdicts + drake_findings:
        print(f"three engines: {f.message()}" if f in verdicts else f.message())
    print(format_parity(report))
    if report.clean and not verdicts:
        return 0
    lead = "; ".join(f.message() for f in verdicts)
    print(
        f"koenig-check: import differences in {args.model}: {'; '.join(t for t in (lead, report.headline()) if t)}",
        file=sys.stderr,
    )
    return 1


# ----------------------------------------------------------------------------- dynamics (self-contained)
def _positive_int(text: str) -> int:
    """A count: an integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be >= 1, got {value}")
    return value


def _add_dynamics_command(sub: argparse._SubParsersAction) -> None:
    """The ``dynamics`` sub-command: M and Q* implied by each formula, against both engines."""
    from koenig_check.engines.load_options import add_load_arguments
    from koenig_check.formulas import FORMULAS
    from koenig_check.implied_dynamics.analysis import M_RTOL, Q_RTOL

    p = _add(
        sub,
        "dynamics",
        "mass matrix and generalized inertia forces implied by each energy formula, against both engines",
        "koenig-check dynamics gimbal.xml --poses 10 --out dyn-report",
    )
    p.add_argument("model", metavar="MODEL", help="model file or name")
    add_load_arguments(p)
    p.add_argument("--poses", type=_positive_int, default=5, help="random poses (default 5)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument(
        "--formulas", nargs="+", metavar="NAME", choices=list(FORMULAS), help="formulas (default: all; exact always)"
    )
    p.add_argument("--out", help="write dynamics.md and dynamics.json into this directory")
    p.add_argument("--m-rtol", type=_tolerance, default=M_RTOL, help=f"tolerance on M of exact (default {M_RTOL:g})")
    p.add_argument("--q-rtol", type=_tolerance, default=Q_RTOL, help=f"tolerance on Q* of exact (default {Q_RTOL:g})")
    p.set_defaults(func=_cmd_dynamics)


def _cmd_dynamics(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from koenig_check.engines.load_options import LoadOptions
    from koenig_check.implied_dynamics.analysis import dynamics
    from koenig_check.implied_dynamics.markdown import terminal_lines, write_dynamics

    options = asdict(LoadOptions.from_namespace(args))
    result = dynamics(
        args.model,
        n_poses=args.poses,
        seed=args.seed,
        formulas=args.formulas,
        m_rtol=args.m_rtol,
        q_rtol=args.q_rtol,
        **options,
    )
    print("\n".join(terminal_lines(result)))
    if args.out:
        written = write_dynamics(Path(args.out), result)
        print(f"\nreport: {Path(args.out).resolve()} ({len(written)} files)")
    if result.ok:
        return 0
    print(f"koenig-check: exact disagrees with an engine: {result.reason()}", file=sys.stderr)
    return 1


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``koenig-check`` console script.

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status.
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    args.debug = bool(getattr(args, "debug", False))
    try:
        return int(args.func(args))
    except KeyboardInterrupt:
        print("koenig-check: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into a command that stopped reading (e.g. head)
        sys.stderr.close()
        return 0
    except Exception as err:  # one line for users, the traceback on --debug
        if args.debug:
            raise
        from koenig_check.api import one_line

        print(f"koenig-check: error: {one_line(err)}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
