"""A per-state cache shared by every formula: ΔR, the paper's angles, world inertias, computed once.

Every formula is a function of a :class:`~koenig_check.segments.SegmentStates`.  Several of them need
the same derived arrays (the central inertia in world axes, ``ΔR = R R_refᵀ`` and the angles read
from it, ``½ m v_C²``, the body-frame angular velocity).  :class:`SharedStates` wraps one state set,
answers every field of the wrapped states, and computes each derived array the first time a
formula asks for it; the formulas ask through :func:`memo`, so that a formula given a plain
:class:`SegmentStates` computes everything itself and gives the same numbers.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from koenig_check.segments import SegmentStates


class SharedStates:
    """One state set and the derived arrays the formulas share.

    Parameters
    ----------
    states : SegmentStates

    Notes
    -----
    Attribute access falls through to the wrapped states, so a :class:`SharedStates` can be
    passed wherever a formula expects a :class:`SegmentStates`.
    """

    def __init__(self, states: SegmentStates) -> None:
        self.states = states
        self._memo: dict[str, Any] = {}

    def __getattr__(self, name: str) -> Any:
        return getattr(self.states, name)

    def memo(self, key: str, compute: Callable[[], Any]) -> Any:
        """Return the cached value under ``key``, computing it on first use.

        Parameters
        ----------
        key : str
        compute : callable
            Called without arguments on first use.

        Returns
        -------
        object
        """
        try:
            return self._memo[key]
        except KeyError:
            value = self._memo[key] = compute()
            return value

    def inertia_world(self) -> np.ndarray:
        """Return the central inertia in world axes, ``R I_body Rᵀ`` (P, B, 3, 3), computed once."""
        return self.memo("inertia_world", self.states.inertia_world)

    def inertia_world_ref(self) -> np.ndarray:
        """Return the central inertia in world axes at the reference configuration (B, 3, 3), computed once."""
        return self.memo("inertia_world_ref", self.states.inertia_world_ref)


#: What a formula accepts: plain states, or states wrapped with the shared cache.
States = SegmentStates | SharedStates


def memo(states: SegmentStates | SharedStates, key: str, compute: Callable[[], Any]) -> Any:
    """Compute ``compute()`` once per shared state set, or every time for plain states.

    Parameters
    ----------
    states : SegmentStates or SharedStates
    key : str
        Name of the derived array.
    compute : callable

    Returns
    -------
    object
    """
    if isinstance(states, SharedStates):
        return states.memo(key, compute)
    return compute()


def memo_of(states: SegmentStates | SharedStates, key: str, source: Any, compute: Callable[[], Any]) -> Any:
    """Like :func:`memo`, for a value derived from a caller's array ``source`` (integrated angles).

    The entry keeps ``source`` itself and is used only while the same object is passed again: an
    ``id()`` alone can be reused by a later array once the first is freed.

    Parameters
    ----------
    states : SegmentStates or SharedStates
    key : str
        Name of the derived array.
    source : object
        The array the value is derived from.
    compute : callable

    Returns
    -------
    object
    """
    if not isinstance(states, SharedStates):
        return compute()
    entry = states.memo(key, lambda: (source, compute()))
    if entry[0] is not source:
        entry = states._memo[key] = (source, compute())
    return entry[1]
