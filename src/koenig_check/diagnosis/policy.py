"""When an optional engine (Drake) checks a model: the checker's policy, apart from how engines load.

``engines=None`` (the default): an optional engine that is installed and declares itself a tie-breaker
(:attr:`~koenig_check.engines.specs.EngineSpec.tie_breaker`) is consulted only on a model where the required
engines disagree, so that agreeing models cost nothing extra; any other optional engine runs only when named.
An engine the user names (``engines=("mujoco", "pinocchio", "drake")``) runs on every pose of every model;
when it cannot check a model, the check the user asked for was not made, and the model fails.
``engines=("all",)`` (``--engines all``) names, per model, every installed engine whose parser reads its format
(:func:`koenig_check.engines.registry.engines_for`, resolved when the model is loaded): each is then asked for,
and each installed engine that does not read the format gets an ``ENGINE_NOT_USED`` finding saying so.

An engine named, or consulted, and not used on a model gets an ``ENGINE_NOT_USED`` finding on that model saying
why.  The installed engines the user did not name get none: the run says so once (:func:`not_named`,
:func:`koenig_check.report.engine_sets.not_named_line`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from koenig_check.engines import registry
from koenig_check.engines.catalogue import cause
from koenig_check.engines.registry import ENGINE_TEXT, install_hint, label, not_used, optional, required, spec
from koenig_check.engines.specs import ALL
from koenig_check.findings import Finding, Kind


def asked_for(engines: Sequence[str] | None) -> tuple[str, ...]:
    """The optional engines the user named: they run on every pose.

    Parameters
    ----------
    engines : sequence of str or None
        As :attr:`koenig_check.engines.LoadOptions.engines`.

    Returns
    -------
    tuple of str
    """
    return tuple(n for n in optional() if engines is not None and n in engines)


def considered(name: str, engines: Sequence[str] | None) -> bool:
    """Whether an optional engine is considered on a model at all: named, or a tie-breaker under the default policy.

    An engine not considered gets no finding on each model: the run says it once
    (:func:`koenig_check.report.engine_sets.not_named_line`).

    Parameters
    ----------
    name : str
    engines : sequence of str or None
        The engines the user named (None: the default policy).

    Returns
    -------
    bool
    """
    return name in engines if engines is not None else spec(name).tie_breaker


def not_named(engines: Sequence[str] | None) -> tuple[str, ...]:
    """The installed optional engines a run leaves out because the user did not name them.

    Parameters
    ----------
    engines : sequence of str or None
        As :attr:`koenig_check.engines.LoadOptions.engines`.  ``None`` (the default policy: the user chose no
        engine) and ``("all",)`` (an engine that does not read a model's format is said on that model) leave none
        out by name.

    Returns
    -------
    tuple of str
        In report order.
    """
    if engines is None or tuple(engines) == (ALL,):  # the default policy names none: nothing to say on each run
        return ()
    return tuple(n for n in optional() if registry.installed(n) and not considered(n, engines))


def to_consult(name: str, engines: Sequence[str] | None, disagree: bool) -> Finding | None:
    """Whether to attach an optional engine :func:`considered` on a model: None to attach it, else why not.

    Parameters
    ----------
    name : str
        An optional engine.
    engines : sequence of str or None
        The engines the user named (None: the default policy).
    disagree : bool
        Whether MuJoCo and Pinocchio disagree on the model.

    Returns
    -------
    Finding or None
    """
    if not registry.installed(name):
        return not_used(name, f"not installed ({install_hint(name)})")
    if engines is None and not disagree:
        return not_used(name, f"not needed, {_and(required())} agree")
    return None


def _and(engines: Sequence[str]) -> str:
    """``"MuJoCo and Pinocchio"``: engines' labels joined for a sentence."""
    labels = [label(e) for e in engines]
    return ", ".join(labels[:-1]) + " and " + labels[-1] if len(labels) > 1 else "".join(labels)


def unmade_checks(findings: Sequence[Finding], engines: Sequence[str] | None) -> list[Finding]:
    """The checks the user asked for that were not made: an engine they named could not check the model.

    Parameters
    ----------
    findings : sequence of Finding
        The model's findings (an optional engine's ``ENGINE_NOT_USED`` carries its own reason).
    engines : sequence of str or None
        The engines the user named.

    Returns
    -------
    list of Finding
        One ``ENGINE_UNABLE`` finding per named engine that was not used, with the engine's whole reason.
    """
    asked = asked_for(engines)
    return [
        Finding(
            Kind.ENGINE_UNABLE,
            f.engine,
            "model",
            f"{label(f.engine)} asked for (--engines) but it could not check the model: "
            + f.summary.removeprefix(f"{label(f.engine)} not used: "),
            {k: v for k, v in f.values.items() if k == ENGINE_TEXT},  # the engine's own words, whole
            hint=(f"{cause(f.cause).hint}; or " if f.cause else "")
            + f"check the model without it (--engines {','.join(required())})"
            + ("" if f.cause else ", or fix what it refuses"),  # the catalogue's hint: the refusal's cause is known
        )
        for f in findings
        if f.kind is Kind.ENGINE_NOT_USED and f.engine in asked
    ]


def attach_engines(model: Any, disagree: bool | None = None, names: Sequence[str] | None = None) -> list[Finding]:
    """Attach to a loaded model the optional engines the policy chooses: the one place they are attached.

    What attaching an engine found (its load findings, or ``ENGINE_NOT_USED`` when it cannot check the model) is
    in the model's :attr:`~koenig_check.engines.LoadedModel.optional_findings`.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel
    disagree : bool, optional
        ``None`` before the run: only the engines the user named (they run on every pose).  Otherwise whether
        MuJoCo and Pinocchio disagree: the engines consulted then (:func:`to_consult`) are attached too.
    names : sequence of str, optional
        Only these optional engines (default: every optional engine).

    Returns
    -------
    list of Finding
        Per optional engine :func:`considered` but not consulted (in report order), the ``ENGINE_NOT_USED``
        finding saying why (the engines not named have none: :func:`not_named`).
    """
    engines = model.options.engines
    why_not: list[Finding] = []
    for name in optional():
        if name in model.engines or (names is not None and name not in names) or not considered(name, engines):
            continue
        why = None if name in asked_for(engines) else to_consult(name, engines, bool(disagree))
        if why is None and (disagree is not None or name in asked_for(engines)):
            model.attach(name)
        elif why is not None and disagree is not None:
            why_not.append(why)
    return why_not
