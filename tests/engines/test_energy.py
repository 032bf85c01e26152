"""Each engine against itself and the two engines against each other, over every model case."""

from __future__ import annotations

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


def test_mass_matrices_and_inverse_dynamics_agree(case, pair, pose_batch):
    qpos, qvel = pose_batch
    qacc = np.random.default_rng(7).normal(size=qvel.shape)
    Mm, Mp = pair.mujoco.mass_matrix(qpos), pair.pinocchio.mass_matrix(qpos)
    tm, tp = pair.mujoco.inverse_dynamics(qpos, qvel, qacc), pair.pinocchio.inverse_dynamics(qpos, qvel, qacc)
    if pair.import_differences or any("armature differs" in n for n in pair.notes):
        assert rel_err(Mp, Mm) > RTOL
        return
    assert rel_err(Mp, Mm) < RTOL
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
