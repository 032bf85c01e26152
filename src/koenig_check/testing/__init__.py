"""Helpers for users' own test suites.

>>> from koenig_check.testing import assert_energy_parity
>>> assert_energy_parity("models/serial7.urdf")  # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.arguments import suggest_keywords
from koenig_check.diagnosis import policy
from koenig_check.engines.load_options import LoadOptions, load_options_from
from koenig_check.exceptions import KoenigCheckError
from koenig_check.formulas import FORMULAS
from koenig_check.run.stats import DEFAULT_RTOL, relative_error


@suggest_keywords
def assert_energy_parity(
    model: str | Path,
    pinocchio_model: str | Path | None = None,
    *,
    n_poses: int = 20,
    seed: int = 0,
    velocity_scale: float = 1.0,
    rtol: float = DEFAULT_RTOL,
    include_armature: bool = True,
    load_options: LoadOptions | None = None,
    floating: bool | None = None,
    balance_inertia: bool | None = None,
    repair_inertia: bool | None = None,
    allow_coupled: bool | None = None,
    engines: Sequence[str] | None = None,
    xacro_args: Mapping[str, Any] | Sequence[str] | None = None,
    gravity: bool = True,
) -> None:
    """Assert that MuJoCo and Pinocchio give the same kinetic energy for a model, segment by segment.

    And, with ``gravity``, that every engine compared applies the same gravity to it: the same gravity vector,
    ``g(q)`` and ``V(q) - V(q_ref)`` (:mod:`koenig_check.gravity`); a difference names its catalogued cause.

    Parameters
    ----------
    model : str or Path
        Model file or name, loaded into MuJoCo (and into Pinocchio unless
        ``pinocchio_model`` is given).
    pinocchio_model : str or Path, optional
        A different file of the same robot for Pinocchio (e.g. the URDF of an MJCF).
    n_poses, seed, velocity_scale
        Seeded random poses within joint limits.
    rtol : float
        Relative tolerance on every segment's energy and on the totals.
    include_armature : bool
        Also require the engines' armature energies to agree.
    load_options : LoadOptions, optional
        How the model is loaded; the load keywords override its fields.
    gravity : bool
        Also require the engines' gravity terms to agree (default True).
    floating, balance_inertia, repair_inertia, allow_coupled, engines, xacro_args
        The other fields of :class:`koenig_check.engines.load_options.LoadOptions` (``None`` keeps the value
        of ``load_options``).  ``engines=("mujoco", "pinocchio", "drake")`` also requires Drake to
        agree; by default Drake, when installed, is consulted only when the two engines disagree, and the
        message then opens with the engine that departs and the construct responsible.

    Raises
    ------
    AssertionError
        Naming the segment, the pose and the size of the largest difference, with the
        import-parity causes found for that segment.  The message reads like the command line's verdict:
        the engine that departs (three engines) and the root cause first, then the symptoms; pytest shows
        no line of this function (``__tracebackhide__``).
    """
    __tracebackhide__ = True
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.diagnosis.reason import ROUNDING_LEVEL, as_note, cause_lines, rounding_hint
    from koenig_check.engines import load_model
    from koenig_check.engines.registry import check_engines
    from koenig_check.findings import Kind
    from koenig_check.run.poses import random_poses

    given = locals()
    options = load_options_from(load_options, {n: given[n] for n in LoadOptions.names() if given[n] is not None})
    check_engines(options.engines)
    try:
        pair = load_model(model, options)
    except KoenigCheckError as refused:  # the file's own problem in one message, no frame of the library below
        raise AssertionError(_refusal(refused)) from None
    policy.attach_engines(pair)  # named engines are compared on every pose
    poses = random_poses(pair.mujoco.model, n_poses, seed=seed, velocity_scale=velocity_scale)
    sa = pair.mujoco.segment_states(poses.qpos, poses.qvel)
    sb = pair.pinocchio.segment_states(poses.qpos, poses.qvel)
    only_a = sorted(set(sa.names) - set(sb.names))
    only_b = sorted(set(sb.names) - set(sa.names))
    if only_a or only_b:
        only = f"only in MuJoCo {only_a}, only in Pinocchio {only_b}"
        raise AssertionError(_folded(f"{model}: segments differ between the engines: {only}"))
    sb = sb.select(segments=list(sa.names))
    ea, eb = FORMULAS["exact"](sa), FORMULAS["exact"](sb)
    scale = np.maximum(np.abs(ea).sum(axis=1, keepdims=True), 1e-300)  # per pose: total energy
    err = np.abs(eb - ea) / scale
    p, b = np.unravel_index(int(np.argmax(err)), err.shape)
    segment_off = bool(err[p, b] > rtol)
    problems: list[str] = []
    ka = pair.mujoco.kinetic_energy(poses.qpos, poses.qvel)
    kb = pair.pinocchio.kinetic_energy(poses.qpos, poses.qvel)
    rel = np.abs(relative_error(kb.rigid, ka.rigid))
    if rel.max() > rtol:
        k = int(np.argmax(rel))
        problems.append(
            f"total rigid-body energy at pose {poses.ids[k]}: MuJoCo {ka.rigid[k]:.9g} J, "
            f"Pinocchio {kb.rigid[k]:.9g} J ({rel[k]:.3g} relative)"
        )
    armature_off = False
    if include_armature:
        darm = np.abs(kb.armature - ka.armature)
        tot = np.maximum(np.abs(ka.rigid) + np.abs(ka.armature), 1e-300)
        armature_off = bool((darm / tot).max() > rtol)
        if armature_off:
            k = int(np.argmax(darm / tot))
            problems.append(
                f"armature energy at pose {poses.ids[k]}: MuJoCo {ka.armature[k]:.9g} J, "
                f"Pinocchio {kb.armature[k]:.9g} J"
            )
    diagnosis = diagnose(
        pair,
        disagree=segment_off or bool(problems),
        qpos=poses.qpos,
        qvel=poses.qvel,
        rtol=rtol,
        include_armature=include_armature,
    )
    if segment_off and diagnosis.parity is not None:  # the segment as the user wrote it, its link or body
        name = sa.names[b]
        causes = diagnosis.parity.causes_for(name, above=ROUNDING_LEVEL)  # never a file's rounding
        problems.insert(
            0,
            f"{diagnosis.parity.label(name)} at pose {poses.ids[p]}: MuJoCo {ea[p, b]:.9g} J, "
            f"Pinocchio {eb[p, b]:.9g} J, "
            f"difference {eb[p, b] - ea[p, b]:+.3g} J ({err[p, b]:.3g} of the pose's total energy)"
            + (f"; import parity: {', '.join(causes)} differ" if causes else ""),
        )
    hint = rounding_hint(float(rel.max()), rtol) if not armature_off else ""
    unable = [f.message() for f in diagnosis.findings if f.kind is Kind.ENGINE_UNABLE]  # a check asked, not made
    verdicts = [as_note(f) for f in diagnosis.findings if f.kind is Kind.VERDICT]
    problems[:0] = verdicts
    if gravity and diagnosis.gravity is not None and not diagnosis.gravity.agrees:
        from koenig_check.gravity.words import verdict_line

        problems.append(verdict_line(diagnosis.gravity))
    if problems or unable:  # as the plugin: a check not made, the root causes, the verdicts, then the symptoms
        problems[:0] = unable + [f"root cause: {cause}" for cause in cause_lines(diagnosis.findings)]
        if hint:
            problems.append(hint)
        raise AssertionError(_one_item_a_line(f"{model}: energy parity fails (rtol {rtol:g}): ", problems))


def _one_item_a_line(head: str, problems: list[str]) -> str:
    """A failure's message: ``head`` and the first problem, then one problem a line.

    Each line fits 200 characters as pytest prints it (``E       AssertionError: `` before the first line,
    ``E         `` before the others).
    """
    from koenig_check.line_width import LINE_LIMIT, fold

    first, *rest = problems
    lines = fold(head + first, LINE_LIMIT - len("E       AssertionError: "))
    for problem in rest:
        lines += fold(f"  {problem}", LINE_LIMIT - len("E       "))
    return "\n".join(lines)


def _refusal(err: KoenigCheckError) -> str:
    """A model that could not be loaded, as one message: a first line naming it and why, then the rest indented.

    The first line fits after pytest's ``E       AssertionError: ``; the lines after it (the rest of the message,
    the engine's own words, the hint: :func:`koenig_check.diagnosis.message.detail_lines`) are never cut.
    """
    from koenig_check.diagnosis.message import detail_lines
    from koenig_check.diagnosis.one_line import short_error
    from koenig_check.testing.failure_text import FAILURE_WIDTH

    first = short_error(err, FAILURE_WIDTH - len("AssertionError: "))
    return "\n".join([first, *detail_lines(err, first, width=FAILURE_WIDTH)])


def _folded(text: str) -> str:
    """A refusal's whole text folded to lines that fit after pytest's ``E       AssertionError: ``.

    As the energy failures are (:func:`koenig_check.testing.failure_text.verdict_lines`); the first line is
    written after the exception's name.
    """
    from koenig_check.line_width import fold
    from koenig_check.testing.failure_text import FAILURE_WIDTH

    return "\n".join(fold(text, FAILURE_WIDTH - len("AssertionError: ")))
