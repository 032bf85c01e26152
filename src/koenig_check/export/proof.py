"""The proof that an export is the same robot: each engine's own mass matrix and energy, on both files.

The independent route: every engine loads the original and the export separately; the original's random
canonical states are written in the export's layout by joint name (:mod:`~koenig_check.export.joint_pairing`);
per engine, the joint-space mass matrix with the armature removed, the rigid-body kinetic energy and the
inverse dynamics (gravity off, armature forces removed) of the export are compared at the same states with
MuJoCo's reading of the original (the reference: the robot MuJoCo simulates, which the export is written
from) and with the engine's own reading of the original (an engine that misreads the original is told apart
from an export that differs).  Per moving segment, mass, the centre of mass's distance from the joint and
the principal moments of inertia (quantities no choice of world frame changes) are compared as well, so
that a difference names the link at fault.
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import numpy as np

from koenig_check.engines import registry
from koenig_check.engines.base import Engine
from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.mujoco.loader import root_free_joint
from koenig_check.engines.sampling import random_states
from koenig_check.engines.specs import ALL
from koenig_check.export.engine_sides import EngineSide, load_side
from koenig_check.export.joint_pairing import JointPairing, pair_joints
from koenig_check.export.result import EngineProof, Proof, SegmentDifference
from koenig_check.export.unread_constructs import refusal_with_frames
from koenig_check.sources.catalogue import detect_format, resolve_model

#: A declared precision this coarse is a single-precision engine's (Newton's float32, 3e-5): by default the proof
#: leaves such an engine out where its round-off reaches the tolerance; named (``engines=``), it is compared at it.
#: A double-precision engine with a coarser reading of some quantity (PyBullet's diagonalized inertias, 3e-6) is
#: compared, at its declared precision.
SINGLE_PRECISION = 1e-5
#: Default relative tolerance of the proof.
PROOF_RTOL = 1e-9
#: Default number of seeded random poses.
PROOF_POSES = 10


def _relative(a: np.ndarray, b: np.ndarray, axes: tuple[int, ...]) -> np.ndarray:
    scale = np.abs(a).max(axis=axes)
    return np.abs(a - b).max(axis=axes) / np.where(scale > 0, scale, 1.0)


def _rigid_mass_matrix(adapter: Engine, qpos: np.ndarray) -> np.ndarray:
    return np.asarray(adapter.mass_matrix(qpos)) - np.asarray(adapter.armature_matrix(qpos))


def _differences(
    a: Engine,
    b: Engine,
    pairing: JointPairing,
    states: tuple[np.ndarray, np.ndarray],
    export_states: tuple[np.ndarray, np.ndarray],
) -> tuple[float, float, float]:
    """Max relative differences of the rigid mass matrix, the rigid energy and the rigid inverse dynamics.

    Adapter ``a`` reads the original, ``b`` the export; the inverse dynamics (gravity and passive forces
    off, armature forces removed) is evaluated at each state with the acceleration equal to the velocity.
    """
    (qpos, qvel), (qx, vx) = states, export_states
    od, xd = pairing.dof_original, pairing.dof_export
    m_a = _rigid_mass_matrix(a, qpos)[:, od][:, :, od]
    m_b = _rigid_mass_matrix(b, qx)[:, xd][:, :, xd]
    t_a = np.asarray(a.kinetic_energy(qpos, qvel).rigid)
    t_b = np.asarray(b.kinetic_energy(qx, vx).rigid)
    de = np.abs(t_a - t_b) / np.where(np.abs(t_a) > 0, np.abs(t_a), 1.0)
    f_a = np.asarray(a.inverse_dynamics(qpos, qvel, qvel)) - np.asarray(a.armature_forces(qpos, qvel, qvel))
    f_b = np.asarray(b.inverse_dynamics(qx, vx, vx)) - np.asarray(b.armature_forces(qx, vx, vx))
    di = _relative(f_a[:, od], f_b[:, xd], (1,))
    return float(_relative(m_a, m_b, (1, 2)).max()), float(de.max()), float(di.max())


def _energy_difference(mujoco_side: Engine, engine_side: Engine, states: tuple[np.ndarray, np.ndarray]) -> float:
    """Max over the states of ``|T_engine - T_mujoco| / |T_mujoco|``, the rigid energies of one file's two readings.

    The measure ``koenig-check compare`` gives the engines' gap (relative to MuJoCo's energy), so the two
    commands give one number for one gap at the same states.
    """
    t_a = np.asarray(mujoco_side.kinetic_energy(*states).rigid)
    t_b = np.asarray(engine_side.kinetic_energy(*states).rigid)
    return float((np.abs(t_b - t_a) / np.where(np.abs(t_a) > 0, np.abs(t_a), 1.0)).max())


def compare_engine(
    engine: str,
    original: EngineSide,
    export: EngineSide,
    pairing: JointPairing,
    states: tuple[np.ndarray, np.ndarray],
    rtol: float,
) -> tuple[EngineProof, list[SegmentDifference]]:
    """One engine's reading of the export against MuJoCo's reading of the original, at the same states.

    MuJoCo's reading of the original is the reference (the robot MuJoCo simulates, which the export is
    written from); the engine's own reading of the original is compared too (``own_reading``), so that an
    engine that reads the original differently from MuJoCo is told apart from an export that differs.

    Parameters
    ----------
    engine : str
    original, export : EngineSide
    pairing : JointPairing
    states : (qpos, qvel) in the original's canonical layout
    rtol : float

    Returns
    -------
    EngineProof, list of SegmentDifference
    """
    qpos, qvel = states
    if engine in export.refused:
        reason = refusal_with_frames(export.refused[engine], export.path, export.mj_model, engine)
        return EngineProof(engine, np.nan, np.nan, 0, False, f"cannot load the export: {reason}"), []
    reference, b = original.adapters[registry.reference()], export.adapters[engine]
    qx, vx = pairing.export_states(qpos, qvel, export.mj_model)
    dm, de, di = _differences(reference, b, pairing, states, (qx, vx))
    own = np.nan
    if engine in original.adapters:  # the engine's reading of the original against MuJoCo's, as compare measures
        own = _energy_difference(reference, original.adapters[engine], states)
    tolerance = max(rtol, registry.spec(engine).precision)  # an engine's declared round-off is no difference
    ok = max(dm, de, di) <= tolerance
    proof = EngineProof(engine, dm, de, int(qpos.shape[0]), ok, own_reading=own, inverse_dynamics=di)
    segments = _segments(engine, reference, b, export, (qpos[:1], qvel[:1]), (qx[:1], vx[:1]), original, tolerance)
    return proof, segments


def _segments(
    engine: str,
    a: Engine,
    b: Engine,
    export: EngineSide,
    state_a: tuple[np.ndarray, np.ndarray],
    state_b: tuple[np.ndarray, np.ndarray],
    original: EngineSide,
    rtol: float,
) -> list[SegmentDifference]:
    sa = a.segment_states(*state_a)
    sb = b.segment_states(*state_b)
    ib = {n: i for i, n in enumerate(sb.names)}
    root_a, root_b = root_free_joint(original.mj_model), root_free_joint(export.mj_model)
    names_x = mujoco_joint_names(export.mj_model)
    out = []
    extent = max(float(original.mj_model.stat.extent), 1e-9)
    # inertia differences are relative to the segment's largest moment, floored at a millionth of the model's
    # largest: a link with moments of 1e-15 kg m² (a massless frame) is round-off, not a difference
    floor = 1e-6 * max((float(np.linalg.eigvalsh(i).max()) for i in sa.inertia_body), default=0.0)
    for i, name in enumerate(sa.names):
        j = ib.get(root_b if name == root_a and root_b else name)
        if j is None:
            continue
        xname = sb.names[j]
        link = (
            export.mj_model.body(int(export.mj_model.jnt_bodyid[names_x.index(xname)])).name
            if xname in names_x
            else xname
        )
        moments_a = np.linalg.eigvalsh(sa.inertia_body[i])
        moments_b = np.linalg.eigvalsh(sb.inertia_body[j])
        arm_a = float(np.linalg.norm(sa.com[0, i] - sa.pole[0, i]))
        arm_b = float(np.linalg.norm(sb.com[0, j] - sb.pole[0, j]))
        checks = (
            ("mass", abs(sa.mass[i] - sb.mass[j]) / max(abs(sa.mass[i]), 1e-300), sa.mass[i], sb.mass[j]),
            ("COM distance from the joint", abs(arm_a - arm_b) / extent, arm_a, arm_b),
            (
                "principal moments of inertia",
                float(np.abs(moments_a - moments_b).max() / max(np.abs(moments_a).max(), floor, 1e-300)),
                float(moments_a[k := int(np.argmax(np.abs(moments_a - moments_b)))]),  # the moment that differs
                float(moments_b[k]),
            ),
        )
        for quantity, rel, va, vb in checks:
            if rel > rtol:
                out.append(SegmentDifference(engine, name, link, quantity, float(rel), float(va), float(vb)))
    return out


def export_options(
    original: LoadOptions, original_side: EngineSide, export_path: str | os.PathLike[str]
) -> LoadOptions:
    """How to load the export: a URDF of a robot with a free root gets a floating base.

    Parameters
    ----------
    original : LoadOptions
    original_side : EngineSide
    export_path : path

    Returns
    -------
    LoadOptions
    """
    floating = bool(root_free_joint(original_side.mj_model)) and detect_format(Path(export_path)) == "urdf"
    return replace(original, floating=floating, pinocchio_model=None, engines=None)


def _unread(engine: str, formats: tuple[str, ...]) -> str:
    """The formats among ``formats`` an engine's parser does not read, for people (``"MJCF"``)."""
    return " or ".join(dict.fromkeys(f.upper() for f in formats if f not in registry.spec(engine).formats))


