"""The command-line reference page (koenig_check.cli.reference) is generated from whatever parser it is given."""

from __future__ import annotations

import argparse

from koenig_check.cli.main import build_parser
from koenig_check.cli.reference import markdown


def _toy() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="toy", description="A toy.")
    parser.add_argument("--verbose", action="store_true", help="say more")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    run = sub.add_parser("run", help="run it", description="Run the toy.")
    run.add_argument("model", metavar="MODEL", help="a file | a name")
    run.add_argument("--poses", type=int, default=20, help="how many (default %(default)s)")
    run.add_argument("--kind", choices=["random", "grid"], default="random", help="pose kind")
    run.add_argument("--hidden", help=argparse.SUPPRESS)
    return parser


def test_every_command_option_default_and_choice_is_on_the_page() -> None:
    page = markdown(_toy())
    assert "## run" in page and "| [`run`](#run) | run it |" in page
    assert "| `--poses POSES` | how many (default 20) |  | `20` |" in page  # %(default)s expanded
    assert "`random`, `grid`" in page
    assert "a file \\| a name" in page  # a pipe cannot split the table's cell
    assert "--verbose" in page and "--hidden" not in page  # as --help shows them


def test_a_new_option_changes_the_page() -> None:
    parser = build_parser()
    before = markdown(parser)
    compare = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices["compare"]
    compare.add_argument("--frobnicate", action="store_true", help="a new option")
    after = markdown(parser)
    assert "--frobnicate" not in before and "| `--frobnicate` | a new option |" in after
    assert markdown() == before  # the default is the tool's own parser, built anew
