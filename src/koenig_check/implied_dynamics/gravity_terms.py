"""Gravity beside the implied dynamics: the engines' g(q), their full inverse dynamics with gravity, and words.

The paper's formulas are kinetic: each gives T(q, q̇), from which M and Q* follow; none has a gravity
counterpart of its own.  The potential energy ``V = -Σ m g·c`` needs only the segment masses and COMs, which
every formula takes from the same engine states, so ``g(q)`` is the engines' alone: compared engine against
engine (:mod:`koenig_check.gravity`), and with it the full inverse dynamics ``τ + g(q)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from koenig_check.gravity import GravityParity, gravity_parity
from koenig_check.gravity.words import verdict_line

#: What the report says of the formula rows.
NO_COUNTERPART = (
    "no formula row has a gravity counterpart: the formulas give T only, and V = -Σ m g·c needs only the segment "
    "masses and COMs every formula shares, so g(q) is compared engine against engine"
)


@dataclass(frozen=True)
class FullInverseDynamics:
    """The largest relative difference of one engine's ``τ + g(q)`` from MuJoCo's (Euclidean norm per pose).

    Attributes
    ----------
    engine : str
    relative : float
    pose : int
    """

    engine: str
    relative: float
    pose: int


def gravity_columns(pair: Any, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray, rtol: float) -> tuple:
    """The gravity verdict and the full inverse dynamics with gravity of every engine against MuJoCo's.

    Parameters
    ----------
    pair : koenig_check.engines.LoadedModel
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)
    rtol : float
        Tolerance of the gravity verdict.

    Returns
    -------
    parity : GravityParity
    full : list of FullInverseDynamics
    """
    parity = gravity_parity(pair, qpos, list(pair.findings), rtol)
    full = []
    reference = None
    for name, engine in pair.engines.items():
        if engine is None or name not in parity.readings:
            continue
        tau = engine.inverse_dynamics(qpos, qvel, qacc) + parity.readings[name].g
        if reference is None:
            reference = tau
            continue
        norm = np.maximum(np.linalg.norm(reference, axis=1), 1e-300)
        rel = np.linalg.norm(tau - reference, axis=1) / norm
        full.append(FullInverseDynamics(name, float(rel.max()), int(np.argmax(rel))))
    return parity, full


def gravity_lines(parity: GravityParity | None, full: list[FullInverseDynamics]) -> list[str]:
    """The gravity part of the dynamics report, one item a line.

    Parameters
    ----------
    parity : GravityParity or None
    full : list of FullInverseDynamics

    Returns
    -------
    list of str
    """
    if parity is None:
        return []
    lines = [verdict_line(parity)]
    lines += [
        f"inverse dynamics with gravity (τ + g(q)), mujoco vs {f.engine}: {f.relative:.3g} relative (pose {f.pose})"
        for f in full
    ]
    return [*lines, NO_COUNTERPART]
