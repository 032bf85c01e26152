"""The one diagnosis of a loaded model: what the API, the CLI and the testing helper all call.

:func:`diagnose` gathers what is known about why the engines may see different robots in one file: the
engines' own load findings, the import parity (computed once), the optional engines where the checker's
policy uses them (:mod:`koenig_check.diagnosis.policy`), with three engines or more the verdicts that say
which engine departs (:mod:`koenig_check.diagnosis.three_way`), and the gravity verdict
(:mod:`koenig_check.gravity`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.diagnosis import policy, three_way
from koenig_check.diagnosis.engine_limits import limited_engines, unable_findings
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.parity_report import PARITY_RTOL, ParityReport
from koenig_check.engines import registry
from koenig_check.engines.catalogue import applies
from koenig_check.engines.cross_readings import cross_readings
from koenig_check.exceptions import one_line
from koenig_check.findings import Finding
from koenig_check.gravity import GravityParity, gravity_parity


@dataclass
class Diagnosis:
    """What is known about one model, typed.

    Attributes
    ----------
    findings : list of Finding
        The three-engine verdicts first, then the model's load findings, the import differences of
        :attr:`parity`, what the optional engines found or why they were not used, and the checks the user
        asked for that could not be made (``ENGINE_UNABLE``).
    parity : ParityReport
        Import parity of MuJoCo and Pinocchio.
    verdicts : list of Finding
        The verdicts of three engines or more (empty without a third engine).
    engines : tuple of str
        The engines that checked the model.
    gravity : GravityParity or None
        The engines' gravity terms against MuJoCo's (its findings are in :attr:`findings` too).
    """

    findings: list[Finding] = field(default_factory=list)
    parity: ParityReport | None = None
    verdicts: list[Finding] = field(default_factory=list)
    engines: tuple[str, ...] = ()
    gravity: GravityParity | None = None

    @property
    def optional_findings(self) -> list[Finding]:
        """The findings about the optional engines (what they found, or why they were not used)."""
        return [f for f in self.findings if f.engine in registry.optional() and f not in self.verdicts]


def diagnose(
    model: Any,
    *,
    disagree: bool | None = None,
    qpos: np.ndarray | None = None,
    qvel: np.ndarray | None = None,
    rtol: float = PARITY_RTOL,
    include_armature: bool = True,
    energies: Mapping[str, Any] | None = None,
) -> Diagnosis:
    """Diagnose a loaded model: import parity, the optional engines where used, the three-engine verdicts.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel
        An optional engine the user named is attached already (it ran on every pose); one consulted by
        default is attached here when MuJoCo and Pinocchio disagree.
    disagree : bool, optional
        Whether MuJoCo and Pinocchio disagree on the model (their energies); by default, whether their
        import parity finds a difference.
    qpos, qvel : ndarray, shape (P, nq) and (P, nv), optional
        Canonical states on which the three engines' energies are compared (without them, only the
        mass properties at MuJoCo's ``qpos0`` are).
    rtol : float
        Relative tolerance of the import parity and of the verdicts.
    include_armature : bool
        Compare the engines' armature energies too.
    energies : mapping of str to energies, optional
        Per engine, its energies (``rigid``, ``armature``) at ``qpos``, ``qvel`` as the run computed them: not
        computed again (an engine attached here is asked for its own).

    Returns
    -------
    Diagnosis
    """
    parity = import_parity(model, rtol=rtol)
    if disagree is None:
        disagree = not parity.clean
    at = qpos if qpos is not None else np.asarray(model.mujoco.model.qpos0, dtype=float)[None]
    if not disagree:  # a gravity difference also calls for the optional engines' votes
        disagree = not gravity_parity(model, at, [], rtol, list(registry.required())).agrees
    engines = model.options.engines
    asked = policy.asked_for(engines)
    not_consulted = [f for f in policy.attach_engines(model, disagree) if f.engine not in asked]
    optional = model.optional_findings + not_consulted
    findings = [f for f in list(model.findings) + parity.as_findings() + optional if _applies(f)]
    findings += cross_readings(findings, model.engines, model.source.format)  # what the catalogue says they misread
    limits = limited_engines(findings, model.mujoco.model)  # engines given another robot: they do not vote
    voters = [name for name in model.engines if name not in limits]
    verdicts: list[Finding] = []
    if len(voters) >= 3:  # a majority can then say which engine departs
        verdicts = _verdicts(model, voters, parity, findings, (qpos, qvel, energies or {}), rtol, include_armature)
    parser = "URDF" if Path(model.path).suffix.lower() == ".urdf" else "MJCF"
    unmade = unable_findings(limits, policy.asked_for(engines), parser) + policy.unmade_checks(optional, engines)
    gravity = gravity_parity(model, at, findings, rtol, voters)  # engines given another robot do not vote
    findings += gravity.findings
    return Diagnosis(unmade + verdicts + findings, parity, verdicts, tuple(model.engines), gravity)


def _applies(f: Finding) -> bool:
    """A finding of a cause whose declared reading does not hold for the installed engine's version is dropped."""
    return not f.cause or applies(f.cause)


def _verdicts(
    model: Any,
    voters: list[str],
    parity: ParityReport,
    findings: list[Finding],
    sample: tuple[np.ndarray | None, np.ndarray | None, Mapping[str, Any]],
    rtol: float,
    include_armature: bool,
) -> list[Finding]:
    """Which of the ``voters`` departs: on the energies at the given states, on the mass properties at ``qpos0``.

    ``sample`` is the states and the energies the run computed there (an engine not run on them is asked here).
    """
    engines = {name: model.engines[name] for name in voters}
    qpos, qvel, known = sample
    out: list[Finding] = []
    if qpos is not None and qvel is not None:
        try:
            energies = {n: known[n] if n in known else e.kinetic_energy(qpos, qvel) for n, e in engines.items()}
        except ValueError as err:  # an engine produced an invalid state: name the file
            raise ValueError(f"{model.path}: {one_line(err)}") from err
        if not include_armature:
            energies = {n: _RigidOnly(k.rigid) for n, k in energies.items()}
        out += three_way.energy_verdicts(energies, findings, rtol)
    q0 = np.asarray(model.mujoco.model.qpos0, dtype=float)[None]
    zero = np.zeros((1, model.mujoco.nv))
    states = {name: e.segment_states(q0, zero) for name, e in engines.items()}
    if parity.frame_offset is not None:  # Pinocchio dropped a jointless root body's pose: compare in MuJoCo's world
        dropped = parity.frame_offset.engine
        states[dropped] = parity.frame_offset.segment_states(states[dropped])
    return out + three_way.import_verdicts(states, findings, rtol, parity.segment_labels)


@dataclass(frozen=True)
class _RigidOnly:
    """An engine's energies with the armature term left out of the comparison."""

    rigid: np.ndarray

    @property
    def armature(self) -> np.ndarray:
        return np.zeros_like(self.rigid)
