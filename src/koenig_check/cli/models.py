"""``koenig-check models``: every name ``compare`` accepts (and Menagerie's robots), loaded on demand."""

from __future__ import annotations

import argparse

from koenig_check.cli.parsing import add_command
from koenig_check.line_width import LINE_LIMIT


def add(sub: argparse._SubParsersAction) -> None:
    """Add the ``models`` sub-command.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    p = add_command(
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


def _cmd_models(args: argparse.Namespace) -> int:
    from koenig_check.sources.catalogue import DEFAULT_FORMAT
    from koenig_check.sources.model_names import model_names

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
            verdict = _loads_in_both(entry.name, LINE_LIMIT - width - 1)
            loaded_both += verdict == "yes"
            print(f"{'':{width}s} {verdict}")
    if args.check:
        print(f"\n{loaded_both} of {len(names)} load in both MuJoCo and Pinocchio (default load options).")
    return 0


def _loads_in_both(name: str, width: int = LINE_LIMIT) -> str:
    """``yes``, or ``no: <engine's reason in one short line>`` for one model name (default load options).

    The reason is :func:`~koenig_check.diagnosis.reason.short_error`'s, within ``width`` characters (the whole
    is ``koenig-check compare NAME``'s).
    """
    import warnings

    from koenig_check.diagnosis.reason import short_error
    from koenig_check.engines import load_model
    from koenig_check.sources.catalogue import resolve_model

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            load_model(name)
    except Exception as err:  # each model's reason, the list goes on
        path = resolve_model(name).path

        def shorter(text: str) -> str:  # the file is the row's
            return text.replace(f"{path}: ", "").replace(str(path), path.name)

        return "no: " + short_error(err, width - len("no: "), rename=shorter)
    return "yes"
