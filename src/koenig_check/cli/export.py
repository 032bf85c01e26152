"""``koenig-check export``: write a model for another engine or format and prove it is the same robot.

The command's arguments, its usage checks (exit status 2 before any work) and its printed result; the export
and the proof themselves are :mod:`koenig_check.export`'s.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from koenig_check.cli.parsing import add_command, load_options_of, positive, usage_error
from koenig_check.engines.load_options import LoadOptions, add_load_arguments

if TYPE_CHECKING:
    from koenig_check.export.carried import ExportRefusedError
    from koenig_check.export.result import Proof


def _rtol(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0 < value < 1:
        raise argparse.ArgumentTypeError(f"must be in (0, 1), got {text}")
    return value


def add(sub: argparse._SubParsersAction) -> None:
    """The ``export`` sub-command: write a model as URDF or portable MJCF and prove it is the same robot.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    p = add_command(
        sub,
        "export",
        "write a model as URDF or portable MJCF and prove, in every engine, that it is the same robot",
        "koenig-check export cartpole.xml --to urdf --out cartpole.urdf",
        "or check a conversion made by another tool:\n  koenig-check export --check-only robot.xml robot.urdf",
    )
    add_export_arguments(p)
    p.set_defaults(func=_cmd_export)


def add_export_arguments(p: argparse.ArgumentParser) -> None:
    """Put the export options on a parser.

    Parameters
    ----------
    p : argparse.ArgumentParser
    """
    from koenig_check.export.proof import PROOF_POSES, PROOF_RTOL

    p.add_argument("model", nargs="?", metavar="MODEL", help="model file or name to export")
    p.add_argument(
        "--to",
        choices=("urdf", "mjcf"),
        help="target format (mjcf of an MJCF: the portable form; its mesh geoms .obj only, as Drake reads, "
        "every mesh with --engines mujoco,pinocchio)",
    )
    p.add_argument("--out", metavar="FILE", help="file to write")
    p.add_argument(
        "--check-only",
        nargs=2,
        metavar=("ORIGINAL", "EXPORT"),
        help="write nothing: prove that EXPORT (made by any tool) is the same robot as ORIGINAL",
    )
    p.add_argument(
        "--drake-extensions", action="store_true", help="URDF: write armature as Drake's drake:rotor_inertia"
    )
    p.add_argument(
        "--poses", type=positive, default=PROOF_POSES, help=f"random poses of the proof (default {PROOF_POSES})"
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the proof's poses (default 0)")
    p.add_argument("--rtol", type=_rtol, default=PROOF_RTOL, help=f"relative tolerance (default {PROOF_RTOL:g})")
    add_load_arguments(p)


def _exists(name: str) -> bool:
    """A file, or a name ``koenig-check models`` accepts."""
    from koenig_check.sources.catalogue import resolve_model

    if Path(name).is_file():
        return True
    try:
        resolve_model(name)
    except Exception:
        return False
    return True


def _usage(args: argparse.Namespace) -> str:
    """The usage error of an export command line, or empty."""
    if args.check_only:
        extra = [f for f, v in (("MODEL", args.model), ("--to", args.to), ("--out", args.out)) if v]
        if extra:
            return f"--check-only takes ORIGINAL EXPORT and no {', '.join(extra)}"
        missing = [f for f in args.check_only if not _exists(f)]
        return f"--check-only: no such file or model name {missing[0]!r}" if missing else ""
    if not args.model:
        return "give MODEL (with --to and --out) or --check-only ORIGINAL EXPORT"
    if not args.to or not args.out:
        return "export needs --to {urdf,mjcf} and --out FILE"
    if args.pinocchio_model:
        return "--pinocchio-model does not apply to export (the export is loaded by every engine)"
    return ""


def print_proof(proof: Proof, shown: Callable[[str], str] = str) -> None:
    """Print the proof: per engine, the skipped engines, and the verdict last.

    Parameters
    ----------
    proof : Proof
    shown : callable, optional
        How a line names the files (default: as it is; the command line: as the user gave them).
    """
    for e in proof.engines:
        if e.compared:
            print(
                f"  {e.engine}: mass matrix {e.mass_matrix:.2g}, rigid energy {e.energy:.2g}, "
                f"inverse dynamics {e.inverse_dynamics:.2g} ({e.poses} poses)"
            )
    from koenig_check.line_width import fold_text

    for line in proof.skipped():
        print(fold_text(shown(f"  not compared: {line}")))
    for line in proof.notes():
        print(fold_text(shown(f"  note: {line}")))
    if proof.equivalent:
        print(proof.summary())
        return
    print("not equivalent:")  # each reason on its own line (the summary joins them in one)
    for line in proof.reasons():
        print(fold_text(shown(f"  - {line}")))


def refused_lines(err: ExportRefusedError, target: str, limit: int = 3) -> list[str]:
    """A refusal: one line naming each construct by at most ``limit`` elements, then each element with why.

    Parameters
    ----------
    err : ExportRefusedError
    target : str
        The format asked for (``urdf``, ``mjcf``).
    limit : int

    Returns
    -------
    list of str
        Every line within 200 characters (a construct's reason folded under it).
    """
    import re

    from koenig_check.exceptions import one_line
    from koenig_check.line_width import LINE_LIMIT, fold_text

    if not err.constructs:
        return fold_text(f"refused: {one_line(err)}").split("\n")
    groups: dict[str, list[str]] = {}
    for c in err.constructs:  # the element without its parenthesis (the list below has it whole)
        groups.setdefault(c.construct, []).append(re.sub(r" \([^)]*\)", "", c.element))
    head = ""
    for n in range(limit, 0, -1):
        named = [
            f"{what} ({', '.join(els[:n])}{f' and {len(els) - n} more' if len(els) > n else ''})"
            for what, els in groups.items()
        ]
        head = f"refused: {target.upper()} cannot hold {'; '.join(named)}"
        if len(head) <= LINE_LIMIT:
            break
    whole = len(head) <= LINE_LIMIT
    if not whole:  # never cut: the constructs counted, each element with why below
        kinds, elements = len(groups), len(err.constructs)
        head = f"refused: {target.upper()} cannot hold {kinds} kinds of construct ({elements} elements)"
    lines = [head]
    if len(err.constructs) > 1 or not whole or head.endswith(")"):
        lines += fold_text("\n".join(f"  - {c.message()}" for c in err.constructs)).split("\n")
    return lines


def _cmd_export(args: argparse.Namespace) -> int:
    return run_export(args, load_options_of(args))


def run_export(args: argparse.Namespace, options: LoadOptions) -> int:
    """Run ``koenig-check export``; return the exit status.

    Parameters
    ----------
    args : argparse.Namespace
    options : LoadOptions
        The command's load options.

    Returns
    -------
    int
        0 when the export is proved equivalent, 1 when it differs, is refused or fails to load; a usage error
        exits with status 2 before any work.
    """
    from koenig_check.arguments import ArgumentValueError
    from koenig_check.export.api import check_export_arguments, export_model
    from koenig_check.export.carried import ExportRefusedError
    from koenig_check.export.proof import prove
    from koenig_check.line_width import fold_text

    problem = _usage(args)
    if not problem and not args.check_only:
        try:
            check_export_arguments(args.model, args.to, args.out, args.poses, args.rtol)
        except ArgumentValueError as err:
            problem = str(err)
    if problem:
        usage_error(args, problem)
    engines = options.engines  # None: every engine
    if args.check_only:
        original, export = args.check_only
        proof = prove(original, export, options, poses=args.poses, seed=args.seed, rtol=args.rtol, engines=engines)
        print(fold_text(f"{export} against {original}:"))
        from koenig_check.sources.shown_paths import as_given

        print_proof(proof, lambda text: as_given(text, [original, export]))  # the files as the user named them
        return 0 if proof.equivalent else 1
    try:
        result = export_model(
            args.model,
            to=args.to,
            out=args.out,
            floating=options.floating,
            repair_inertia=options.repair_inertia,
            balance_inertia=options.balance_inertia,
            drake_extensions=args.drake_extensions,
            poses=args.poses,
            seed=args.seed,
            rtol=args.rtol,
            engines=engines,
        )
    except ExportRefusedError as err:
        print("\n".join(refused_lines(err, args.to)))
        return 1
    print(fold_text(f"wrote {result.path} ({result.target})"))
    if result.not_carried:
        print("not carried:")
        for n in result.not_carried:
            print(fold_text(f"  - {n.message()}"))
    if result.floating_base:
        print(fold_text(f"load {result.path} with a floating base (--floating): the original's root joint is free"))
    print_proof(result.proof)
    return 0 if result.equivalent else 1
