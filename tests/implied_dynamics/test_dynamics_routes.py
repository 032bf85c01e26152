"""Building blocks: polarization, momentum, Lagrange's Hamel term, refusals, the API's arrays."""

from __future__ import annotations

import numpy as np
import pytest
from dynamics_helpers import states_with_accelerations

import koenig_check
from koenig_check.implied_dynamics.energy import (
    FormulaEnergy,
    PathDependentError,
    implied_mass_matrix,
    implied_momentum,
    polarization_pairs,
)
from koenig_check.implied_dynamics.lagrange import configuration_gradient, momentum_rate
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix


def test_polarization_pairs_cover_the_upper_triangle():
    pairs, unit = polarization_pairs(4)
    assert len(pairs) == 10 and len({tuple(p) for p in pairs}) == 10
    assert (unit.sum(axis=1) == np.where(pairs[:, 0] == pairs[:, 1], 1, 2)).all()


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_energy_is_the_quadratic_form_of_the_implied_mass_matrix(load_pair, engine):
    pair = load_pair("serial7.urdf", True)
    eng = pair.mujoco if engine == "mujoco" else pair.pinocchio
    qpos, qvel, _ = states_with_accelerations(pair, 3)
    energy = FormulaEnergy("exact", eng)
    M = implied_mass_matrix(energy, qpos)
    assert np.allclose(M, np.swapaxes(M, 1, 2), rtol=0, atol=0)
    quadratic = 0.5 * np.einsum("pi,pij,pj->p", qvel, M, qvel)
    assert np.allclose(energy(qpos, qvel), quadratic, rtol=1e-12, atol=0)
    assert np.allclose(eng.kinetic_energy(qpos, qvel).rigid, quadratic, rtol=1e-12, atol=0)
    p = implied_momentum(energy, qpos, qvel)
    assert np.allclose(p, np.einsum("pij,pj->pi", M, qvel), rtol=1e-10, atol=1e-12)


def test_path_dependent_formulas_are_refused_with_a_reason(load_pair):
    pair = load_pair("gimbal.xml")
    for name in ("alyushin_paper:integrated", "alyushin_pole:paper:integrated"):
        with pytest.raises(PathDependentError, match="depends on the path"):
            FormulaEnergy(name, pair.mujoco)
    result = koenig_check.dynamics("gimbal.xml", n_poses=2, formulas=["alyushin_paper:integrated"])
    assert "Lagrange's equations are not defined" in result.refusals["alyushin_paper:integrated"]
    assert not any(f == "alyushin_paper:integrated" for f, _ in result.routes)


def test_planar_is_refused_off_plane_and_evaluated_on_the_double_pendulum():
    gimbal = koenig_check.dynamics("gimbal.xml", n_poses=2, formulas=["planar"])
    assert "plane-parallel" in gimbal.refusals["planar"]
    pendulum = koenig_check.dynamics("double_pendulum.xml", n_poses=2, formulas=["planar"])
    assert "planar" not in pendulum.refusals
    assert max(e.max_rel_error for e in pendulum.errors_of("planar")) < 1e-6


def test_body_frame_angular_velocities_need_hamels_term(load_pair):
    # A free rigid body: τ = I ω̇ + ω × I ω (Euler).  The plain d/dt ∂T/∂q̇ − ∂T/∂q misses ω × ∂T/∂ω.
    pair = load_pair("free_body.xml")
    qpos, qvel, qacc = states_with_accelerations(pair, 3)
    energy = FormulaEnergy("exact", pair.mujoco)
    plain = -(
        momentum_rate(energy, pair.mujoco.model, qpos, qvel, qacc)
        - configuration_gradient(energy, pair.mujoco.model, qpos, qvel)
    )
    engine = rigid_inertia_forces(pair.mujoco, qpos, qvel, qacc)
    assert np.allclose(plain[:, :3], engine[:, :3], rtol=1e-6, atol=1e-9)  # world-frame translation: no term
    assert (np.linalg.norm(plain[:, 3:] - engine[:, 3:], axis=1) > 1e-3 * np.linalg.norm(engine, axis=1)).all()


def test_api_returns_arrays(load_pair):
    result = koenig_check.dynamics("serial7.xml", n_poses=3, seed=4, formulas=["koenig_world"])
    P, nv = result.qvel.shape
    assert (P, nv) == (3, 7) and len(result.dof_names) == nv
    r = result.routes[("koenig_world", "lagrange@mujoco")]
    assert r.M.shape == (P, nv, nv) and r.Q.shape == (P, nv)
    assert result.engine_mass["mujoco"].shape == (P, nv, nv)
    assert all(e.rel_error.shape == (P,) for e in result.errors)
    assert {f for f, _ in result.routes} == {"exact", "koenig_world"}
    assert result.ok
    pair = load_pair("serial7.xml")
    assert np.allclose(result.engine_mass["pinocchio"], rigid_mass_matrix(pair.pinocchio, result.qpos))
    with pytest.raises(TypeError, match="unexpected"):
        koenig_check.dynamics("serial7.xml", n_poses=1, flaoting=True)
