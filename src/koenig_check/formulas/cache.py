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
        """Return the central inertia in world axes at the reference configuration (B, 3, 3), computed once per model.

        It depends only on the model's constants (``rotation_ref``, ``inertia_body``): every chunk of the model
        shares it (:func:`per_model`).
        """
        states = self.states
        return per_model(
            "inertia_world_ref", (states.rotation_ref, states.inertia_body), states.inertia_world_ref, memo=self
        )


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


#: Values derived from a model's constant arrays, kept across the state sets (chunks) of the model.
_PER_MODEL: dict[tuple, Any] = {}
#: Entries kept at most (a few models' worth); beyond, the cache starts afresh.
_PER_MODEL_LIMIT = 32


def per_model(
    key: str, constants: tuple[np.ndarray, ...], compute: Callable[[], Any], memo: SharedStates | None = None
) -> Any:
    """``compute()`` once per value of ``constants`` (a model's mass properties, its reference pose), read-only.

    Every chunk of a model has the same constants: what is derived from them alone (principal axes,
    equimomental points, the reference inertia in world axes) is computed for the first chunk and
    reused by the next ones, looked up by the constants' bytes (a few kilobytes).  The arrays of the
    value are made read-only.  A ``compute`` that raises is not kept (it raises again next time).

    Parameters
    ----------
    key : str
        Name of the derived value.
    constants : tuple of ndarray
        Everything the value depends on.
    compute : callable
        Called without arguments on first use.
    memo : SharedStates, optional
        Also kept in this state set's own cache (a cheaper lookup for the chunk's next formulas).

    Returns
    -------
    object
    """
    if memo is not None and key in memo._memo:
        return memo._memo[key]
    arrays = tuple(np.asarray(c) for c in constants)
    full_key = (key, *((a.dtype.str, a.shape, a.tobytes()) for a in arrays))
    value = _PER_MODEL.get(full_key)
    if value is None:
        value = compute()
        for a in value if isinstance(value, tuple) else (value,):
            if isinstance(a, np.ndarray):
                a.setflags(write=False)
        if len(_PER_MODEL) >= _PER_MODEL_LIMIT:
            _PER_MODEL.clear()
        _PER_MODEL[full_key] = value
    if memo is not None:
        memo._memo[key] = value
    return value
