"""Kinetic-energy parts reported by an engine, and checks of an engine against itself."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from koenig_check.findings import Finding, Kind

if TYPE_CHECKING:
    from koenig_check.engines.base import Engine

#: Default relative tolerance of the self-consistency checks.
CONSISTENCY_RTOL = 1e-9


@dataclass(frozen=True)
class EnergyParts:
    """Kinetic energy of ``P`` poses as an engine reports it.

    Parameters
    ----------
    rigid : ndarray, shape (P,)
        The rigid-body term alone, from the engine itself: Pinocchio's kinetic-energy function on a
        copy of the model whose armature is zero; MuJoCo's ``½ q̇ᵀ (M − diag(armature)) q̇`` (a
        zeroed copy keeps the armature of its "simple" dofs, see ``MujocoEngine.kinetic_energy``).
    armature : ndarray, shape (P,)
        ``½ Σ aᵢ vᵢ²`` over the engine's velocity coordinates and armature values (rotor inertia).
    reported : ndarray, shape (P,)
        The engine's kinetic-energy function on the model as loaded (it may or may not include the
        armature term: see the model's notes).
    """

    rigid: np.ndarray
    armature: np.ndarray
    reported: np.ndarray

    @property
    def total(self) -> np.ndarray:
        """Rigid-body plus armature energy, shape (P,)."""
        return self.rigid + self.armature


def _close(a: np.ndarray, b: np.ndarray, rtol: float) -> bool:
    scale = np.maximum(np.abs(a), np.abs(b))
    return bool(np.all(np.abs(a - b) <= rtol * np.maximum(scale, 1e-12)))


def _kinds_concerned(
    engine: Engine,
    qpos: np.ndarray,
    qvel: np.ndarray,
    test: Callable[[np.ndarray, np.ndarray, float], bool],
    rtol: float,
) -> list[str]:
    """Return the joint kinds for which ``test(qpos, qvel_restricted)`` fails."""
    bad = []
    for kind, dofs in engine.dofs_by_kind().items():
        v = np.zeros_like(qvel)
        v[:, dofs] = qvel[:, dofs]
        if not test(qpos, v, rtol):
            bad.append(kind)
    return bad


def _fact(engine: Engine, summary: str, **values: object) -> Finding:
    return Finding(Kind.SELF_CONSISTENCY, engine.engine, "model", summary, values)


def _armature_inclusion(engine: Engine, qpos: np.ndarray, qvel: np.ndarray, rtol: float) -> list[Finding]:
    """Say, joint kind by joint kind, whether the engine's energy includes the armature term."""
    parts = engine.kinetic_energy(qpos, qvel)
    if _close(parts.reported, parts.total, rtol):
        return [_fact(engine, "its kinetic energy includes the armature term")]
    if _close(parts.reported, parts.rigid, rtol):
        return [_fact(engine, "its kinetic energy excludes the armature term")]
    included, excluded, other = [], [], []
    for kind, dofs in engine.dofs_by_kind().items():
        v = np.zeros_like(qvel)
        v[:, dofs] = qvel[:, dofs]
        p = engine.kinetic_energy(qpos, v)
        if not np.any(p.armature > 0):
            continue
        if _close(p.reported, p.total, rtol):
            included.append(kind)
        elif _close(p.reported, p.rigid, rtol):
            excluded.append(kind)
        else:
            other.append(kind)
    return [
        Finding(
            Kind.SELF_CONSISTENCY,
            engine.engine,
            "joint kinds " + ", ".join(excluded + other),
            "its kinetic energy includes the armature term for some joint kinds only",
            {"included": included, "excluded": excluded, "neither": other},
            affects_energy=True,
        )
    ]


def self_consistency(
    engine: Engine, qpos: np.ndarray, qvel: np.ndarray, rtol: float = CONSISTENCY_RTOL
) -> list[Finding]:
    """Describe what an engine's energy, mass matrix and inverse dynamics include, and where they disagree.

    Parameters
    ----------
    engine : Engine
    qpos : ndarray, shape (P, nq)
    qvel : ndarray, shape (P, nv)
    rtol : float
        Relative tolerance.

    Returns
    -------
    list of Finding
        Facts (``"includes the armature term"``, not affecting the energy) and inconsistencies
        (affecting it, naming the joint kinds concerned), of kind ``SELF_CONSISTENCY``.
    """
    out: list[Finding] = []
    parts = engine.kinetic_energy(qpos, qvel)
    M = engine.mass_matrix(qpos)

    def quad(q: np.ndarray, v: np.ndarray) -> np.ndarray:
        return 0.5 * np.einsum("pi,pij,pj->p", v, engine.mass_matrix(q), v)

    def energy_vs_matrix(q: np.ndarray, v: np.ndarray, tol: float) -> bool:
        return _close(engine.kinetic_energy(q, v).reported, quad(q, v), tol)

    half_vmv = 0.5 * np.einsum("pi,pij,pj->p", qvel, M, qvel)
    if np.any(parts.armature > 0):
        out += _armature_inclusion(engine, qpos, qvel, rtol)
        if _close(half_vmv, parts.total, rtol):
            out.append(_fact(engine, "its mass matrix includes the armature on the diagonal"))
        elif _close(half_vmv, parts.rigid, rtol):
            out.append(_fact(engine, "its mass matrix excludes the armature"))
    if not _close(parts.reported, half_vmv, rtol):
        kinds = _kinds_concerned(engine, qpos, qvel, energy_vs_matrix, rtol)
        out.append(
            Finding(
                Kind.SELF_CONSISTENCY,
                engine.engine,
                "joint kinds " + ", ".join(kinds),
                "inconsistent: kinetic energy != ½ q̇ᵀ M q̇",
                {"joint kinds": kinds},
                affects_energy=True,
            )
        )
    rng = np.random.default_rng(0)
    qacc = rng.normal(size=qvel.shape)
    tau = engine.inverse_dynamics(qpos, np.zeros_like(qvel), qacc)
    if not _close(tau, np.einsum("pij,pj->pi", M, qacc), rtol):

        def id_vs_matrix(q: np.ndarray, a: np.ndarray, tol: float) -> bool:
            t = engine.inverse_dynamics(q, np.zeros_like(a), a)
            return _close(t, np.einsum("pij,pj->pi", engine.mass_matrix(q), a), tol)

        kinds = _kinds_concerned(engine, qpos, qacc, id_vs_matrix, rtol)
        out.append(
            Finding(
                Kind.SELF_CONSISTENCY,
                engine.engine,
                "joint kinds " + ", ".join(kinds),
                "inconsistent: inverse dynamics at q̇=0 != M q̈",
                {"joint kinds": kinds},
            )
        )
    return out