def prove(
    original: str | os.PathLike[str],
    export: str | os.PathLike[str],
    options: LoadOptions | None = None,
    *,
    poses: int = PROOF_POSES,
    seed: int = 0,
    rtol: float = PROOF_RTOL,
    engines: tuple[str, ...] | None = None,
) -> Proof:
    """Load the original and the export in every engine and compare them at seeded random states.

    Parameters
    ----------
    original, export : path
        The original model file (or name) and the converted one.
    options : LoadOptions, optional
        How the original is loaded (``floating``, ``repair_inertia``, ``balance_inertia``); the export
        gets the same inertia options and a floating base where it is a URDF of a free-root robot.
    poses : int
    seed : int
    rtol : float
        Relative tolerance on the mass matrix, the energy and each segment's mass properties.
    engines : tuple of str, optional
        Default: every engine whose parser reads the export's format (its spec's ``formats``), but a
        single-precision engine (declared precision of :data:`SINGLE_PRECISION` or more, at or above ``rtol``) only
        where it is named; each compared where it loads both files.  Engines named here are asked for: one that
        cannot compare the files fails the proof.  ``("all",)`` (``--engines all``): every installed engine
        whose parser reads both files' formats, each asked for.

    Returns
    -------
    Proof
    """
    target = detect_format(Path(export))
    left_out: tuple[EngineProof, ...] = ()
    if engines is not None and tuple(engines) == (ALL,):  # every installed engine that reads both files, asked for
        source = resolve_model(original).format
        engines = tuple(n for n in registry.reading(target, installed_only=True) if n in registry.reading(source))
        left_out = tuple(
            EngineProof(
                n, np.nan, np.nan, 0, False, f"its parser does not read {_unread(n, (source, target))} (--engines all)"
            )
            for n in registry.optional()
            if n not in engines and registry.installed(n)
        )
    asked = () if engines is None else tuple(engines)
    if engines is None:  # every engine whose parser reads the export's format (PyBullet, iDynTree: URDF only)
        engines = tuple(  # a single-precision engine (Newton) only where named, or at a coarse rtol
            n for n in registry.reading(target) if registry.spec(n).precision < max(rtol, SINGLE_PRECISION)
        )
    else:
        engines = tuple(engines)
    opts = options or LoadOptions()
    side_a = load_side(original, opts, engines)
    side_b = load_side(export, export_options(opts, side_a, export), engines)
    pairing = pair_joints(side_a.mj_model, side_b.mj_model)
    if side_a.mj_model.nv == 0:
        problem = (
            f"{side_a.path}: nothing moves (no joint), so there is no mass matrix to compare "
            "(--floating gives the root body a free joint)"
        )
        skipped = tuple(EngineProof(e, np.nan, np.nan, 0, False, "nothing moves") for e in engines) + left_out
        return Proof(skipped, (), poses, seed, rtol, (problem,), asked)
    if pairing.problems:
        skipped = tuple(EngineProof(e, np.nan, np.nan, 0, False, "joints do not pair") for e in engines) + left_out
        return Proof(skipped, (), poses, seed, rtol, pairing.problems, asked)
    states = random_states(side_a.mj_model, poses, seed)
    results, segments = [], []
    for engine in engines:
        proof, diffs = compare_engine(engine, side_a, side_b, pairing, states, rtol)
        results.append(proof)
        segments += diffs
    return Proof(tuple(results) + left_out, tuple(segments), poses, seed, rtol, asked=asked)
