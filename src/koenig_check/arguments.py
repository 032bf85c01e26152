"""Argument checks shared by the API and the command line, run before any work starts.

A bad argument is a usage error: :class:`ArgumentValueError` (a :class:`ValueError`) or
:class:`ArgumentTypeError` (a :class:`TypeError`), both :class:`~koenig_check.exceptions.KoenigCheckError`.
The API raises them instead of recording a model failure; the command line exits with status 2.
"""

from __future__ import annotations

import difflib
import functools
import inspect
import math
from collections.abc import Callable, Mapping, Sequence
from numbers import Integral, Real
from typing import Any, TypeVar, cast

from koenig_check.exceptions import ArgumentTypeError, ArgumentValueError

POSE_KINDS = ("random", "keyframes", "grid", "trajectory")
#: Which records a run keeps: per segment and totals, totals only, or none.
RECORD_MODES = ("segments", "totals", "none")

#: One line per pose kind, for ``--help`` and the report's glossary.
POSE_KIND_HELP = {
    "random": "N random joint positions, uniform within limits (unlimited: hinges over [-pi, pi], slides and "
    "free-joint positions within +-1 of the reference), orientations uniform; joint rates normal, std "
    "--velocity-scale",
    "keyframes": "the model's own keyframes; one at rest gets the joint rates of the random pose of its index",
    "grid": "an N x N sweep of the two --grid-joints over their range, unit rate on each, other joints at rest",
    "trajectory": "N samples of a torque-free MuJoCo simulation (gravity off) of --duration seconds",
}


def check_keywords(given: Mapping[str, Any], accepted: Sequence[str], where: str) -> None:
    """Refuse keywords a function does not take, suggesting the closest accepted one.

    Parameters
    ----------
    given : mapping
        The keywords passed.
    accepted : sequence of str
        The keywords the function takes.
    where : str
        The function's name, for the message.

    Raises
    ------
    ArgumentTypeError
    """
    for key in given:
        if key in accepted:
            continue
        close = difflib.get_close_matches(key, list(accepted), n=1)
        hint = f"; did you mean {close[0]!r}?" if close else f"; it takes {sorted(accepted)}"
        raise ArgumentTypeError(f"{where}() got an unexpected keyword argument {key!r}{hint}")


_Function = TypeVar("_Function", bound=Callable[..., Any])


def suggest_keywords(func: _Function) -> _Function:
    """Make a misspelt keyword raise :class:`ArgumentTypeError` naming the closest keyword of ``func``.

    The wrapper keeps ``func``'s signature (``inspect.signature`` and IDEs show every keyword); only the
    message of an unexpected keyword changes, from Python's bare ``TypeError`` to one with a suggestion.

    Parameters
    ----------
    func : callable
        A function whose keywords are all named in its signature (no ``**kwargs``).

    Returns
    -------
    callable
        ``func`` wrapped.
    """
    accepted = sorted(keywords_of(func))

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        __tracebackhide__ = True  # a failing assertion of the wrapped helper shows no line of this one
        check_keywords(kwargs, accepted, func.__name__)
        return func(*args, **kwargs)

    return cast(_Function, wrapper)


def keywords_of(*functions: Callable[..., Any]) -> set[str]:
    """The named keyword parameters of functions (``**kwargs`` excluded).

    Parameters
    ----------
    *functions : callable

    Returns
    -------
    set of str
    """
    names: set[str] = set()
    for func in functions:
        for p in inspect.signature(func).parameters.values():
            if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY):
                names.add(p.name)
    return names


def check_tolerance(value: Any, name: str = "rtol") -> float:
    """A relative tolerance: a finite real number > 0.

    Parameters
    ----------
    value : Any
    name : str

    Returns
    -------
    float

    Raises
    ------
    ArgumentTypeError
        Not a real number (a string, None, ...).
    ArgumentValueError
        Not finite or not > 0.
    """
    if isinstance(value, bool) or not isinstance(value, Real):
        raise ArgumentTypeError(f"{name} must be a real number > 0, got {value!r} ({type(value).__name__})")
    value = float(value)
    if not (value > 0 and math.isfinite(value)):
        raise ArgumentValueError(f"{name} must be a finite number > 0, got {value!r}")
    return value


def check_count(value: Any, name: str, minimum: int = 1) -> int:
    """A whole number >= ``minimum``.

    Parameters
    ----------
    value : Any
    name : str
    minimum : int

    Returns
    -------
    int

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
    """
    if isinstance(value, bool) or not isinstance(value, Integral):
        raise ArgumentTypeError(f"{name} must be a whole number, got {value!r} ({type(value).__name__})")
    if value < minimum:
        raise ArgumentValueError(f"{name} must be >= {minimum}, got {value}")
    return int(value)


def check_positive(value: Any, name: str) -> float:
    """A finite real number > 0 (a duration, a velocity scale).

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
    """
    return check_tolerance(value, name)


