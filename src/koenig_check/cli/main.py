"""The ``koenig-check`` command line: the parser with one sub-command per job, and the entry point.

Exit status: 0 when the engines agree with each other and with ``exact`` within tolerance on every model,
1 with a one-line reason otherwise (a model that fails to load counts), 2 for a usage error.  Disagreements
of the paper's formulas are findings reported in the tables, not failures.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from koenig_check import __version__
from koenig_check.cli import causes, compare, dynamics, export, models, parity, selfcheck
from koenig_check.cli.parsing import USAGE_ERRORS, Parser, formatter, usage_error

#: The sub-commands, in the order ``--help`` lists them (each module adds its own).
COMMANDS = (compare, parity, models, causes, selfcheck, dynamics, export)


def build_parser() -> argparse.ArgumentParser:
    """Build the argument parser with one sub-command per job.

    Returns
    -------
    argparse.ArgumentParser
    """
    parser = Parser(
        prog="koenig-check",
        description="Cross-check rigid-body kinetic energy: MuJoCo, Pinocchio and the formulas of "
        "Alyushin's correction of Koenig's formula.",
        epilog="example:\n  koenig-check demo",
        formatter_class=formatter,
    )
    parser.add_argument("--version", action="version", version=f"koenig-check {__version__}")
    parser.add_argument("--debug", action="store_true", help="show Python tracebacks on errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for command in COMMANDS:
        command.add(sub)
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
    except USAGE_ERRORS as err:  # raised by the API's argument checks: a usage error
        usage_error(args, str(err))
    except BrokenPipeError:  # output piped into a command that stopped reading (e.g. head)
        sys.stderr.close()
        return 0
    except Exception as err:  # one message for users (a line, then the whole indented), the traceback on --debug
        if args.debug:
            raise
        from koenig_check.cli.error_line import error_line, error_lines

        line = error_line(args, err)
        print("\n".join([line, *error_lines(args, err, line)]), file=sys.stderr)
        return 1
