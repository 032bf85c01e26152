"""When an optional engine (Drake) checks a model: the checker's policy, apart from how engines load.

``engines=None`` (the default): an optional engine that is installed is consulted only on a model where
MuJoCo and Pinocchio disagree, as tie-breaker, so that agreeing models cost nothing extra.  An engine the
user names (``engines=("mujoco", "pinocchio", "drake")``) runs on every pose of every model; when it cannot
check a model, the check the user asked for was not made, and the model fails.  Whenever an optional
engine is not used, an ``ENGINE_NOT_USED`` finding says why.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from koenig_check.engines import registry
from koenig_check.engines.registry import install_hint, label, not_used, optional
from koenig_check.findings import Finding, Kind

if TYPE_CHECKING:
    OPTIONAL: tuple[str, ...]  # read through __getattr__, from the specs


def __getattr__(name: str) -> tuple[str, ...]:
    """``OPTIONAL``, the tuple of earlier versions: the optional engines in report order, read when asked."""
    if name == "OPTIONAL":
        return optional()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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


def to_consult(name: str, engines: Sequence[str] | None, disagree: bool) -> Finding | None:
    """Whether to attach an optional engine to a model: None to attach it, else the finding saying why not.

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
    if engines is not None and name not in engines:
        return not_used(name, "not asked for (engines: " + ", ".join(engines) + ")")
    if not registry.installed(name):
        return not_used(name, f"not installed ({install_hint(name)})")
    if engines is None and not registry.spec(name).by_default:
        return not_used(name, "used only where named (--engines)")
    if engines is None and not disagree:
        return not_used(name, "not needed, MuJoCo and Pinocchio agree")
    return None


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
            hint="check the model without it (--engines mujoco,pinocchio), or fix what it refuses",
        )
        for f in findings
        if f.kind is Kind.ENGINE_NOT_USED and f.engine in asked
    ]
