"""What every command shares: the parser whose errors are one line with exit status 2, argument types, options."""

from __future__ import annotations

import argparse
import difflib
import re
import sys
from dataclasses import replace
from typing import Any, NoReturn

from koenig_check.arguments import ArgumentTypeError, ArgumentValueError
from koenig_check.engines.load_options import ALLOW_COUPLED_DEPRECATION, LoadOptions
from koenig_check.sources.errors import ModelSourceError

#: The report directory of ``demo`` when none is given.
DEFAULT_OUT = "koenig-check-report"
#: Errors of the API's argument checks that the command line reports as usage errors (exit 2).
USAGE_ERRORS = (ArgumentValueError, ArgumentTypeError, ModelSourceError)


class Parser(argparse.ArgumentParser):
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

    def parse_args(self, args=None, namespace=None):  # type: ignore[no-untyped-def, override]
        """Parse like argparse; an unknown option is reported by its sub-command with the closest option."""
        parsed, extras = self.parse_known_args(args, namespace)
        if extras:
            parser = getattr(parsed, "parser", None)
            (parser if isinstance(parser, Parser) else self).error(unrecognized(parser or self, extras))
        return parsed

    def error(self, message: str) -> None:  # type: ignore[override]
        """Exit with status 2: the short usage line, then the error in one line."""
        from koenig_check.line_width import LINE_LIMIT, elided_paths

        line = f"{self.prog}: error: {closest_choice(message)}"
        see = "" if f"{self.prog} --help" in message else f" (see {self.prog} --help)"  # said once
        if len(line + see) > LINE_LIMIT:  # one line: the help's pointer goes, then a long path's folders
            line, see = elided_paths(line), ""
        self.exit(2, f"{self.short_usage()}\n{line}{see}\n")


#: argparse's message for a value outside an argument's choices (a misspelt command).
_INVALID_CHOICE = re.compile(r"invalid choice: '([^']*)' \(choose from (.*)\)")


def closest_choice(message: str) -> str:
    """The message of argparse for a value outside the choices, with the closest (``did you mean 'compare'?``).

    Parameters
    ----------
    message : str
        argparse's error message; any other message is returned as it is.

    Returns
    -------
    str
    """
    found = _INVALID_CHOICE.search(message)
    if not found:
        return message
    choices = re.findall(r"'([^']*)'", found.group(2))
    close = difflib.get_close_matches(found.group(1), choices, n=1, cutoff=0.6)
    if not close:
        return message
    return f"{message[: found.end(1) + 1]}; did you mean {close[0]!r}? {message[found.end(1) + 2 :]}"


def unrecognized(parser: argparse.ArgumentParser, extras: list[str]) -> str:
    """The message for arguments a parser does not know, with the closest option to a misspelt one.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The (sub-command's) parser that did not know them.
    extras : list of str

    Returns
    -------
    str
        E.g. ``unrecognized argument --floting; did you mean --floating?``.
    """
    words = " ".join(extras)
    message = f"unrecognized argument{'s' if len(extras) > 1 else ''} {words}"
    options = [o for o in parser._option_string_actions if o.startswith("--")]
    for word in extras:
        if word.startswith("-"):
            typed = word.split("=", 1)[0]
            meant = SYNONYMS.get(typed)
            close = [meant] if meant in options else difflib.get_close_matches(typed, options, n=1, cutoff=0.6)
            if close:
                return f"{message}; did you mean {close[0]}?"
    return message


#: Options other tools spell another way, and the option meant (the closest by spelling would mislead:
#: ``--report`` is nearest ``--records``, which chooses what the records hold).
SYNONYMS = {"--report": "--out", "--report-dir": "--out", "--output": "--out", "--output-dir": "--out"}


def usage_error(args: argparse.Namespace, message: str) -> NoReturn:
    """Exit with status 2, the command's usage and a one-line message (before any work)."""
    parser: argparse.ArgumentParser | None = getattr(args, "parser", None)
    if parser is None:
        print(f"koenig-check: error: {message}", file=sys.stderr)
        raise SystemExit(2)
    parser.error(message)


def check_models(args: argparse.Namespace, models: list[Any]) -> None:
    """Refuse a model name that is neither a file nor a known model, before any work (exit status 2)."""
    from koenig_check.sources.known_names import check_model_names

    try:
        check_model_names(models)
    except ModelSourceError as err:
        usage_error(args, str(err))


def check_out(args: argparse.Namespace) -> None:
    """Refuse an unusable ``--out`` before any work."""
    from koenig_check.arguments import ArgumentValueError
    from koenig_check.report.output_dir import check_out_dir

    if getattr(args, "out", None):
        try:
            check_out_dir(args.out, overwrite=args.overwrite)
        except ArgumentValueError as err:
            usage_error(args, str(err))


def tolerance(text: str) -> float:
    """A relative tolerance: a finite number > 0."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (value > 0 and value < float("inf")):
        raise argparse.ArgumentTypeError(f"tolerance must be a finite number > 0, got {text}")
    return value


def positive(text: str) -> int:
    """A whole number >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be >= 1, got {text}")
    return value


def formatter(prog: str) -> argparse.HelpFormatter:
    """The help formatter of every command: epilogs kept as written (examples, formula lists), lines within 200."""
    import shutil

    from koenig_check.line_width import LINE_LIMIT

    width = min(shutil.get_terminal_size().columns - 2, LINE_LIMIT)
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=32, width=width)


def add_command(
    sub: argparse._SubParsersAction, name: str, help_: str, example: str, epilog: str = ""
) -> argparse.ArgumentParser:
    """Add a sub-command with its help, an example in its epilog and ``--debug``.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    name, help_, example : str
    epilog : str
        Shown before the example.

    Returns
    -------
    argparse.ArgumentParser
    """
    text = f"{epilog}\n\nexample:\n  {example}" if epilog else f"example:\n  {example}"
    p = sub.add_parser(name, help=help_, description=help_, epilog=text, formatter_class=formatter)
    p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="show Python tracebacks on errors")
    p.set_defaults(parser=p)
    return p


def add_out(p: argparse.ArgumentParser, help_: str, default: str | None = None) -> None:
    """Add ``--out DIR`` and ``--overwrite`` to a sub-command.

    Parameters
    ----------
    p : argparse.ArgumentParser
    help_ : str
    default : str, optional
    """
    p.add_argument("--out", default=default, help=help_)
    p.add_argument(
        "--overwrite",
        action="store_true",
        help="write into an --out directory holding files koenig-check did not write (they are left in place); "
        "koenig-check's own earlier files are always replaced",
    )


def load_options_of(args: argparse.Namespace) -> LoadOptions:
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
