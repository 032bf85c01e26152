"""Engine adapters: load one model file into MuJoCo and Pinocchio and put both in the same state.

Public API
----------
``load_model(path_or_name, floating=False, balance_inertia=False, fmt=None, pinocchio_source=None,
allow_coupled=False, check=True) -> ModelPair``
    ``pair.mujoco`` and ``pair.pinocchio`` answer the same methods for canonical (MuJoCo-layout)
    states: ``segment_states``, ``point_velocities``, ``kinetic_energy``, ``mass_matrix``,
    ``inverse_dynamics``; ``pair.state_map`` converts states; ``pair.notes`` says what was changed
    or noticed while loading and what each engine includes.
``list_models()``, ``resolve_model()``
    Names of the project's models and of every example-robot-data URDF.
``random_states(model, n, seed)``
    Seeded random canonical states.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from koenig_check.causes import explain_load_failures
from koenig_check.engines.coupling import coupled_joints
from koenig_check.engines.energy import EnergyParts, self_consistency
from koenig_check.engines.errors import (
    CoupledJointsError,
    InertiaError,
    JointMismatch,
    ModelLoadError,
    NoMovingSegmentError,
)
from koenig_check.engines.finite import check_finite, check_segments
from koenig_check.engines.mujoco_engine import MujocoEngine
from koenig_check.engines.mujoco_loader import ROOT_JOINT_NAME, load_mujoco, root_free_joint
from koenig_check.engines.pinocchio_engine import PinocchioEngine
from koenig_check.engines.pinocchio_loader import load_pinocchio
from koenig_check.engines.sampling import random_states
from koenig_check.engines.sources import ModelSource, list_models, resolve_model
from koenig_check.engines.state_map import StateMap, build_state_map
from koenig_check.validate import preflight

__all__ = [
    "ROOT_JOINT_NAME",
    "CoupledJointsError",
    "EnergyParts",
    "InertiaError",
    "JointMismatch",
    "ModelLoadError",
    "ModelPair",
    "ModelSource",
    "MujocoEngine",
    "NoMovingSegmentError",
    "PinocchioEngine",
    "StateMap",
    "list_models",
    "load_model",
    "random_states",
    "resolve_model",
]

#: Number of seeded random states the self-consistency checks run on at load time.
CONSISTENCY_POSES = 3
#: Tolerance (rotation entries, metres) under which both engines place a segment identically.
POSE_ATOL = 1e-9


@dataclass
class ModelPair:
    """One model file loaded in both engines.

    Parameters
    ----------
    source : ModelSource
    mujoco : MujocoEngine
    pinocchio : PinocchioEngine
    state_map : StateMap
    floating : bool
    balance_inertia : bool
    notes : list of str
        Load notes of both engines, the state map's notes and the engines' self-consistency
        findings, each prefixed with the engine concerned.
    findings : list of str
        The self-consistency part of ``notes`` alone.
    import_differences : dict
        Segment name -> reasons the engines were given different mass properties for it (empty
        when both engines load the file's values).
    """

    source: ModelSource
    mujoco: MujocoEngine
    pinocchio: PinocchioEngine
    state_map: StateMap
    floating: bool = False
    balance_inertia: bool = False
    notes: list[str] = field(default_factory=list)
    findings: list[str] = field(default_factory=list)
    import_differences: dict[str, list[str]] = field(default_factory=dict)

    @property
    def path(self) -> str:
        """The model file."""
        return str(self.source.path)

    @property
    def engines(self) -> tuple[MujocoEngine, PinocchioEngine]:
        """Both engine models, MuJoCo first."""
        return (self.mujoco, self.pinocchio)


def _armature_notes(mj: MujocoEngine, pn: PinocchioEngine, state_map: StateMap) -> list[str]:
    """Compare the armature each engine was given, joint by joint (canonical dofs)."""
    arm_pin = np.zeros(state_map.nv)
    arm_pin[state_map.velocity_permutation[1]] = np.asarray(pn.model.armature)[state_map.velocity_permutation[0]]
    arm_mj = np.asarray(mj.model.dof_armature)
    width = {"free": 6, "ball": 3}
    differ = sorted(
        p.name
        for p in state_map.pairs
        if not np.allclose(*(a[p.vadr : p.vadr + width.get(p.kind, 1)] for a in (arm_mj, arm_pin)), rtol=1e-12)
    )
    if not differ:
        return []
    pairs = {p.name: p for p in state_map.pairs}
    detail = ", ".join(f"{n}: {arm_mj[pairs[n].vadr]:g} vs {arm_pin[pairs[n].vadr]:g}" for n in differ)
    return [f"armature differs between the engines (MuJoCo vs Pinocchio): {detail}"]


def _pose_notes(mj: MujocoEngine, pn: PinocchioEngine) -> list[str]:
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
        f"segment poses differ between the engines at qpos0 (max rotation entry {d_rot.max():.3g}, "
        f"max COM distance {d_com.max():.3g} m) for {len(bad)} segment(s): {bad[:8]}"
    ]


@explain_load_failures
def load_model(
    path_or_name: str | os.PathLike[str],
    floating: bool = False,
    balance_inertia: bool = False,
    fmt: str | None = None,
    pinocchio_source: str | os.PathLike[str] | None = None,
    allow_coupled: bool = False,
    check: bool = True,
) -> ModelPair:
    """Load a model file (or a named model) into MuJoCo and Pinocchio.

    Parameters
    ----------
    path_or_name : str or path
        A file, or a name from :func:`list_models`.
    floating : bool
        Give a fixed-base model a free root joint named :data:`ROOT_JOINT_NAME` (a file whose
        single root body already has a free joint is left as it is).
    balance_inertia : bool
        Let MuJoCo load inertias violating ``A + B >= C`` (``balanceinertia``); the notes record the
        change per link (Pinocchio keeps the file's inertia).
    fmt : {"mjcf", "urdf"}, optional
        Disambiguates a project model name.
    pinocchio_source : str or path, optional
        Load Pinocchio from this other file of the same mechanism (e.g. the URDF twin of an
        MJCF); MuJoCo loads ``path_or_name``.
    allow_coupled : bool
        Load a model with mimic joints, loops or joint/tendon equality constraints anyway; both
        engines then treat its joints as independent (recorded in the notes).  Refused by default.
    check : bool
        Run the engines' self-consistency checks on a few random states and record the findings.

    Returns
    -------
    ModelPair

    Raises
    ------
    ModelLoadError, InertiaError
        If an engine cannot load the file, or the model couples its joints (one-line message
        naming the file and the element).
    koenig_check.validate.ModelFileError
        If the file fails the pre-flight checks (missing, empty, not XML, DOCTYPE...).
    JointMismatch
        If the engines' joints cannot be paired by name.

    Notes
    -----
    Pinocchio gets a free flyer exactly when MuJoCo's model ends with a free joint on its single
    root body, named like it, so the two engines' free joints always pair.
    """
    source = resolve_model(path_or_name, fmt)
    pin_source = source if pinocchio_source is None else resolve_model(pinocchio_source)
    for s in {source.path: source, pin_source.path: pin_source}.values():
        preflight(s.path)
    mj_model, mj_notes, mj_diffs = load_mujoco(source, floating=floating, balance_inertia=balance_inertia)
    coupled = coupled_joints(source, mj_model)
    if coupled and not allow_coupled:
        raise CoupledJointsError(
            f"{source.path}: coupled joints are not supported: {'; '.join(coupled)} (both engines would treat "
            "the joints as independent; --allow-coupled (allow_coupled=True) loads it anyway)"
        )
    if coupled:
        mj_notes.append(f"coupled joints loaded as independent joints (allow_coupled=True): {coupled}")
    pin_model, pin_notes = load_pinocchio(pin_source, root_joint=root_free_joint(mj_model))
    if pin_source is not source:
        pin_notes.insert(0, f"pinocchio: loaded from {pin_source.path} (MuJoCo from {source.path})")
    check_finite(mj_model, pin_model, str(source.path))
    if mj_model.nv == 0:
        raise NoMovingSegmentError(
            f"{source.path}: nothing moves (no joint), so there is nothing to compare; not an engine error "
            "(--floating, floating=True, gives the root body a free joint)"
        )
    state_map = build_state_map(mj_model, pin_model, str(source.path))
    mj = MujocoEngine(mj_model, source.path, mj_notes, mj_diffs)
    pn = PinocchioEngine(pin_model, state_map, pin_source.path, pin_notes + state_map.notes)
    pn.notes += check_segments(
        (mj, pn), mj_model.qpos0, str(source.path), frozenset({"pinocchio"}) if balance_inertia else frozenset()
    )
    notes = mj.notes + pn.notes + _armature_notes(mj, pn, state_map) + _pose_notes(mj, pn)
    if set(mj.segment_names) != set(pn.segment_names):
        only_mj = sorted(set(mj.segment_names) - set(pn.segment_names))
        only_pin = sorted(set(pn.segment_names) - set(mj.segment_names))
        notes.append(f"segments differ between engines: only MuJoCo {only_mj}, only Pinocchio {only_pin}")
    findings: list[str] = []
    if check:
        qpos, qvel = random_states(mj_model, CONSISTENCY_POSES, seed=12345)
        for engine in (mj, pn):
            found = self_consistency(engine, qpos, qvel)
            engine.notes.extend(found)
            findings.extend(found)
    return ModelPair(
        source, mj, pn, state_map, floating, balance_inertia, notes + findings, findings, dict(mj.import_differences)
    )
