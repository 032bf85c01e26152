"""Drake's failed C++ checks as Python errors: one line with Drake's whole reason, without its build location.

pydrake turns a failed ``DRAKE_DEMAND`` into :class:`SystemExit` with the message ``Failure at
bazel-out/.../multibody_plant.h:2896 in SetPositions(): condition 'q.size() == num_positions()' failed.``:
uncaught, it would end the whole run (every other model of a batch lost) and print the build path.  Here it
becomes a :class:`RuntimeError` (at run time) or a finding (at load time) whose text is Drake's reason whole,
the function and the condition kept, the location dropped.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import wraps
from typing import Any, TypeVar, cast

from koenig_check.exceptions import without_build_location

F = TypeVar("F", bound=Callable[..., Any])


def failed_check(exit_: SystemExit) -> str | None:
    """Drake's reason for a failed C++ check on one line, or ``None`` when the exit is not one.

    Parameters
    ----------
    exit_ : SystemExit

    Returns
    -------
    str or None
        E.g. ``SetPositions(): condition 'q.size() == num_positions()' failed.``
    """
    text = " ".join(str(exit_.code or "").split())
    return without_build_location(text) if text.startswith("Failure at ") else None


def drake_failures_raised(method: F) -> F:
    """Make a Drake failed check inside ``method`` a :class:`RuntimeError` naming Drake and its reason.

    Parameters
    ----------
    method : callable

    Returns
    -------
    callable
    """

    @wraps(method)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return method(*args, **kwargs)
        except SystemExit as exit_:
            reason = failed_check(exit_)
            if reason is None:
                raise
            raise RuntimeError(f"Drake: {reason}") from None

    return cast(F, wrapper)
