"""The ``koenig-check`` command line.

Exit status: 0 when both engines agree with each other and with ``exact`` within
tolerance on every model, 1 with a one-line reason otherwise (a model that fails to
load counts), 2 for a usage error.  Disagreements of the paper's formulas are findings
reported in the tables, not failures.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any, NoReturn

from koenig_check import __version__
from koenig_check.arguments import ArgumentTypeError, ArgumentValueError
from koenig_check.engines.load_options import ALLOW_COUPLED_DEPRECATION, LoadOptions, add_load_arguments
from koenig_check.sources.errors import ModelSourceError

DEFAULT_OUT = "koenig-check-report"
KoenigCheckUsageErrors = (ArgumentValueError, ArgumentTypeError, ModelSourceError)


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors are one line and exit with status 2."""

    def short_usage(self) -> str:
        """One line: the command, ``[options]`` and its positional arguments."""
        positionals = [a.metavar or a.dest for a in self._actions if not a.option_strings and a.nargs != 0]
        shown = [
            f"{m} [{m} ...]" if a.nargs == "+" else str(m)
            for a, m in zip(
                [a for a in self._actions if not a.option_strings and a.nargs != 0], positionals, strict=True
            )
        ]
        return " ".join(["usage:", self.prog, "[options]", *shown])

    def error(self, message: str) -> None:  # type: ignore[override]
        """Exit with status 2: the short usage line, then the error in one line."""
        self.exit(2, f"{self.short_usage()}\n{self.prog}: error: {message} (see {self.prog} --help)\n")


def _usage_error(args: argparse.Namespace, message: str) -> NoReturn:
    """Exit with status 2, the command's usage and a one-line message (before any work)."""
    parser: argparse.ArgumentParser | None = getattr(args, "parser", None)
    if parser is None:
        print(f"koenig-check: error: {message}", file=sys.stderr)
        raise SystemExit(2)
    parser.error(message)


def _check_out(args: argparse.Namespace) -> None:
    """Refuse an unusable ``--out`` before any work."""
    from koenig_check.arguments import ArgumentValueError
    from koenig_check.report.output_dir import check_out_dir

    if getattr(args, "out", None):
        try:
            check_out_dir(args.out, overwrite=args.overwrite)
        except ArgumentValueError as err:
            _usage_error(args, str(err))


def _formulas_epilog() -> str:
    from koenig_check.arguments import POSE_KIND_HELP
    from koenig_check.formulas import FORMULAS

    lines = ["formulas (--formulas NAME ...; the paper's equation numbers in brackets):"]
    lines += [f"  {name:30s} {f.equations}" for name, f in FORMULAS.items()]
    lines.append("pose kinds (--pose-kind):")
    lines += [f"  {kind:11s} {text}" for kind, text in POSE_KIND_HELP.items()]
    return "\n".join(lines)


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


def _add(
    sub: argparse._SubParsersAction, name: str, help_: str, example: str, epilog: str = ""
) -> argparse.ArgumentParser:
    text = f"{epilog}\n\nexample:\n  {example}" if epilog else f"example:\n  {example}"
    p = sub.add_parser(name, help=help_, description=help_, epilog=text, formatter_class=_formatter)
    p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="show Python tracebacks on errors")
    p.set_defaults(parser=p)
    return p


