"""Loading a model file into MuJoCo and Pinocchio, and attaching optional engines: :class:`LoadedModel`."""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from koenig_check.engines import registry
from koenig_check.engines.base import Engine
from koenig_check.engines.coupling import coupling_findings
from koenig_check.engines.energy import self_consistency
from koenig_check.engines.errors import (
    EngineUnavailableError,
    NoMassError,
    NoMovingSegmentError,
)
from koenig_check.engines.finite import check_finite, check_segments
from koenig_check.engines.load_options import ALLOW_COUPLED_DEPRECATION, LoadOptions
from koenig_check.engines.mujoco.adapter import MujocoEngine
from koenig_check.engines.mujoco.loader import load_mujoco, root_free_joint
from koenig_check.engines.parser_traps import explain_load_failures, moving_advice
from koenig_check.engines.pinocchio.adapter import PinocchioEngine
from koenig_check.engines.pinocchio.loader import load_pinocchio
from koenig_check.engines.pinocchio.state_map import StateMap, build_state_map
from koenig_check.engines.sampling import random_states
from koenig_check.engines.specs import parity_pair
from koenig_check.exceptions import KoenigCheckError, quote_engine
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.validate import preflight
from koenig_check.roundoff import ROUNDOFF
from koenig_check.sources.catalogue import ModelSource, resolve_model

#: Number of seeded random states the self-consistency checks run on at load time.
CONSISTENCY_POSES = 3
#: Tolerance (rotation entries, metres) under which both engines place a segment identically.
POSE_ATOL = 1e-9


