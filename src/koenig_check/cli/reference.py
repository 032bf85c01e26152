"""The command-line reference page, generated from the argument parser (``docs`` builds it; never copied by hand).

Every sub-command and every option the parser holds is on the page: its flags or metavar, its help text with
argparse's ``%(default)s`` expanded, its choices and its default.  ``python -m koenig_check.cli.reference``
prints the page; the documentation build (``mkdocs_hooks.py``) writes it into the site.
"""

from __future__ import annotations

import argparse
import html
from collections.abc import Iterator

#: The page's title and the sentence that says where it comes from.
TITLE = "# Command-line reference"
ORIGIN = (
    "<!-- generated from koenig_check.cli.main.build_parser() by koenig_check.cli.reference; do not edit -->\n\n"
    "Every sub-command of `koenig-check` and every option, as the argument parser defines them (the same text "
    "as `koenig-check COMMAND --help`)."
)


def _cell(text: str) -> str:
    """Text for a Markdown table cell: HTML special characters escaped, pipes and newlines kept out."""
    return html.escape(" ".join(text.split()), quote=False).replace("|", "\\|")


def _help(parser: argparse.ArgumentParser, action: argparse.Action) -> str:
    """The action's help text as ``--help`` prints it (``%(default)s`` and the like expanded)."""
    if not action.help or action.help == argparse.SUPPRESS:
        return ""
    return parser._get_formatter()._expand_help(action)


def _name(action: argparse.Action) -> str:
    """How the argument is written: its flags with their metavar, or a positional's metavar."""
    metavar = action.metavar if isinstance(action.metavar, str) else None
    if not action.option_strings:
        return metavar or action.dest
    takes_value = action.nargs != 0
    shown = metavar or action.dest.upper()
    return ", ".join(f"{flag} {shown}" if takes_value else flag for flag in action.option_strings)


def _default(action: argparse.Action) -> str:
    """The default as a cell, or empty when there is none worth naming."""
    if action.nargs == 0 or action.default in (None, argparse.SUPPRESS, False):
        return ""
    return f"`{action.default}`"


def _table(parser: argparse.ArgumentParser) -> list[str]:
    """One row per argument of ``parser`` (sub-command choices excepted)."""
    rows = ["| argument | what it does | choices | default |", "| --- | --- | --- | --- |"]
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) or action.help == argparse.SUPPRESS:
            continue
        choices = ", ".join(f"`{c}`" for c in action.choices) if action.choices else ""
        cells = (f"`{_cell(_name(action))}`", _cell(_help(parser, action)), _cell(choices), _cell(_default(action)))
        rows.append("| " + " | ".join(cells) + " |")
    return rows


def _commands(parser: argparse.ArgumentParser) -> Iterator[tuple[str, str, argparse.ArgumentParser]]:
    """Each sub-command: its name, its one-line help and its parser, in the order ``--help`` lists them."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {a.dest: a.help or "" for a in action._choices_actions}
            for name, sub in action.choices.items():
                yield name, helps.get(name, ""), sub


def _usage(parser: argparse.ArgumentParser) -> str:
    return "```text\n" + parser.format_usage().strip() + "\n```"


def markdown(parser: argparse.ArgumentParser | None = None) -> str:
    """The reference page of a parser (by default ``koenig-check``'s own) in Markdown.

    Parameters
    ----------
    parser : argparse.ArgumentParser, optional
        The parser to document (default: :func:`koenig_check.cli.main.build_parser`).

    Returns
    -------
    str
    """
    if parser is None:
        from koenig_check.cli.main import build_parser

        parser = build_parser()
    commands = list(_commands(parser))
    out = [TITLE, "", ORIGIN, "", _usage(parser), "", _cell(parser.description or ""), ""]
    out += ["| command | what it does |", "| --- | --- |"]
    out += [f"| [`{name}`](#{name}) | {_cell(text)} |" for name, text, _ in commands]
    out += ["", "Options of every command:", "", *_table(parser), ""]
    for name, _, sub in commands:
        out += [f"## {name}", "", _usage(sub), "", _cell(sub.description or ""), "", *_table(sub), ""]
        if sub.epilog:
            out += ["```text", sub.epilog.strip("\n"), "```", ""]
    return "\n".join(out)


if __name__ == "__main__":
    print(markdown(), end="")
