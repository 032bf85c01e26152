"""Each engine against itself and the two engines against each other, over every model case."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from engine_helpers import RTOL, equimomental, exact_energy, physical, rel_err


def _engine(pair, name):
    return pair.mujoco if name == "mujoco" else pair.pinocchio


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_exact_energy_of_segments_equals_engine_rigid_energy(case, pair, pose_batch, engine):
    qpos, qvel = pose_batch
    eng = _engine(pair, engine)
    states = eng.segment_states(qpos, qvel)
    assert states.n_poses == qpos.shape[0] and states.n_segments > 0
    total = exact_energy(states).sum(axis=1)
    rigid = eng.kinetic_energy(qpos, qvel).rigid
    assert rel_err(total, rigid) < RTOL, f"{case.id} {engine}: Σ exact {total[:3]} vs engine {rigid[:3]}"


@pytest.mark.parametrize(("engine", "method"), [("mujoco", "spatial"), ("mujoco", "jacobian"), ("pinocchio", None)])
def test_equimomental_point_velocities_give_engine_energy(case, pair, pose_batch, engine, method):
    qpos, qvel = pose_batch
    eng = _engine(pair, engine)
    states = eng.segment_states(qpos, qvel)
    offsets, masses = equimomental(states.mass, states.inertia_body)
    kwargs = {} if method is None else {"method": method}
    v = eng.point_velocities(qpos, qvel, offsets, **kwargs)
    assert v.shape == (qpos.shape[0], states.n_segments, 6, 3)
    per_segment = 0.5 * np.einsum("bk,pbki,pbki->pb", masses, v, v)
    ok = physical(states.mass, states.inertia_body)
    if ok.all():
        assert rel_err(per_segment.sum(axis=1), eng.kinetic_energy(qpos, qvel).rigid) < RTOL
    else:  # no equimomental set for a non-physical inertia: only Pinocchio keeps those (balanced cases)
        bad = {n for n, k in zip(states.names, ok, strict=True) if not k}
        assert engine == "pinocchio" and bad <= set(pair.import_differences)
        assert rel_err(per_segment[:, ok].sum(axis=1), exact_energy(states)[:, ok].sum(axis=1)) < RTOL


def test_engines_agree_on_segments_and_energy(case, pair, pose_batch):
    qpos, qvel = pose_batch
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel)
    assert set(sm.names) == set(sp.names), pair.notes
    sp = sp.select(segments=list(sm.names))
    e_mj, e_pin = exact_energy(sm), exact_energy(sp)
    scale = np.abs(e_mj).sum(axis=1, keepdims=True)
    seg_err = (np.abs(e_mj - e_pin) / scale).max(axis=0)
    mass_err = np.abs(sm.mass - sp.mass) / sm.mass
    inertia_err = np.abs(sm.inertia_world() - sp.inertia_world()).max(axis=(0, 2, 3)) / np.abs(sm.inertia_world()).max(
        axis=(0, 2, 3)
    )
    differing = {n for n, a, b, c in zip(sm.names, seg_err, mass_err, inertia_err, strict=True) if max(a, b, c) > RTOL}
    # every difference is explained by an import difference the loader recorded, and vice versa
    assert differing == set(pair.import_differences), (differing, pair.import_differences)
    rigid_mj = pair.mujoco.kinetic_energy(qpos, qvel).rigid
    rigid_pin = pair.pinocchio.kinetic_energy(qpos, qvel).rigid
    if not differing:
        assert rel_err(rigid_pin, rigid_mj) < RTOL
    else:
        assert rel_err(rigid_pin, rigid_mj) > RTOL


def test_engines_agree_on_motion_of_each_segment(case, pair, pose_batch):
    """COM velocity and angular velocity (world) are frame-free: the state map must make them equal."""
    qpos, qvel = pose_batch
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=list(sm.names))
    if pair.import_differences:
        keep = [n for n in sm.names if n not in pair.import_differences]
        sm, sp = sm.select(segments=keep), sp.select(segments=keep)
    speed = max(np.abs(sm.v_com).max(initial=0.0), 1.0)
    assert np.abs(sm.omega - sp.omega).max(initial=0.0) < RTOL * max(np.abs(sm.omega).max(initial=0.0), 1.0)
    assert np.abs(sm.v_com - sp.v_com).max(initial=0.0) < RTOL * speed


def _armature(eng, qpos: np.ndarray, nv: int) -> np.ndarray:
    """Per-dof armature (canonical dofs) read from the engine's own armature energy ½ a_d at unit rates."""
    return 2.0 * np.asarray(eng.kinetic_energy(np.tile(qpos, (nv, 1)), np.eye(nv)).armature)


