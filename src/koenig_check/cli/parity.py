"""``koenig-check parity``: import parity only, with the diagnosis's root causes and three-engine verdicts.

With three engines, the verdicts compare the engines' energies on seeded random states (``--poses``, ``--seed``:
the first states of the sequence ``compare`` draws with the same options, so both commands reach the same
verdict on the same file and engines) as well as each segment's mass, COM and inertia at ``qpos0``: a joint
anchor, an axis or an armature only the motion shows is not missed.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from koenig_check.cli.parsing import add_command, check_models, load_options_of, positive, tolerance, usage_error
from koenig_check.engines.load_options import add_load_arguments
from koenig_check.exceptions import JointMismatch

#: Random states on which a third engine's energies are compared by default (``compare``'s default poses; not
#: :data:`koenig_check.run.engine_runs.VERDICT_POSES`, the most of a run's poses ``compare`` gives the verdicts).
DEFAULT_POSES = 20


def add(sub: argparse._SubParsersAction) -> None:
    """Add the ``parity`` sub-command.

    Parameters
    ----------
    sub : argparse._SubParsersAction
    """
    p = add_command(
        sub,
        "parity",
        "import parity only: do MuJoCo and Pinocchio see the same robot in the same file?",
        "koenig-check parity serial7.urdf",
    )
    from koenig_check.diagnosis.import_parity import PARITY_RTOL

    p.add_argument("model", metavar="MODEL", help="model file or name")
    p.add_argument(
        "--rtol",
        type=tolerance,
        default=PARITY_RTOL,
        help=f"relative tolerance of the import parity (lengths by the model's size, inertias by the largest "
        f"principal moment; default {PARITY_RTOL:g}): 1e-5 for a twin written at 6 significant digits, "
        "rounded by up to 5e-6 per number",
    )
    p.add_argument(
        "--poses",
        type=positive,
        default=DEFAULT_POSES,
        help=f"random states on which the engines' energies are compared for the three-engine verdicts "
        f"(default {DEFAULT_POSES}, the first states `compare` draws with the same --seed)",
    )
    p.add_argument("--seed", type=int, default=0, help="seed of those states (default 0)")
    add_load_arguments(p)
    p.set_defaults(func=_cmd_parity)


def parity_diagnosis(model: Any, rtol: float, poses: int = DEFAULT_POSES, seed: int = 0) -> Any:
    """What ``parity`` prints: import parity, and the three engines' verdicts on energies and mass properties.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel
        The engines the user named attached already.
    rtol : float
    poses : int
        Seeded random states (:func:`koenig_check.engines.sampling.random_states`) on which the engines' rigid-body
        and armature energies are compared, as ``compare`` compares them on its first poses.
    seed : int

    Returns
    -------
    koenig_check.diagnosis.diagnose.Diagnosis
    """
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.engines.sampling import random_states

    qpos, qvel = random_states(model.mujoco.model, poses, seed)
    return diagnose(model, rtol=rtol, qpos=qpos, qvel=qvel)


def _cmd_parity(args: argparse.Namespace) -> int:
    from koenig_check.diagnosis.model_reason import short_reason
    from koenig_check.diagnosis.policy import attach_engines
    from koenig_check.diagnosis.reason import REASON_WIDTH, ROUNDING_LEVEL, as_note, lead_line, rounding_hint
    from koenig_check.engines import load_model
    from koenig_check.findings import Kind
    from koenig_check.gravity.words import reason_words, verdict_line
    from koenig_check.line_width import closed_cut
    from koenig_check.report.parity_table import format_parity
    from koenig_check.run.labels import unique_labels

    if args.seed < 0:
        usage_error(args, f"--seed must be >= 0, got {args.seed}")
    options = load_options_of(args)
    check_models(args, [args.model, *([options.pinocchio_model] if options.pinocchio_model else [])])
    try:
        model = load_model(args.model, options)
    except JointMismatch as err:
        if not any(c.root_cause and c.affects_energy for c in err.causes):
            raise  # no construct of the file explains it: an error
        return _unpaired_report(args, err)  # a parser that ignores a construct: a disagreement with its root cause
    attach_engines(model)  # the engines the user named
    diagnosis = parity_diagnosis(model, args.rtol, args.poses, args.seed)
    report = diagnosis.parity
    assert report is not None
    from koenig_check.engines.registry import label as engine_label
    from koenig_check.engines.registry import optional
    from koenig_check.line_width import fold_text
    from koenig_check.sources.shown_paths import as_given

    def shown(text: str) -> str:  # the file as the user named it; a long cause folded under its line
        return fold_text(as_given(text, [args.model]))

    print(shown(format_parity(report, args.model)))
    third = [as_note(f) for f in diagnosis.findings if f.kind is Kind.VERDICT]
    unable = {f.engine for f in diagnosis.findings if f.kind is Kind.ENGINE_UNABLE}  # its reason said once, there
    third += [f.message() for f in diagnosis.findings if f.kind is Kind.ENGINE_UNABLE]
    third += [
        f.message()
        for f in diagnosis.findings
        if f in diagnosis.optional_findings
        and f.kind is not Kind.ENGINE_UNABLE
        and not (f.kind is Kind.ENGINE_NOT_USED and f.engine in unable)
    ]
    if third:  # the optional engines' part, after MuJoCo's and Pinocchio's: their verdicts, their parsers' words
        said = {f.engine for f in diagnosis.optional_findings}  # attached, refused, or left out by --engines all
        used = [e for e in optional() if e in model.engines or e in said] or list(optional())
        names = ", ".join(engine_label(e) for e in used)
        head = "The third engine" if len(used) == 1 else "The other engines"
        print(f"\n{head} ({names}): verdicts and what {'its parser' if len(used) == 1 else 'their parsers'} said")
        print("\n".join(shown(f"  {line}") for line in third))
    gravity = diagnosis.gravity
    if gravity is not None:  # beside the kinetic verdict: the same robot in the same world
        print("\n" + shown(verdict_line(gravity)))
    gravity_off = gravity is not None and not gravity.agrees
    lead = lead_line(diagnosis.findings)
    if report.clean and not lead and not gravity_off:
        return 0
    label = unique_labels([args.model], options.floating, options.xacro_args)[0]
    if report.clean and not lead:  # only gravity differs
        print(f"koenig-check: {closed_cut(f'{label}: {reason_words(gravity)}', REASON_WIDTH)}", file=sys.stderr)
        return 1
    line = short_reason(label, diagnosis.findings)  # one sentence: the details are in the table above
    if line == f"{label}: ":  # every difference at the level of a written file's rounding: the option that accepts it
        hint = rounding_hint(report.largest_relative(), args.rtol, cli=True)
        line += hint or f"import differences, each at most {ROUNDING_LEVEL:g} relative: a written file's rounding"
    print(f"koenig-check: {line}", file=sys.stderr)
    return 1


def _unpaired_report(args: argparse.Namespace, err: JointMismatch) -> int:
    """The parity report of a model whose joints cannot be paired because one parser ignores a construct.

    Pinocchio's MJCF parser ignores ``<attach>``, ``<include>``, ``<frame>``...: the engines build different
    mechanisms from one file, which is the disagreement ``parity`` reports, led by its root causes (exit status 1).

    Parameters
    ----------
    args : argparse.Namespace
    err : JointMismatch
        With its root causes (:attr:`~koenig_check.exceptions.KoenigCheckError.causes`).

    Returns
    -------
    int
        1.
    """
    from koenig_check.diagnosis.message import detail_lines
    from koenig_check.diagnosis.model_reason import short_reason
    from koenig_check.line_width import fold_text
    from koenig_check.run.labels import unique_labels
    from koenig_check.sources.shown_paths import as_given

    options = load_options_of(args)
    lines = [f"Import parity of {args.model} (relative tolerance {args.rtol:g})", ""]
    named = (("only in MuJoCo", err.only_in_mujoco), ("only in Pinocchio", err.only_in_pinocchio))
    lines += [f"joints {what}: {', '.join(names)}" for what, names in named if names]
    lines += [f"joints of incompatible types: {', '.join(err.kind_mismatch)}"] if err.kind_mismatch else []
    lines += ["the engines' joints cannot be paired: no segment, dof or energy is compared", "", "root causes:"]
    for c in err.causes:
        effect = "changes the kinetic energy" if c.affects_energy else "no effect on the kinetic energy"
        lines.append(f"  - [{c.kind.value}, {effect}] {c.message()}")
    label = unique_labels([args.model], options.floating, options.xacro_args)[0]
    line = short_reason(label, err.causes)
    lines += ["", f"verdict: {line.removeprefix(f'{label}: ')}"]
    print(fold_text(as_given("\n".join(lines), [args.model])))
    hints = [c.hint for c in err.causes if c.hint]
    more = detail_lines({"hint": "; ".join(dict.fromkeys(hints))}, line, cli=True)
    print("\n".join([f"koenig-check: {line}", *more]), file=sys.stderr)
    return 1
