"""``koenig-check export``: write a model for another engine or format and prove it is the same robot."""

from __future__ import annotations

import argparse

from koenig_check.cli.parsing import add_command, load_options_of, usage_error


def add(sub: argparse._SubParsersAction) -> None:
    """The ``export`` sub-command: write a model as URDF or portable MJCF and prove it is the same robot."""
    from koenig_check.export.cli_export import add_export_arguments, run_export

    p = add_command(
        sub,
        "export",
        "write a model as URDF or portable MJCF and prove, in every engine, that it is the same robot",
        "koenig-check export cartpole.xml --to urdf --out cartpole.urdf",
        "or check a conversion made by another tool:\n  koenig-check export --check-only robot.xml robot.urdf",
    )
    add_export_arguments(p)
    p.set_defaults(func=_cmd_export, export_runner=run_export)


def _cmd_export(args: argparse.Namespace) -> int:
    return int(args.export_runner(args, load_options_of(args), usage_error))