def _supporting_dofs(model: mujoco.MjModel, segment: str) -> set[int] | None:
    """Dofs whose rate moves a segment (named by its joint): those of its body and of every ancestor body."""
    joint = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, segment)
    if joint < 0:
        return None
    body, dofs = int(model.jnt_bodyid[joint]), set()
    while body > 0:
        dofs |= set(np.flatnonzero(model.dof_bodyid == body).tolist())
        body = int(model.body_parentid[body])
    return dofs


def _masked_rel_err(a: np.ndarray, b: np.ndarray, mask: np.ndarray) -> float:
    """Largest |a - b| over the masked entries, relative to the largest |b| overall."""
    return float(np.abs(a - b)[..., mask].max(initial=0.0) / max(np.abs(b).max(initial=0.0), 1e-300))


def test_mass_matrices_and_inverse_dynamics_agree(case, pair, pose_batch):
    """M − diag(armature) and inverse dynamics − armature·q̈ agree, except where the rigid bodies differ."""
    qpos, qvel = pose_batch
    nv = qvel.shape[1]
    qacc = np.random.default_rng(7).normal(size=qvel.shape)
    Mm, Mp = pair.mujoco.mass_matrix(qpos), pair.pinocchio.mass_matrix(qpos)
    tm, tp = pair.mujoco.inverse_dynamics(qpos, qvel, qacc), pair.pinocchio.inverse_dynamics(qpos, qvel, qacc)
    arm_m, arm_p = _armature(pair.mujoco, qpos[0], nv), _armature(pair.pinocchio, qpos[0], nv)
    armature_differs = np.abs(arm_m - arm_p).max(initial=0.0) > RTOL * np.abs(Mm).max()
    if any("armature differs" in n for n in pair.notes):
        assert armature_differs, (arm_m, arm_p)
    rigid_m, rigid_p = Mm - arm_m * np.eye(nv), Mp - arm_p * np.eye(nv)
    rigid_tm, rigid_tp = tm - arm_m * qacc, tp - arm_p * qacc
    every = np.ones(nv, dtype=bool)
    same_m, same_t = np.ones((nv, nv), dtype=bool), every.copy()
    if pair.import_differences:
        # The engines were given different rigid bodies for these segments (MuJoCo's fusestatic dropped a massless
        # link's inertia, or balanceinertia altered an inertia Pinocchio keeps): M_ij and τ_i that involve them
        # differ by construction.  Only the entries no such segment enters are compared.
        for segment in pair.import_differences:
            if segment == "(static)":  # a body that never moves enters neither M nor τ
                continue
            dofs = _supporting_dofs(pair.mujoco.model, segment)
            assert dofs is not None, segment
            inside = np.isin(np.arange(nv), sorted(dofs))
            same_m &= ~(inside[:, None] & inside[None, :])
            same_t &= ~inside
        assert not same_m.all()
        assert _masked_rel_err(rigid_p, rigid_m, ~same_m) > RTOL  # the recorded difference is real
    assert _masked_rel_err(rigid_p, rigid_m, same_m) < RTOL
    assert _masked_rel_err(rigid_tp, rigid_tm, same_t) < 1e-8
    if not pair.import_differences:
        assert (rel_err(Mp, Mm) > RTOL) == armature_differs
        if not armature_differs:
            assert rel_err(tp, tm) < 1e-8


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_mass_matrix_is_the_energy_hessian(case, pair, pose_batch, engine):
    """½ q̇ᵀ M q̇ equals rigid + armature energy, and ID(q, 0, q̈) = M q̈."""
    qpos, qvel = pose_batch
    eng = _engine(pair, engine)
    M = eng.mass_matrix(qpos)
    assert np.allclose(M, np.swapaxes(M, -1, -2), rtol=0, atol=1e-12 * np.abs(M).max())
    parts = eng.kinetic_energy(qpos, qvel)
    assert rel_err(0.5 * np.einsum("pi,pij,pj->p", qvel, M, qvel), parts.total) < RTOL
    qacc = np.random.default_rng(3).normal(size=qvel.shape)
    tau = eng.inverse_dynamics(qpos, np.zeros_like(qvel), qacc)
    assert rel_err(tau, np.einsum("pij,pj->pi", M, qacc)) < 1e-8
