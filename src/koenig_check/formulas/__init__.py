"""Kinetic-energy formulas under test: pure numpy, batched over (poses, segments).

Every formula maps a :class:`~koenig_check.segments.SegmentStates` to per-segment
energies of shape ``(P, B)``.  :data:`FORMULAS` names every variant the tool evaluates,
``base:option`` for formulas with a convention or recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial

import numpy as np

from koenig_check.formulas.alyushin import alyushin_current, alyushin_paper, alyushin_pole
from koenig_check.formulas.angles import CONVENTIONS, integrate_angular_velocity
from koenig_check.formulas.cache import States
from koenig_check.formulas.exact import exact
from koenig_check.formulas.koenig import koenig_principal, koenig_world
from koenig_check.formulas.planar import NotPlaneParallelError, planar
from koenig_check.formulas.point_masses import equimomental_points, point_masses


@dataclass(frozen=True)
class Formula:
    """A named formula variant.

    Attributes
    ----------
    name : str
        Registry name, e.g. ``"alyushin_paper:rotvec"``.
    equations : str
        The paper's equation numbers it implements.
    func : callable
        ``func(states, **kwargs) -> ndarray (P, B)``.
    needs_path : bool
        True when the formula needs the path integrals of ω (``angles=``).
    """

    name: str
    equations: str
    func: Callable[..., np.ndarray] = field(repr=False)
    needs_path: bool = False

    def __call__(self, states: States, angles: np.ndarray | None = None) -> np.ndarray:
        """Evaluate on ``states``; ``angles`` is passed only to path-dependent variants."""
        if self.needs_path:
            return self.func(states, angles=angles)
        return self.func(states)


def _registry() -> dict[str, Formula]:
    entries = [
        Formula("exact", "encyclopedia T; (10) integrated", exact),
        Formula("koenig_world", "(1) world axes", koenig_world),
        Formula("koenig_principal", "(1) principal axes", koenig_principal),
        Formula("alyushin_current", "(38) with (35), (27)", alyushin_current),
    ]
    for conv in CONVENTIONS:
        entries.append(
            Formula(
                f"alyushin_paper:{conv}",
                "(38) with (35) initial, (36)",
                partial(alyushin_paper, convention=conv),
                needs_path=conv == "integrated",
            )
        )
    entries.append(Formula("alyushin_pole:current", "(37) with (28), (27)", partial(alyushin_pole, recipe="current")))
    for conv in CONVENTIONS:
        entries.append(
            Formula(
                f"alyushin_pole:paper:{conv}",
                "(37) with (28) initial, (33)",
                partial(alyushin_pole, recipe="paper", convention=conv),
                needs_path=conv == "integrated",
            )
        )
    entries += [
        Formula("planar", "(16)", planar),
        Formula("point_masses", "(10) over equimomental points", point_masses),
    ]
    return {f.name: f for f in entries}


#: Every formula variant, by name.
FORMULAS: dict[str, Formula] = _registry()

__all__ = [
    "FORMULAS",
    "Formula",
    "NotPlaneParallelError",
    "alyushin_current",
    "alyushin_paper",
    "alyushin_pole",
    "equimomental_points",
    "exact",
    "integrate_angular_velocity",
    "koenig_principal",
    "koenig_world",
    "planar",
    "point_masses",
]
