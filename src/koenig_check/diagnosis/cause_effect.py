"""How much a root cause changes the kinetic energy, read from the values it carries on each side.

A root cause that names the mass (or inertia) each engine gives the same element (``{"mujoco": 0.1163577,
"pinocchio": 6.0}``: the mass of the geoms a parser reads another way) changes the energy of the segments it
concerns in proportion: the kinetic energy is linear in the masses and inertias.  Its effect is the change
itself, ``max|a - b|`` in the cause's unit (kg for the mass causes that MJCF parsers' traps give), not the
change relative to the element: 0.54 kg that a class's ``mass="0"`` should remove weighs less in the energy
than 2.6 kg that meshes add (dm_control's Jaco arm).  Only mass causes (kind ``MASS``, in kg) are measured, so that
the values compared share a unit; another cause (an ``<include>`` ignored, a ``<frame>`` skipped, a joint's
position) has no measured effect here and keeps its place.  The sides are the engines' (every declared engine,
:func:`koenig_check.engines.specs.names`, or those that loaded the model), so a cause of any engine is ranked.
"""

from __future__ import annotations

from collections.abc import Sequence
from numbers import Real
from typing import Any

import numpy as np

from koenig_check.engines.specs import names
from koenig_check.findings import Finding, Kind


def _numbers(value: Any) -> np.ndarray | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, Real):
        return np.array([float(value)])
    numbers = isinstance(value, list | tuple) and value
    if numbers and all(isinstance(v, Real) and not isinstance(v, bool) for v in value):
        return np.asarray(value, dtype=float)
    return None


def effect(cause: Finding, engines: Sequence[str] | None = None) -> float | None:
    """The change of the mass a cause names on two engines' sides, or ``None`` when it is not a mass cause.

    Parameters
    ----------
    cause : Finding
    engines : sequence of str, optional
        The engines whose sides its values may carry, in report order (default: every declared engine).

    Returns
    -------
    float or None
        ``max|a - b|`` over the two sides, in the values' unit.
    """
    if cause.kind is not Kind.MASS or not cause.affects_energy:  # kg only: lengths and moments do not compare
        return None
    sides = [_numbers(cause.values[s]) for s in (names() if engines is None else engines) if s in cause.values]
    pair = [s for s in sides if s is not None]
    if len(pair) < 2 or pair[0].shape != pair[1].shape:
        return None
    change = float(np.abs(pair[0] - pair[1]).max())
    return change if np.isfinite(change) else None


def by_effect(causes: Sequence[Finding], engines: Sequence[str] | None = None) -> list[Finding]:
    """Causes with a measured effect in the order of their effect, the largest first; the others keep their place.

    Parameters
    ----------
    causes : sequence of Finding
    engines : sequence of str, optional
        The engines that loaded the model, in report order (default: every declared engine).

    Returns
    -------
    list of Finding
    """
    effects = [effect(c, engines) for c in causes]
    slots = [k for k, e in enumerate(effects) if e is not None]
    measured = sorted(slots, key=lambda k: -float(effects[k] or 0.0))  # stable: ties keep their order
    out = list(causes)
    for slot, k in zip(slots, measured, strict=True):
        out[slot] = causes[k]
    return out
