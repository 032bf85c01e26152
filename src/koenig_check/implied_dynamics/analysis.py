"""One model's dynamics check: every formula's implied ``M`` and ``Q*`` by every route, against both engines.

Routes
------
``lagrange@<engine>``
    The formula evaluated on that engine's segment states: ``M`` by polarization, ``Q*`` by Lagrange's
    equations (any formula that is a function of the state).
``kane@<engine>``
    ``exact`` only: Kane's form with that engine's own Jacobians and accelerations.

Every route is compared with both engines' rigid ``M`` and ``Q*`` (armature taken out, see
:mod:`~koenig_check.implied_dynamics.reference`), and the engines with each other.  The check passes
when ``exact`` agrees with both engines by every route and the engines agree with each other; the
paper's formulas disagreeing is the finding the report is for, not a failure.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from koenig_check.arguments import suggest_keywords
from koenig_check.engines import LoadedModel, load_model
from koenig_check.engines.canonical import mujoco_coordinate_names
from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.specs import parity_pair, specs
from koenig_check.exceptions import KoenigCheckError, one_line
from koenig_check.findings import Finding, Kind
from koenig_check.formulas import FORMULAS, NotPlaneParallelError
from koenig_check.gravity import GravityParity
from koenig_check.gravity.words import reason_words
from koenig_check.implied_dynamics.energy import FormulaEnergy, PathDependentError, implied_mass_matrix
from koenig_check.implied_dynamics.engine_columns import add_engine_columns
from koenig_check.implied_dynamics.errors import Discrepancy, discrepancy
from koenig_check.implied_dynamics.gravity_terms import FullInverseDynamics, gravity_columns
from koenig_check.implied_dynamics.kane import kane_mujoco, kane_pinocchio
from koenig_check.implied_dynamics.lagrange import lagrange_inertia_forces
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix
from koenig_check.run.poses import random_poses

#: Default relative tolerance (Frobenius norm, per pose) for ``M`` of ``exact`` against an engine.
M_RTOL = 1e-9
#: Default relative tolerance (Euclidean norm, per pose) for ``Q*`` of ``exact`` against an engine.
Q_RTOL = 1e-6
#: The engines every model is loaded in, the reference first (MuJoCo, Pinocchio): a column each, always.
ENGINES = parity_pair()
#: The pseudo-formula under which the engines are compared with each other.
ENGINE_PARITY = "(engine)"


@dataclass
class RouteResult:
    """What one route gives for one formula.

    Attributes
    ----------
    M : ndarray, shape (P, nv, nv)
    Q : ndarray, shape (P, nv)
        Generalized inertia forces ``Q*``.
    """

    M: np.ndarray
    Q: np.ndarray


@dataclass
class DynamicsResult:
    """Every formula's implied dynamics on one model, with the errors against both engines.

    Attributes
    ----------
    model : str
        The model file.
    qpos, qvel, qacc : ndarray
        The canonical states, shapes (P, nq), (P, nv), (P, nv).
    dof_names : tuple of str
        Canonical velocity coordinates, named after their joints.
    engine_mass, engine_forces : dict
        Engine name -> its rigid mass matrix (P, nv, nv) and ``Q* = −τ_rigid`` (P, nv).
    routes : dict
        ``(formula, route)`` -> :class:`RouteResult`.
    errors : list of Discrepancy
        Every route against every engine, ``M`` and ``Q*``, and the engines against each other.
    refusals : dict
        Formula -> why it has no ``M``/``Q*`` (path-dependent energy, non-plane-parallel motion...).
    m_rtol, q_rtol : float
        Tolerances of the verdict on ``exact``.
    rtol : float, optional
        Tolerance of the engines' readings of the model against each other, when larger (see :meth:`tolerance`).
    notes : list of str
        The model's load notes, for people.
    findings : list of Finding
        The same as typed records (and Drake's, when it was consulted).
    gravity : GravityParity, optional
        The engines' gravity terms against MuJoCo's; ``full_inverse_dynamics``: their ``τ + g(q)``.
    """

    model: str
    qpos: np.ndarray
    qvel: np.ndarray
    qacc: np.ndarray
    dof_names: tuple[str, ...]
    engine_mass: dict[str, np.ndarray] = field(default_factory=dict)
    engine_forces: dict[str, np.ndarray] = field(default_factory=dict)
    routes: dict[tuple[str, str], RouteResult] = field(default_factory=dict)
    errors: list[Discrepancy] = field(default_factory=list)
    refusals: dict[str, str] = field(default_factory=dict)
    m_rtol: float = M_RTOL
    q_rtol: float = Q_RTOL
    rtol: float | None = None
    notes: list[str] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    gravity: GravityParity | None = None
    full_inverse_dynamics: list[FullInverseDynamics] = field(default_factory=list)

    def __repr__(self) -> str:
        return (
            f"<DynamicsResult {self.model} ok={self.ok} poses={len(self.qpos)} dofs={len(self.dof_names)} "
            f"formulas={len(self.formulas)} refused={len(self.refusals)}>"
        )

    @property
    def formulas(self) -> list[str]:
        """Formulas evaluated or refused, in order."""
        seen = dict.fromkeys([f for f, _ in self.routes] + list(self.refusals))
        return list(seen)

    def errors_of(self, formula: str, quantity: str | None = None) -> list[Discrepancy]:
        """The discrepancies of one formula (optionally only ``"M"`` or ``"Q*"``)."""
        return [e for e in self.errors if e.formula == formula and quantity in (None, e.quantity)]

    def tolerance(self, e: Discrepancy) -> float:
        """The tolerance of one comparison.

        ``m_rtol`` / ``q_rtol`` by quantity; where two engines' readings of the model meet (the engines against
        each other, or a route on one engine's states against another engine) the larger of that, ``rtol`` and
        the precision both engines declare (:attr:`~koenig_check.engines.specs.EngineSpec.precision`: Newton's
        float32 round-off is no difference).

        Parameters
        ----------
        e : Discrepancy

        Returns
        -------
        float
        """
        tol = self.m_rtol if e.quantity == "M" else self.q_rtol
        if not self._across(e):
            return tol
        declared = {s.name: s.precision for s in specs()}  # a float32 engine's round-off is no difference
        tol = max([tol, *(declared.get(name, 0.0) for name in (e.engine, e.route.rpartition("@")[2]))])
        return max(tol, self.rtol) if self.rtol is not None else tol

    @staticmethod
    def _across(e: Discrepancy) -> bool:
        """True where two engines' readings of the model meet: the engines, or a route against the other engine."""
        return e.formula == ENGINE_PARITY or e.route.rpartition("@")[2] != e.engine

    def failures(self) -> list[Discrepancy]:
        """Comparisons of ``exact`` (every route) and of the engines with each other beyond tolerance."""
        out = []
        for e in self.errors:
            if e.formula not in ("exact", ENGINE_PARITY):
                continue
            if not e.max_rel_error <= self.tolerance(e):
                out.append(e)
        return out

    @property
    def ok(self) -> bool:
        """True when ``exact`` agrees with both engines by every route, the engines agree, and so on.

        Every engine the user named must have checked the model too (:meth:`unmade` is empty).
        """
        gravity = self.gravity is None or self.gravity.agrees  # the same robot in the same world
        return "exact" not in self.refusals and not self.failures() and not self.unmade() and gravity

    def unmade(self) -> list[Finding]:
        """The checks asked for and not made: an engine the user named could not check the model."""
        return [f for f in self.findings if f.kind is Kind.ENGINE_UNABLE]

    def reason(self, cli: bool = False) -> str:
        """One line: why the check failed, or ``""``.

        Parameters
        ----------
        cli : bool
            Name an option as the command line spells it (``--rtol``); by default as Python does (``rtol=``).

        Returns
        -------
        str
        """
        if self.unmade():
            return f"{self.model}: " + "; ".join(f.message() for f in self.unmade())
        if "exact" in self.refusals:
            return f"{self.model}: exact refused: {self.refusals['exact']}"
        bad = self.failures()
        if not bad:
            return f"{self.model}: {reason_words(self.gravity)}" if self.gravity is not None else ""
        e = max(bad, key=lambda d: d.max_rel_error / self.tolerance(d))
        tol = self.tolerance(e)
        if all(self._across(d) for d in bad):  # only where the engines' readings meet: a file's rounding?
            from koenig_check.diagnosis.reason import rounding_hint

            worst = max(bad, key=lambda d: d.max_rel_error)
            hint = rounding_hint(worst.max_rel_error, max(self.tolerance(d) for d in bad), cli=cli)
            if hint:
                return f"{self.model}: {hint}"
        who = "engines disagree" if e.formula == ENGINE_PARITY else f"exact disagrees with an engine by {e.route}"
        return (
            f"{self.model}: {who}: {e.quantity} of {e.route} against {e.engine} off by {e.max_rel_error:.3g} "
            f"relative (tolerance {tol:g}) at pose {e.max_pose}, worst entry {self.entry_name(e)} "
            f"({e.worst_entry_error:+.3g})"
        )

    def entry_name(self, e: Discrepancy) -> str:
        """Name the worst entry of a discrepancy by its dofs."""
        return ",".join(self.dof_names[k] for k in e.worst_entry)


def _random_accelerations(nv: int, n: int, seed: int) -> np.ndarray:
    return np.random.default_rng([seed, 9]).normal(size=(n, nv))


def dynamics_of_pair(
    pair: LoadedModel,
    qpos: np.ndarray,
    qvel: np.ndarray,
    qacc: np.ndarray,
    formulas: list[str] | None = None,
    m_rtol: float = M_RTOL,
    q_rtol: float = Q_RTOL,
) -> DynamicsResult:
    """Run every route for every formula on given canonical states of a loaded model.

    Parameters
    ----------
    pair : LoadedModel
    qpos : ndarray, shape (P, nq)
    qvel, qacc : ndarray, shape (P, nv)
    formulas : list of str, optional
        Default: every formula; ``exact`` is always included (the verdict needs it).
    m_rtol, q_rtol : float

    Returns
    -------
    DynamicsResult
    """
    names = list(FORMULAS) if formulas is None else list(formulas)
    unknown = [n for n in names if n not in FORMULAS]
    if unknown:
        raise ValueError(f"unknown formulas {unknown}; known: {list(FORMULAS)}")
    if "exact" not in names:
        names.insert(0, "exact")
    qpos, qvel, qacc = (np.atleast_2d(np.asarray(x, dtype=float)) for x in (qpos, qvel, qacc))
    mj_model = pair.mujoco.model
    result = DynamicsResult(
        model=pair.path,
        qpos=qpos,
        qvel=qvel,
        qacc=qacc,
        dof_names=tuple(mujoco_coordinate_names(mj_model)[1]),
        m_rtol=m_rtol,
        q_rtol=q_rtol,
        notes=list(pair.notes),
        findings=list(pair.findings),
    )
    engines = {name: pair.engines[name] for name in ENGINES}
    for name, eng in engines.items():
        result.engine_mass[name] = rigid_mass_matrix(eng, qpos)
        result.engine_forces[name] = rigid_inertia_forces(eng, qpos, qvel, qacc)
    for name in names:
        try:
            for source, eng in engines.items():
                energy = FormulaEnergy(name, eng)
                M = implied_mass_matrix(energy, qpos)
                Q = lagrange_inertia_forces(energy, mj_model, qpos, qvel, qacc)
                result.routes[(name, f"lagrange@{source}")] = RouteResult(M, Q)
        except (PathDependentError, NotPlaneParallelError, ValueError) as err:
            if isinstance(err, ValueError) and not isinstance(err, KoenigCheckError) and name != "point_masses":
                raise  # only point_masses refuses by ValueError (a non-physical inertia has no point set)
            result.routes = {k: v for k, v in result.routes.items() if k[0] != name}
            result.refusals[name] = one_line(err)
            continue
        if name == "exact":
            result.routes[(name, "kane@mujoco")] = RouteResult(*kane_mujoco(pair.mujoco, qpos, qvel, qacc))
            result.routes[(name, "kane@pinocchio")] = RouteResult(*kane_pinocchio(pair.pinocchio, qpos, qvel, qacc))
    for (name, route), r in result.routes.items():
        for engine in ENGINES:
            result.errors.append(discrepancy(r.M, result.engine_mass[engine], name, route, engine))
            result.errors.append(discrepancy(r.Q, result.engine_forces[engine], name, route, engine))
    first, second = ENGINES
    result.errors.append(
        discrepancy(result.engine_mass[first], result.engine_mass[second], ENGINE_PARITY, first, second)
    )
    result.errors.append(
        discrepancy(result.engine_forces[first], result.engine_forces[second], ENGINE_PARITY, first, second)
    )
    return result


@suggest_keywords
def dynamics(
    model: str | os.PathLike[str],
    n_poses: int = 5,
    seed: int = 0,
    formulas: list[str] | None = None,
    m_rtol: float = M_RTOL,
    q_rtol: float = Q_RTOL,
    velocity_scale: float = 1.0,
    *,
    rtol: float | None = None,
    load_options: LoadOptions | None = None,
    floating: bool | None = None,
    balance_inertia: bool | None = None,
    repair_inertia: bool | None = None,
    pinocchio_model: str | os.PathLike[str] | None = None,
    allow_coupled: bool | None = None,
    engines: Sequence[str] | None = None,
    xacro_args: Mapping[str, Any] | Sequence[str] | None = None,
) -> DynamicsResult:
    """Mass matrix and generalized inertia forces implied by each energy formula, against both engines.

    Parameters
    ----------
    model : str or path
        A model file or a name from ``koenig-check models``.
    n_poses : int
        Random poses (within joint limits), velocities and accelerations (normal, std ``velocity_scale``).
    seed : int
    formulas : list of str, optional
        Default: every formula (``exact`` is always included).
    m_rtol, q_rtol : float
        Tolerances of the verdict on ``exact`` (per-pose norm-relative error of ``M`` and ``Q*``): how closely
        the routes (polarization, Lagrange's finite differences, Kane) must reproduce an engine.
    velocity_scale : float
    rtol : float, optional
        How closely the two engines' readings of the model must agree: the tolerance of the engines against
        each other and of a route on one engine's states against the other engine, when it is larger than
        ``m_rtol`` / ``q_rtol``: ``1e-5`` for a twin file written at 6 significant digits (each number rounded by up
        to 5e-6 of itself; MuJoCo and Pinocchio then differ by about 1e-6, more than ``1e-6`` allows).  Default: no
        more than ``m_rtol`` / ``q_rtol``.
    load_options : LoadOptions, optional
        How the model is loaded; the load keywords below override its fields.
    floating, balance_inertia, repair_inertia, pinocchio_model, allow_coupled, engines, xacro_args
        The fields of :class:`koenig_check.engines.load_options.LoadOptions` (``None`` keeps the value of
        ``load_options``): e.g. ``repair_inertia=True`` loads inertias MuJoCo refuses;
        ``engines=("mujoco", "pinocchio", "drake")`` adds Drake's column (by default Drake, when installed,
        only where MuJoCo and Pinocchio disagree).  ``allow_coupled`` is a deprecated no-op.

    Returns
    -------
    DynamicsResult
        ``result.routes[(formula, route)].M`` / ``.Q``, ``result.engine_mass`` / ``engine_forces``,
        ``result.errors`` (arrays of per-pose relative errors), ``result.ok``, ``result.reason()``.

    Raises
    ------
    TypeError
        A keyword :func:`dynamics` does not take (the message names the closest one) or a wrong type.
    ValueError
        An argument out of range, before the model is loaded.
    """
    from koenig_check.arguments import check_dynamics_arguments, check_tolerance
    from koenig_check.engines.load_options import load_options_from
    from koenig_check.engines.registry import check_engines

    given = dict(locals())
    check_dynamics_arguments(n_poses, seed, formulas, m_rtol, q_rtol, velocity_scale)
    if rtol is not None:
        check_tolerance(rtol, "rtol")
    options = load_options_from(load_options, {n: given[n] for n in LoadOptions.names() if given[n] is not None})
    check_engines(options.engines)
    pair = load_model(model, options)  # every load option, one definition (repair_inertia included)
    poses = random_poses(pair.mujoco.model, n_poses, seed=seed, velocity_scale=velocity_scale)
    qacc = velocity_scale * _random_accelerations(pair.mujoco.nv, n_poses, seed)
    result = dynamics_of_pair(pair, poses.qpos, poses.qvel, qacc, formulas, m_rtol, q_rtol)
    result.rtol = rtol
    add_engine_columns(result, pair, pair.options.engines, ENGINE_PARITY)  # "all" resolved for the model's format
    tolerance = rtol if rtol is not None else M_RTOL
    result.gravity, result.full_inverse_dynamics = gravity_columns(pair, poses.qpos, poses.qvel, qacc, tolerance)
    return result