@dataclass
class LoadedModel:
    """One model file loaded in MuJoCo and Pinocchio, and in the optional engines attached to it.

    Parameters
    ----------
    source : ModelSource
    mujoco : MujocoEngine
    pinocchio : PinocchioEngine
    state_map : StateMap
        Canonical <-> Pinocchio states.
    options : LoadOptions
        How it was loaded.
    findings : list of Finding
        Everything learned while loading: loading decisions, couplings, inertias MuJoCo's compiler
        or a repair changed (with the segments concerned), armature and pose differences between
        the engines, and each engine's self-consistency facts and inconsistencies.

    Attributes
    ----------
    engines : dict of str to Engine
        Every engine the model is loaded in, by name, MuJoCo and Pinocchio first, then the optional
        engines attached (:meth:`attach`).
    optional_findings : list of Finding
        What attaching the optional engines found (their load findings and the constructs their parsers
        misread), or why an engine could not be attached (``ENGINE_NOT_USED``).
    """

    source: ModelSource
    mujoco: MujocoEngine
    pinocchio: PinocchioEngine
    state_map: StateMap
    options: LoadOptions = field(default_factory=LoadOptions)
    findings: list[Finding] = field(default_factory=list)
    engines: dict[str, Engine] = field(init=False)
    optional_findings: list[Finding] = field(init=False, default_factory=list)
    _refused: dict[str, Finding] = field(init=False, default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        reference, other = parity_pair()
        self.engines = {reference: self.mujoco, other: self.pinocchio}

    @property
    def path(self) -> str:
        """The model file."""
        return str(self.source.path)

    @property
    def floating(self) -> bool:
        """Whether a free base was asked for."""
        return self.options.floating

    @property
    def notes(self) -> list[str]:
        """The findings rendered for people, one line each (:meth:`Finding.message`)."""
        return [f.message() for f in self.findings]

    @property
    def import_differences(self) -> dict[str, list[Finding]]:
        """Segment -> the findings by which the engines were given different mass properties for it."""
        out: dict[str, list[Finding]] = {}
        for f in self.findings:
            if f.affects_energy and f.kind in (Kind.REPAIR, Kind.COMPILER):
                for segment in f.segments or ("(static)",):
                    out.setdefault(segment, []).append(f)
        return out

    def attach(self, name: str) -> Engine | None:
        """Load an optional engine on this model (once), recording what it found or why it cannot.

        Parameters
        ----------
        name : str
            An optional engine (:func:`koenig_check.engines.registry.optional`).

        Returns
        -------
        Engine or None
            None when the engine cannot check this model; :attr:`optional_findings` then holds its reason.
        """
        if name in self.engines:
            return self.engines[name]
        if name in self._refused:
            return None
        engine, found = registry.attach(name, self)
        self.optional_findings.extend(found)
        if engine is None:
            self._refused[name] = next((f for f in found if f.kind is Kind.ENGINE_NOT_USED), found[0])
            return None
        self.engines[name] = engine
        return engine

    def refusal(self, name: str) -> Finding | None:
        """Why an optional engine could not be attached (None when it was, or was not tried).

        Parameters
        ----------
        name : str

        Returns
        -------
        Finding or None
        """
        return self._refused.get(name)

    def engine(self, name: str) -> Engine:
        """An engine of this model by name, attaching an optional one on first use.

        Parameters
        ----------
        name : str

        Returns
        -------
        Engine

        Raises
        ------
        EngineUnavailableError
            The engine cannot check this model; the message is the engine's own reason, naming the file.
        """
        engine = self.attach(name)
        if engine is None:
            why = self._refused[name]
            raise EngineUnavailableError(f"{self.path}: {why.message()}", engine=name)
        return engine


def _armature_findings(mj: MujocoEngine, pn: PinocchioEngine, state_map: StateMap) -> list[Finding]:
    """Compare the armature each engine was given, joint by joint (canonical dofs)."""
    arm_pin = np.zeros(state_map.nv)
    arm_pin[state_map.velocity_permutation[1]] = np.asarray(pn.model.armature)[state_map.velocity_permutation[0]]
    arm_mj = np.asarray(mj.model.dof_armature)
    width = {"free": 6, "ball": 3}
    out = []
    for p in state_map.pairs:
        a, b = (x[p.vadr : p.vadr + width.get(p.kind, 1)] for x in (arm_mj, arm_pin))
        if not np.allclose(a, b, rtol=1e-12):
            out.append(
                Finding(
                    Kind.ARMATURE,
                    "both",
                    f"joint {p.name}",
                    "armature differs between the engines",
                    dict(zip(parity_pair(), (float(a[0]), float(b[0])), strict=True)),
                    affects_energy=True,
                    segments=(p.name,),
                )
            )
    return out


def _pose_findings(mj: MujocoEngine, pn: PinocchioEngine) -> list[Finding]:
    """Compare where both engines put each segment at MuJoCo's ``qpos0`` (frame-only differences)."""
    common = [n for n in mj.segment_names if n in pn.segment_names]
    if not common:
        return []
    qpos0 = np.asarray(mj.model.qpos0, dtype=float)[None]
    zero = np.zeros((1, mj.nv))
    sm = mj.segment_states(qpos0, zero).select(segments=common)
    sp = pn.segment_states(qpos0, zero).select(segments=common)
    d_rot = np.abs(sm.rotation - sp.rotation).max(axis=(0, 2, 3))
    d_com = np.linalg.norm(sm.com - sp.com, axis=-1).max(axis=0)
    bad = [n for n, a, b in zip(common, d_rot, d_com, strict=True) if a > POSE_ATOL or b > POSE_ATOL]
    if not bad:
        return []
    return [
        Finding(
            Kind.FRAME,
            "both",
            "segments " + ", ".join(bad[:8]) + (" …" if len(bad) > 8 else ""),
            "segment poses differ between the engines at qpos0",
            {"max rotation entry": float(d_rot.max()), "max COM distance (m)": float(d_com.max())},
            segments=tuple(bad),
        )
    ]


#: A moving mass (kg) at most this, in every engine, is no mass: round-off, or MuJoCo's minimum masses of a repair.
NO_MASS = ROUNDOFF


def _check_moving_mass(mj_model: Any, pin_model: Any, path: str, repaired: bool) -> None:
    """Refuse a model whose moving bodies have no mass in any engine: there is no kinetic energy to compare."""
    moving = [b for b in range(1, mj_model.nbody) if mj_model.body_weldid[b] != 0]
    mj_mass = float(np.sum(mj_model.body_mass[moving]))
    pin_mass = float(sum(pin_model.inertias[i].mass for i in range(1, pin_model.njoints)))
    if max(mj_mass, pin_mass) > NO_MASS:
        return
    links = tuple(mj_model.body(b).name or f"body{b}" for b in moving)
    shown = ", ".join(links[:6]) + (f" (+{len(links) - 6} more)" if len(links) > 6 else "")
    how = "; MuJoCo holds only the minimum masses of --repair-inertia" if repaired else ""
    raise NoMassError(
        f"{path}: no mass to compare: no moving link has mass ({shown}: MuJoCo {mj_mass:.3g} kg, "
        f"Pinocchio {pin_mass:.3g} kg{how}); give the links an <inertial>",
        links,
    )


@explain_load_failures
def load_model(
    path_or_name: str | os.PathLike[str],
    options: LoadOptions | None = None,
    *,
    fmt: str | None = None,
    check: bool = True,
    **legacy: Any,
) -> LoadedModel:
    """Load a model file (or a named model) into MuJoCo and Pinocchio.

    Parameters
    ----------
    path_or_name : str or path
        A file, or a name from :func:`list_models`.
    options : LoadOptions, optional
        How to load it (floating base, inertia balancing or repair, a separate file for
        Pinocchio).  The same options are accepted as keywords (``floating=True``, ...;
        ``pinocchio_source`` is the older name of ``pinocchio_model``).
    fmt : {"mjcf", "urdf"}, optional
        Disambiguates a project model name.
    check : bool
        Run the engines' self-consistency checks on a few random states and record the findings.

    Returns
    -------
    LoadedModel

    Raises
    ------
    ModelLoadError, InertiaError
        If an engine cannot load the file (one-line message naming the file, the element and
        the engine's whole reason; for an inertia MuJoCo refuses, the option that would load it).
    koenig_check.modelfile.validate.ModelFileError
        If the file fails the pre-flight checks (missing, empty, not XML, DOCTYPE...).
    JointMismatch
        If the engines' joints cannot be paired by name.

    Notes
    -----
    Coupled joints (URDF mimic, MJCF joint/tendon equalities, connect and weld constraints) are
    loaded and recorded as ``COUPLING`` findings: the kinetic energy is defined on the tree's
    coordinates.  ``allow_coupled`` is a deprecated no-op.

    Pinocchio gets a free flyer exactly when MuJoCo's model ends with a free joint on its single
    root body, named like it, so the two engines' free joints always pair.
    """
    if "pinocchio_source" in legacy:
        legacy["pinocchio_model"] = legacy.pop("pinocchio_source")
    unknown = sorted(set(legacy) - set(LoadOptions.names()))
    if unknown:
        raise TypeError(f"load_model() got unexpected keyword argument(s) {unknown}")
    opts = options if options is not None else LoadOptions()
    if legacy:
        opts = replace(opts, **legacy)
    if opts.allow_coupled:
        warnings.warn(ALLOW_COUPLED_DEPRECATION, DeprecationWarning, stacklevel=2)
    source = resolve_model(path_or_name, fmt, xacro_args=opts.xacro_args)
    pin_source = (
        source if opts.pinocchio_model is None else resolve_model(opts.pinocchio_model, xacro_args=opts.xacro_args)
    )
    for s in {source.path: source, pin_source.path: pin_source}.values():
        preflight(s.path)
    reference, other = parity_pair()  # loaded below in MuJoCo and Pinocchio
    try:
        mj_model, mj_findings, body_findings = load_mujoco(
            source, floating=opts.floating, balance_inertia=opts.balance_inertia, repair_inertia=opts.repair_inertia
        )
    except KoenigCheckError as refused:  # MuJoCo's own words kept with ours (the exception it raised)
        quote_engine(refused, "MuJoCo")
        raise
    try:
        pin_model, pin_findings = load_pinocchio(pin_source, root_joint=root_free_joint(mj_model))
    except KoenigCheckError as refused:
        quote_engine(refused, "Pinocchio")
        raise
    if pin_source is not source:
        pin_findings.insert(
            0,
            Finding(
                Kind.LOAD,
                other,
                f"file {pin_source.path.name}",
                "Pinocchio loaded from another file than MuJoCo",
                {other: str(pin_source.path), reference: str(source.path)},
            ),
        )
    large_values = check_finite(mj_model, pin_model, str(source.path), (reference, other))
    if mj_model.nv == 0:
        advice = moving_advice(mj_model, urdf=source.path.suffix.lower() == ".urdf")
        err = NoMovingSegmentError(
            f"{source.path}: nothing moves (no joint), so there is nothing to compare; not an engine error ({advice})"
        )
        err.advice = advice  # the cause explain_load_failures attaches says the same
        raise err
    _check_moving_mass(mj_model, pin_model, str(source.path), repaired=opts.repair_inertia)
    state_map = build_state_map(mj_model, pin_model, str(source.path))
    mj = MujocoEngine(mj_model, source.path, mj_findings, body_findings)
    pn = PinocchioEngine(pin_model, state_map, pin_source.path, pin_findings + state_map.findings)
    tolerate = frozenset({other}) if opts.balance_inertia or opts.repair_inertia else frozenset()
    pn.findings += check_segments((mj, pn), mj_model.qpos0, str(source.path), tolerate)
    findings = mj.findings + pn.findings + large_values + coupling_findings(source, mj_model)
    findings += _armature_findings(mj, pn, state_map) + _pose_findings(mj, pn)
    if set(mj.segment_names) != set(pn.segment_names):
        only_mj = sorted(set(mj.segment_names) - set(pn.segment_names))
        only_pin = sorted(set(pn.segment_names) - set(mj.segment_names))
        findings.append(
            Finding(
                Kind.SEGMENTS,
                "both",
                "segments " + ", ".join(only_mj + only_pin),
                "segments differ between the engines",
                {"only mujoco": only_mj, "only pinocchio": only_pin},
                affects_energy=True,
                segments=tuple(only_mj + only_pin),
            )
        )
    if check:
        qpos, qvel = random_states(mj_model, CONSISTENCY_POSES, seed=12345)
        for engine in (mj, pn):
            found = self_consistency(engine, qpos, qvel)
            engine.findings.extend(found)
            findings.extend(found)
    engines, left_out = registry.engines_for(opts.engines, source.format)  # --engines all: those that read it
    loaded = LoadedModel(source, mj, pn, state_map, replace(opts, engines=engines), findings)
    loaded.optional_findings += left_out
    return loaded