def check_formulas(formulas: Sequence[str] | None) -> None:
    """Refuse unknown formula names, suggesting close ones.

    Parameters
    ----------
    formulas : sequence of str, optional

    Raises
    ------
    ArgumentValueError, ArgumentTypeError
    """
    from koenig_check.formulas import FORMULAS

    if formulas is None:
        return
    if isinstance(formulas, str):
        raise ArgumentTypeError(f"formulas must be a list of names, got the string {formulas!r}")
    if len(formulas) == 0:
        raise ArgumentValueError("formulas: give at least one name (or None for all)")
    for name in formulas:
        if name not in FORMULAS:
            raise ArgumentValueError(unknown_name("formula", str(name), list(FORMULAS), FORMULAS_LISTED))


#: Where every formula name is listed (a usage error names the closest ones only).
FORMULAS_LISTED = "`koenig-check compare --help` lists them"


def closest(name: str, valid: Sequence[str], n: int = 3, cutoff: float = 0.5) -> list[str]:
    """The valid names closest to ``name``: the closest, and the others as close as it (ties), at most ``n``.

    Parameters
    ----------
    name : str
    valid : sequence of str
    n : int
    cutoff : float
        Similarity (:class:`difflib.SequenceMatcher` ratio) below which a name is not suggested.

    Returns
    -------
    list of str
    """
    scored = sorted(((difflib.SequenceMatcher(None, name, v).ratio(), v) for v in valid), reverse=True)
    best = scored[0][0] if scored else 0.0
    return [v for ratio, v in scored[:n] if ratio >= max(cutoff, best - 0.02)]


def unknown_name(what: str, name: str, valid: Sequence[str], listed: str) -> str:
    """The message for a name that is not one of ``valid``: the closest valid names and where all are listed.

    Parameters
    ----------
    what : str
        What the name names (``"formula"``).
    name : str
    valid : sequence of str
    listed : str
        Where the valid names are listed.

    Returns
    -------
    str
        One line, e.g. ``unknown formula 'koenig'; did you mean 'koenig_world'? (13 formulas: ...)``.
    """
    close = closest(name, valid)
    hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
    return f"unknown {what} {name!r}{hint} ({len(valid)} {what}s: {listed})"


def check_pose_file(pose_file: Any) -> None:
    """Refuse a pose file that does not exist, before any model is loaded.

    Parameters
    ----------
    pose_file : str, path or None

    Raises
    ------
    ArgumentValueError
        Naming the file, in one line.
    """
    from pathlib import Path

    if pose_file is not None and not Path(pose_file).expanduser().is_file():
        raise ArgumentValueError(f"{pose_file}: pose file not found (pose_file, --pose-file)")


def check_compare_arguments(rtol: Any, options: Mapping[str, Any]) -> None:
    """Check the arguments of :func:`koenig_check.compare` before any model is loaded.

    Parameters
    ----------
    rtol : Any
    options : mapping
        The other keywords (see :func:`koenig_check.api.compare_model`).

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
    """
    check_tolerance(rtol)
    kind = options.get("pose_kind", "random")
    if kind not in POSE_KINDS:
        raise ArgumentValueError(f"pose_kind must be one of {POSE_KINDS}, got {kind!r}")
    has_poses = options.get("pose_set") is not None or options.get("pose_file") is not None
    if "n_poses" in options:
        check_count(options["n_poses"], "n_poses")
    if "seed" in options:
        check_count(options["seed"], "seed", minimum=0)
    for name in ("velocity_scale", "duration"):
        if name in options:
            check_positive(options[name], name)
    check_formulas(options.get("formulas"))
    check_pose_file(options.get("pose_file"))
    if kind == "grid" and not has_poses:
        joints = options.get("grid_joints")
        if joints is None or isinstance(joints, str) or len(joints) != 2:
            raise ArgumentValueError("pose_kind 'grid' needs grid_joints: the names of two joints")
    records = options.get("records", "totals")
    if records not in RECORD_MODES:
        raise ArgumentValueError(f"records must be one of {RECORD_MODES}, got {records!r}")
    if "jobs" in options:
        check_count(options["jobs"], "jobs")


def check_dynamics_arguments(
    n_poses: Any, seed: Any, formulas: Any, m_rtol: Any, q_rtol: Any, velocity_scale: Any
) -> None:
    """Check the arguments of :func:`koenig_check.dynamics` before the model is loaded.

    Parameters
    ----------
    n_poses, seed, formulas, m_rtol, q_rtol, velocity_scale : Any
        As given to :func:`koenig_check.dynamics`.

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
    """
    check_count(n_poses, "n_poses")
    check_count(seed, "seed", minimum=0)
    check_formulas(formulas)
    check_tolerance(m_rtol, "m_rtol")
    check_tolerance(q_rtol, "q_rtol")
    check_positive(velocity_scale, "velocity_scale")
