"""The optional engines' columns in the dynamics check: each one's rigid M and inertia forces, against every route.

An optional engine's ``mass_matrix`` and ``inverse_dynamics`` include its own armature (Drake: the reflected
inertia of joint actuators, on one-dof joints only, where Drake's velocity is the canonical one): it is taken
out as MuJoCo's and Pinocchio's are, by the engine's own ``armature_matrix`` and ``armature_forces``
(:mod:`koenig_check.implied_dynamics.reference`), so nothing here is specific to one engine.  An optional engine
is run when ``engines`` asks for it, or by default (when installed) when MuJoCo and Pinocchio disagree on ``M``
or ``Q*`` (:mod:`koenig_check.diagnosis.policy`); the result's notes say when it was not used.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from koenig_check.engines.registry import optional, reference
from koenig_check.implied_dynamics.errors import discrepancy
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix


def add_engine_columns(result: Any, pair: Any, engines: Sequence[str] | None, parity_label: str) -> None:
    """Compare every route of a dynamics result with each optional engine used, and that engine with MuJoCo.

    Parameters
    ----------
    result : DynamicsResult
        Extended in place, per optional engine used (``"drake"``): ``engine_mass[name]``,
        ``engine_forces[name]``, discrepancies against it; and a note per optional engine not used.
    pair : LoadedModel
    engines : sequence of str or None
        As :attr:`LoadOptions.engines`.
    parity_label : str
        The pseudo-formula under which engines are compared with each other.
    """
    from koenig_check.diagnosis import policy

    # Whether MuJoCo and Pinocchio disagree: read before any optional engine adds its own comparisons.
    disagree = any(e.formula == parity_label and e.max_rel_error > result.tolerance(e) for e in result.errors)
    left_out = list(pair.optional_findings)  # said at load: the engines --engines all left out for the format
    result.findings += left_out
    result.notes += [f.message() for f in left_out]
    for name in optional():
        before = len(pair.optional_findings)
        found = policy.attach_engines(pair, disagree, names=(name,)) or list(pair.optional_findings[before:])
        engine = pair.engines.get(name)
        found = policy.unmade_checks(found, engines) + found
        result.findings += found
        result.notes += [f.message() for f in found]
        if engine is not None:
            _add_column(result, name, engine, parity_label)


def _add_column(result: Any, name: str, engine: Any, parity_label: str) -> None:
    """One optional engine's rigid ``M`` and ``Q*``, compared with every route and with MuJoCo's."""
    M = rigid_mass_matrix(engine, result.qpos)
    Q = rigid_inertia_forces(engine, result.qpos, result.qvel, result.qacc)
    result.engine_mass[name], result.engine_forces[name] = M, Q
    for (formula, route), r in list(result.routes.items()):
        result.errors.append(discrepancy(r.M, M, formula, route, name))
        result.errors.append(discrepancy(r.Q, Q, formula, route, name))
    ref = reference()
    result.errors.append(discrepancy(result.engine_mass[ref], M, parity_label, ref, name))
    result.errors.append(discrepancy(result.engine_forces[ref], Q, parity_label, ref, name))
