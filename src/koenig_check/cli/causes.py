"""``koenig-check causes``: every known parser difference, from the catalogue (:mod:`koenig_check.causes`)."""

from __future__ import annotations

import argparse
import json

from koenig_check.cli.parsing import add_command


def add(sub: argparse._SubParsersAction) -> None:
    """Add the ``causes`` sub-command.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    from koenig_check.causes import FORMATS
    from koenig_check.engines.specs import names

    p = add_command(
        sub,
        "causes",
        "list every known parser difference: id, construct, each engine's reading, fixture and hint",
        "koenig-check causes --engine pinocchio --format mjcf",
    )
    p.add_argument("--engine", choices=names(), help="only the causes this engine takes part in")
    p.add_argument("--format", dest="fmt", choices=FORMATS, help="only the causes of this file format")
    p.add_argument("--json", action="store_true", help="print a JSON array of the declarations")
    p.set_defaults(func=_cmd_causes)


def _cmd_causes(args: argparse.Namespace) -> int:
    from koenig_check.causes import select, table

    causes = select(args.engine, args.fmt)
    if args.json:
        print(json.dumps([c.as_dict() for c in causes], indent=2, ensure_ascii=False))
    else:
        print(table(causes))
    return 0
