"""Drake's column in the dynamics check: its rigid mass matrix and inertia forces, against every route.

Drake's ``CalcMassMatrix`` and ``CalcInverseDynamics`` include the reflected inertia of joint actuators
(Drake's armature, on one-dof joints only, where Drake's velocity is the canonical one): it is taken
out as each engine's own armature is, ``M − diag(I_refl)`` and ``τ − I_refl ⊙ q̈``.  Drake is run when
``engines`` asks for it, or by default (when installed) when MuJoCo and Pinocchio disagree on ``M`` or
``Q*`` (:mod:`koenig_check.diagnosis.policy`); the result's notes say when it was not used.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from koenig_check.implied_dynamics.errors import discrepancy
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix


def add_drake_column(result: Any, pair: Any, engines: Sequence[str] | None, parity_label: str) -> None:
    """Compare every route of a dynamics result with Drake, and Drake with MuJoCo, when Drake is used.

    Parameters
    ----------
    result : DynamicsResult
        Extended in place: ``engine_mass["drake"]``, ``engine_forces["drake"]``, discrepancies against
        Drake, and a note when Drake was not used.
    pair : ModelPair
    engines : sequence of str or None
        As :attr:`LoadOptions.engines`.
    parity_label : str
        The pseudo-formula under which engines are compared with each other.
    """
    from koenig_check.diagnosis import policy

    disagree = any(e.formula == parity_label and e.max_rel_error > result.tolerance(e) for e in result.errors)
    why = policy.to_consult("drake", engines, disagree)
    drake = pair.attach("drake") if why is None else None
    found = [why] if why is not None else list(pair.optional_findings)
    found = policy.unmade_checks(found, engines) + found
    result.findings += found
    result.notes += [f.message() for f in found]
    if drake is None:
        return
    M = rigid_mass_matrix(drake, result.qpos)
    Q = rigid_inertia_forces(drake, result.qpos, result.qvel, result.qacc)
    result.engine_mass["drake"], result.engine_forces["drake"] = M, Q
    for (name, route), r in list(result.routes.items()):
        result.errors.append(discrepancy(r.M, M, name, route, "drake"))
        result.errors.append(discrepancy(r.Q, Q, name, route, "drake"))
    result.errors.append(discrepancy(result.engine_mass["mujoco"], M, parity_label, "mujoco", "drake"))
    result.errors.append(discrepancy(result.engine_forces["mujoco"], Q, parity_label, "mujoco", "drake"))
