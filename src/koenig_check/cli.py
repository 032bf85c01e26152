"""The ``koenig-check`` command line."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from koenig_check import __version__


def _cmd_selfcheck(args: argparse.Namespace) -> int:
    from koenig_check.selfcheck import format_table, run_selfcheck

    print(format_table(run_selfcheck(seed=args.seed), rtol=args.rtol))
    return 0


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser with one sub-command per job.

    Returns
    -------
    argparse.ArgumentParser
    """
    parser = argparse.ArgumentParser(
        prog="koenig-check",
        description="Cross-check rigid-body kinetic energy: MuJoCo, Pinocchio and the formulas of "
        "Alyushin's correction of Koenig's formula.",
    )
    parser.add_argument("--version", action="version", version=f"koenig-check {__version__}")
    parser.add_argument("--debug", action="store_true", help="show Python tracebacks on errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    p = sub.add_parser(
        "selfcheck",
        help="run every formula on analytic cases and print how far each is from the exact energy",
        description="Run every formula on analytic cases (box, cylinder, one-axis and two-axis rotations, "
        "random bodies) and print a table of relative errors against the exact energy.",
        epilog="example: koenig-check selfcheck --rtol 1e-12",
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")
    p.add_argument("--rtol", type=float, default=1e-9, help="agreement tolerance (default 1e-9)")
    p.set_defaults(func=_cmd_selfcheck)
    return parser


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
    try:
        return int(args.func(args))
    except Exception as err:  # one line for users, the traceback on --debug
        if args.debug:
            raise
        print(f"koenig-check: error: {err}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