def _add_out(p: argparse.ArgumentParser, help_: str, default: str | None = None) -> None:
    p.add_argument("--out", default=default, help=help_)
    p.add_argument(
        "--overwrite",
        action="store_true",
        help="write into an --out directory holding files koenig-check did not write (they are left in place); "
        "koenig-check's own earlier files are always replaced",
    )


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser with one sub-command per job.

    Returns
    -------
    argparse.ArgumentParser
    """
    from koenig_check.run.chunks import RECORD_MODES
    from koenig_check.run.stats import DEFAULT_RTOL

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
    _add_out(p, f"report directory (default {DEFAULT_OUT})", DEFAULT_OUT)
    p.add_argument("--poses", type=_positive, default=20, help="random poses per model (default 20)")
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
        _formulas_epilog(),
    )
    p.add_argument("models", nargs="+", metavar="MODEL", help="model file or name")
    p.add_argument("--poses", type=_positive, default=20, help="number of poses / grid samples per joint (default 20)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument("--formulas", nargs="+", metavar="NAME", help="formulas to evaluate (default: all; names below)")
    _add_out(p, "write a report directory here")
    p.add_argument(
        "--rtol", type=_tolerance, default=DEFAULT_RTOL, help=f"agreement tolerance (default {DEFAULT_RTOL:g})"
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

    p = _add(
        sub,
        "models",
        "list every model name and alias compare accepts, with its format and source",
        "koenig-check models --check",
    )
    p.add_argument("--check", action="store_true", help="load each model in both engines and say why not (slow)")
    p.add_argument("--paths", action="store_true", help="show each model's file")
    p.add_argument(
        "--menagerie",
        action="store_true",
        help="list MuJoCo Menagerie's robots instead (menagerie:NAME; extra [menagerie])",
    )
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
    _add_export_command(sub)
    return parser


# ----------------------------------------------------------------------------- commands
def _cmd_selfcheck(args: argparse.Namespace) -> int:
    from koenig_check.selfcheck import format_table, run_selfcheck

    print(format_table(run_selfcheck(seed=args.seed), rtol=args.rtol))
    return 0


def _cmd_models(args: argparse.Namespace) -> int:
    from koenig_check.engines.sources import DEFAULT_FORMAT, model_names

    if args.menagerie:
        from koenig_check.sources.listing import menagerie_lines

        print("\n".join(menagerie_lines(paths=args.paths)))
        return 0
    names = model_names()
    print(f"{len(names)} models. Type the NAME or any ALIAS, or a file path. A project model in both formats")
    print(f"is name.xml or name.urdf; its bare name means the {DEFAULT_FORMAT.upper()} file.")
    width = max(len(e.name) for e in names)
    header = f"{'NAME':{width}s} {'FORM':4s} {'SOURCE':18s} ALIASES"
    print(header if not args.check else f"{header}\n{'':{width}s} LOADS IN BOTH ENGINES?")
    loaded_both = 0
    for entry in names:
        prefix = f"{entry.name:{width}s} {entry.format:4s} {entry.source:18s} "
        rows, row = [], ""
        for alias in entry.aliases:  # aliases wrapped under their column, within 100 columns
            if row and len(prefix) + len(row) + len(alias) + 2 > 100:
                rows.append(row + ",")
                row = ""
            row = f"{row}, {alias}" if row else alias
        for k, text in enumerate([*rows, row]):
            print(((prefix if k == 0 else " " * len(prefix)) + text).rstrip())
        if args.paths:
            print(f"{'':{width}s} {entry.path}")
        if args.check:
            verdict = _loads_in_both(entry.name)
            loaded_both += verdict == "yes"
            print(f"{'':{width}s} {verdict}")
    if args.check:
        print(f"\n{loaded_both} of {len(names)} load in both MuJoCo and Pinocchio (default load options).")
    return 0


def _loads_in_both(name: str) -> str:
    """``yes``, or ``no: <engine's one-line reason>`` for one model name (default load options)."""
    import warnings

    from koenig_check.api import one_line
    from koenig_check.engines import load_model
    from koenig_check.engines.sources import resolve_model

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            load_model(name)
    except Exception as err:  # each model's reason, the list goes on
        text = one_line(err).replace(f"{resolve_model(name).path}: ", "")  # the file is the row's
        return f"no: {text}"
    return "yes"


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
    print(f"koenig-check: engines disagree or a model failed: {check.reason()}", file=sys.stderr)
    return 1


def _check_compare_usage(args: argparse.Namespace) -> None:
    """Every usage error of ``compare`` / ``demo``, before any model is loaded or any file written."""
    from koenig_check.arguments import ArgumentTypeError, ArgumentValueError, check_formulas

    try:
        check_formulas(getattr(args, "formulas", None))
    except (ArgumentValueError, ArgumentTypeError) as err:
        _usage_error(args, str(err))
    if getattr(args, "pose_kind", None) == "grid" and not args.grid_joints and not args.pose_file:
        _usage_error(args, "--pose-kind grid needs --grid-joints A B (the names of two joints)")
    if getattr(args, "grid_joints", None) and args.pose_kind != "grid":
        _usage_error(args, "--grid-joints is only used with --pose-kind grid")
    for name in ("duration", "velocity_scale"):
        value = getattr(args, name, None)
        if value is not None and not (0 < value < float("inf")):
            _usage_error(args, f"--{name.replace('_', '-')} must be a finite number > 0, got {value}")
    if getattr(args, "seed", 0) < 0:
        _usage_error(args, f"--seed must be >= 0, got {args.seed}")
    _check_out(args)


