"""Generalized inertia forces from any state-function energy by Lagrange's equations.

``Q* = −(d/dt ∂T/∂q̇ − ∂T/∂q)`` (Kane & Levinson), on canonical coordinates.  Canonical velocities of
ball joints and of a free joint's rotation are angular velocities in the body frame (quasi-velocities,
see :mod:`~koenig_check.implied_dynamics.manifold`); for them Lagrange's equations take Hamel's form
(the Euler–Poincaré equations on SO(3)) with one more term per joint,

``τ_ω = d/dt ∂T/∂ω + ω × ∂T/∂ω − X(T)``,

where ``X(T)`` is the derivative of ``T`` along the body-side rotation with ``ω`` held fixed (what
:func:`configuration_gradient` computes through ``mj_integratePos``).  For a single free rigid body
this is Euler's ``I ω̇ + ω × I ω``; without the term, Lagrange's form disagrees with both engines
on every ball or free joint.  Hinges, slides and the free joint's world-frame linear velocity are
true coordinate rates and need nothing more.  The result is ``Q* = −τ``.

Numerics
--------
* ``∂T/∂q̇`` is exact up to rounding (symmetric difference of a quadratic,
  :func:`~koenig_check.implied_dynamics.energy.implied_momentum`).
* ``∂T/∂q_j = (T(q ⊕ δ e_j, q̇) − T(q ⊕ −δ e_j, q̇)) / 2δ``: truncation ``≈ δ² |T'''| / 6`` and rounding
  ``≈ ε |T| / δ``.  With ``δ`` = :data:`CONFIGURATION_STEP` = 1e-5 (rad or m; the balance point
  ``(3ε)^{1/3}`` for unit length and angle scales) both are about 1e-11 of ``|T|``.
* ``d/dt p`` along the path ``q(t ± h) = q ⊕ (±h q̇ + h²/2 q̈)``, ``q̇(t ± h) = q̇ ± h q̈``
  (second-order accurate also on SO(3): the commutator term of the Magnus series is O(h³)),
  ``(p(t + h) − p(t − h)) / 2h``: truncation ``≈ (hΩ)² / 6`` and rounding ``≈ ε / (hΩ)`` relative
  to ``|p| Ω``, with ``Ω = max(|q̇|∞, √|q̈|∞, 1)`` the pose's characteristic rate.  ``h = η / Ω``
  with ``η`` = :data:`TIME_STEP_SCALE` = 1e-5 keeps both near 1e-11.
Measured (``exact`` on MuJoCo's states against ``mj_inverse``, worst norm-relative error over 6 random
states with unit and 10× velocities, on gimbal, serial7, free_body, a ball/composite model, ur5 and
solo12 floating, g1 floating with 35 dofs), with ``δ = η``:  1e-3 → 2e-6, 1e-4 → 2e-8 (truncation,
falling as h²), 1e-5 → 7e-10, 1e-6 → 6e-9, 1e-7 → 8e-8 (rounding, growing as 1/h).  The chosen 1e-5
is the minimum, about three orders of magnitude inside the 1e-7 the method is built for.
"""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.implied_dynamics.energy import FormulaEnergy, implied_momentum
from koenig_check.implied_dynamics.manifold import integrate, rotation_blocks

#: Step ``δ`` of the central difference ``∂T/∂q`` on the configuration manifold (rad or m).
CONFIGURATION_STEP = 1e-5
#: ``η = hΩ``: time step of ``d/dt ∂T/∂q̇`` as a fraction of the pose's characteristic period ``1/Ω``.
TIME_STEP_SCALE = 1e-5


