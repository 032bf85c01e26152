"""``koenig-check dynamics``: the mass matrix and inertia forces each formula implies, against the engines."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from koenig_check.cli.parsing import add_command, add_out, check_models, check_out, load_options_of, positive, tolerance


def add(sub: argparse._SubParsersAction) -> None:
    """The ``dynamics`` sub-command: M and Q* implied by each formula, against both engines."""
    from koenig_check.engines.load_options import add_load_arguments
    from koenig_check.formulas import FORMULAS
    from koenig_check.implied_dynamics.analysis import M_RTOL, Q_RTOL

    p = add_command(
        sub,
        "dynamics",
        "mass matrix and generalized inertia forces implied by each energy formula, against both engines",
        "koenig-check dynamics gimbal.xml --poses 10 --out dyn-report",
    )
    p.add_argument("model", metavar="MODEL", help="model file or name")
    add_load_arguments(p)
    p.add_argument("--poses", type=positive, default=5, help="random poses (default 5)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument(
        "--formulas", nargs="+", metavar="NAME", choices=list(FORMULAS), help="formulas (default: all; exact always)"
    )
    add_out(p, "write dynamics.md and dynamics.json into this directory")
    p.add_argument("--m-rtol", type=tolerance, default=M_RTOL, help=f"tolerance on M of exact (default {M_RTOL:g})")
    p.add_argument("--q-rtol", type=tolerance, default=Q_RTOL, help=f"tolerance on Q* of exact (default {Q_RTOL:g})")
    p.add_argument(
        "--rtol",
        type=tolerance,
        default=None,
        help="tolerance of the engines' readings of the model against each other (engine against engine, a "
        "route on one engine against the other), when larger than --m-rtol/--q-rtol: 1e-5 for a twin "
        "written at 6 significant digits, rounded by up to 5e-6 per number (default: --m-rtol/--q-rtol)",
    )
    p.set_defaults(func=_cmd_dynamics)


def _cmd_dynamics(args: argparse.Namespace) -> int:
    from koenig_check.implied_dynamics.analysis import dynamics
    from koenig_check.implied_dynamics.markdown import terminal_lines, write_dynamics

    check_out(args)
    load_options = load_options_of(args)
    check_models(args, [args.model, *([load_options.pinocchio_model] if load_options.pinocchio_model else [])])
    result = dynamics(
        args.model,
        n_poses=args.poses,
        seed=args.seed,
        formulas=args.formulas,
        m_rtol=args.m_rtol,
        q_rtol=args.q_rtol,
        rtol=args.rtol,
        load_options=load_options,
    )
    from koenig_check.line_width import LINE_LIMIT, fold_text
    from koenig_check.sources.shown_paths import as_given

    print(fold_text(as_given("\n".join(terminal_lines(result)), [args.model])))
    if args.out:
        from koenig_check.report.output_dir import clean_out_dir, file_listing, finish_out_dir

        clean_out_dir(args.out)
        written = finish_out_dir(args.out, write_dynamics(Path(args.out), result))
        print("\n" + file_listing(args.out, written))
    if result.ok:
        return 0
    whole = as_given(f"koenig-check: {result.reason(cli=True)}", [args.model])  # the reason says which check failed
    line = whole if len(whole) <= LINE_LIMIT else as_given(whole, [args.model], short=True)  # the file by its name
    if len(line) > LINE_LIMIT:  # one message: a first line naming the model and what failed, the rest indented
        from koenig_check.diagnosis.message import first_and_rest

        first, rest = first_and_rest(line, LINE_LIMIT)
        line = "\n".join([first, *rest])
    print(line, file=sys.stderr)
    return 1
