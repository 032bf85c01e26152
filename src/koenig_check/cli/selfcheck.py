"""``koenig-check selfcheck``: every formula on analytic cases, no engine."""

from __future__ import annotations

import argparse

from koenig_check.cli.parsing import add_command, tolerance


def add(sub: argparse._SubParsersAction) -> None:
    """Add the ``selfcheck`` sub-command.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    p = add_command(
        sub,
        "selfcheck",
        "run every formula on analytic cases and print how far each is from the exact energy",
        "koenig-check selfcheck --rtol 1e-12",
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the random cases (default 0)")
    p.add_argument("--rtol", type=tolerance, default=1e-9, help="agreement tolerance (default 1e-9)")
    p.set_defaults(func=_cmd_selfcheck)


def _cmd_selfcheck(args: argparse.Namespace) -> int:
    from koenig_check.formulas.selfcheck import format_table, run_selfcheck

    print(format_table(run_selfcheck(seed=args.seed), rtol=args.rtol))
    return 0