def configuration_gradient(
    energy: FormulaEnergy, model: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray, step: float = CONFIGURATION_STEP
) -> np.ndarray:
    """``∂T/∂q`` at fixed ``q̇``, by central differences along each canonical direction on the manifold.

    Parameters
    ----------
    energy : FormulaEnergy
    model : mujoco.MjModel
        The canonical (MuJoCo) model, for ``mj_integratePos``.
    qpos : ndarray, shape (P, nq)
    qvel : ndarray, shape (P, nv)
    step : float
        ``δ`` (rad or m).

    Returns
    -------
    ndarray, shape (P, nv)
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    qvel = np.atleast_2d(np.asarray(qvel, dtype=float))
    P, nv = qvel.shape
    q = np.repeat(qpos, nv, axis=0)
    dirs = np.tile(np.eye(nv), (P, 1))
    plus, minus = integrate(model, q, dirs, step), integrate(model, q, dirs, -step)
    u = np.repeat(qvel, nv, axis=0)
    T = energy(np.concatenate([plus, minus]), np.concatenate([u, u])).reshape(2, P, nv)
    return (T[0] - T[1]) / (2.0 * step)


def momentum_rate(
    energy: FormulaEnergy,
    model: mujoco.MjModel,
    qpos: np.ndarray,
    qvel: np.ndarray,
    qacc: np.ndarray,
    scale: float = TIME_STEP_SCALE,
) -> np.ndarray:
    """``d/dt ∂T/∂q̇`` along the motion through ``(q, q̇)`` with acceleration ``q̈``, by central differences in time.

    Parameters
    ----------
    energy : FormulaEnergy
    model : mujoco.MjModel
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)
    scale : float
        ``η``: the time step is ``h = η / Ω`` per pose.

    Returns
    -------
    ndarray, shape (P, nv)
    """
    qpos = np.atleast_2d(np.asarray(qpos, dtype=float))
    qvel = np.atleast_2d(np.asarray(qvel, dtype=float))
    qacc = np.atleast_2d(np.asarray(qacc, dtype=float))
    omega = np.maximum.reduce([np.abs(qvel).max(axis=1), np.sqrt(np.abs(qacc).max(axis=1)), np.ones(len(qvel))])
    h = (scale / omega)[:, None]
    q_plus = integrate(model, qpos, h * qvel + 0.5 * h**2 * qacc)
    q_minus = integrate(model, qpos, -h * qvel + 0.5 * h**2 * qacc)
    p = implied_momentum(
        energy, np.concatenate([q_plus, q_minus]), np.concatenate([qvel + h * qacc, qvel - h * qacc])
    ).reshape(2, *qvel.shape)
    return (p[0] - p[1]) / (2.0 * h)


def hamel_term(model: mujoco.MjModel, qvel: np.ndarray, momentum: np.ndarray) -> np.ndarray:
    """``ω × ∂T/∂ω`` on every body-frame angular-velocity triple, zero elsewhere.

    Parameters
    ----------
    model : mujoco.MjModel
    qvel, momentum : ndarray, shape (P, nv)

    Returns
    -------
    ndarray, shape (P, nv)
    """
    out = np.zeros_like(np.atleast_2d(qvel), dtype=float)
    blocks = rotation_blocks(model)
    if len(blocks):
        out[:, blocks] = np.cross(np.atleast_2d(qvel)[:, blocks], np.atleast_2d(momentum)[:, blocks])
    return out


def lagrange_inertia_forces(
    energy: FormulaEnergy, model: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray
) -> np.ndarray:
    """``Q* = −(d/dt ∂T/∂q̇ − ∂T/∂q)`` (Hamel's form on body-frame angular velocities) for a formula's energy.

    Parameters
    ----------
    energy : FormulaEnergy
        The formula on one engine's segment states.
    model : mujoco.MjModel
        The canonical (MuJoCo) model, for ``mj_integratePos``.
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)

    Returns
    -------
    ndarray, shape (P, nv)
    """
    rate = momentum_rate(energy, model, qpos, qvel, qacc)
    grad = configuration_gradient(energy, model, qpos, qvel)
    p = implied_momentum(energy, qpos, qvel)
    return -(rate - grad + hamel_term(model, qvel, p))