def _load_options(args: argparse.Namespace) -> LoadOptions:
    """The load options of a command; ``--allow-coupled`` is accepted with a note and ignored."""
    from koenig_check.engines.errors import EngineUnavailableError
    from koenig_check.engines.registry import check_engines

    options = LoadOptions.from_namespace(args)
    try:
        check_engines(options.engines)
    except EngineUnavailableError as err:  # a usage error: refused before any work
        print(f"koenig-check: error: {err}", file=sys.stderr)
        raise SystemExit(2) from None
    if options.allow_coupled:
        print(f"koenig-check: note: {ALLOW_COUPLED_DEPRECATION}", file=sys.stderr)
        options = replace(options, allow_coupled=False)
    return options


def _cmd_compare(args: argparse.Namespace) -> int:
    from koenig_check.api import compare
    from koenig_check.report.progress import Progress

    _check_compare_usage(args)
    load_options = _load_options(args)
    from koenig_check.sources.external import prepare

    prepare([*args.models, *([load_options.pinocchio_model] if load_options.pinocchio_model else [])])
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
    with Progress(len(args.models), "models") as bar, _aborted_on_error(sink):
        check = compare(
            args.models,
            rtol=args.rtol,
            progress=bar.step,
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
    check, figures = run_demo(n_poses=args.poses, seed=args.seed, rtol=args.rtol)
    clean_out_dir(args.out)
    return _finish(check, args.out, figures)


def _cmd_parity(args: argparse.Namespace) -> int:
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.diagnosis.import_parity import format_parity
    from koenig_check.diagnosis.policy import asked_for
    from koenig_check.diagnosis.reason import lead_line
    from koenig_check.engines import load_model
    from koenig_check.findings import Kind

    options = _load_options(args)
    model = load_model(args.model, options)
    for name in asked_for(options.engines):
        model.attach(name)
    diagnosis = diagnose(model)
    report = diagnosis.parity
    assert report is not None
    for f in diagnosis.findings:
        if f.kind is Kind.VERDICT:
            print(f"three engines: {f.message()}")
        elif f in diagnosis.optional_findings:
            print(f.message())
    print(format_parity(report))
    lead = lead_line(diagnosis.findings)
    if report.clean and not lead:
        return 0
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
    _add_out(p, "write dynamics.md and dynamics.json into this directory")
    p.add_argument("--m-rtol", type=_tolerance, default=M_RTOL, help=f"tolerance on M of exact (default {M_RTOL:g})")
    p.add_argument("--q-rtol", type=_tolerance, default=Q_RTOL, help=f"tolerance on Q* of exact (default {Q_RTOL:g})")
    p.set_defaults(func=_cmd_dynamics)


def _cmd_dynamics(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from koenig_check.engines.load_options import LoadOptions
    from koenig_check.implied_dynamics.analysis import dynamics
    from koenig_check.implied_dynamics.markdown import terminal_lines, write_dynamics

    _check_out(args)
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
        from koenig_check.report.output_dir import clean_out_dir, file_listing, finish_out_dir

        clean_out_dir(args.out)
        written = finish_out_dir(args.out, write_dynamics(Path(args.out), result))
        print("\n" + file_listing(args.out, written))
    if result.ok:
        return 0
    print(f"koenig-check: exact disagrees with an engine: {result.reason()}", file=sys.stderr)
    return 1


def _add_export_command(sub: argparse._SubParsersAction) -> None:
    """The ``export`` sub-command: write a model as URDF or portable MJCF and prove it is the same robot."""
    from koenig_check.export.cli_export import add_export_arguments, run_export

    p = _add(
        sub,
        "export",
        "write a model as URDF or portable MJCF and prove, in every engine, that it is the same robot",
        "koenig-check export cartpole.xml --to urdf --out cartpole.urdf",
        "or check a conversion made by another tool:\n  koenig-check export --check-only robot.xml robot.urdf",
    )
    add_export_arguments(p)
    p.set_defaults(func=_cmd_export, export_runner=run_export)


def _cmd_export(args: argparse.Namespace) -> int:
    return int(args.export_runner(args, _load_options(args), _usage_error))


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
    from koenig_check.noise import route_mujoco_warnings

    route_mujoco_warnings()  # no MUJOCO_LOG.TXT in the user's directory; load warnings are findings already
    if args.debug:
        import logging

        logging.basicConfig(level=logging.INFO, format="koenig-check: %(name)s: %(message)s")
    try:
        return int(args.func(args))
    except KeyboardInterrupt:
        print("koenig-check: interrupted", file=sys.stderr)
        return 130
    except KoenigCheckUsageErrors as err:  # raised by the API's argument checks: a usage error
        _usage_error(args, str(err))
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
