"""Armature: the engines' M and inverse dynamics include it, no formula does; the comparison takes it out explicitly."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from dynamics_helpers import states_with_accelerations

from koenig_check.engines import load_model
from koenig_check.implied_dynamics.analysis import ENGINES, dynamics_of_pair
from koenig_check.implied_dynamics.energy import FormulaEnergy, implied_mass_matrix
from koenig_check.implied_dynamics.reference import rigid_inertia_forces, rigid_mass_matrix

#: armature of j1..j4 in models/armature_chain.xml, typed from the file
ARMATURE = np.array([0.02, 0.015, 0.01, 0.005])


@pytest.fixture(scope="module")
def chain(load_pair):
    return load_pair("armature_chain.xml")


@pytest.mark.parametrize("engine", ENGINES)
def test_engine_mass_matrix_carries_the_armature_and_the_reference_removes_it(chain, engine):
    eng = chain.engines[engine]
    qpos, qvel, qacc = states_with_accelerations(chain, 3)
    raw, rigid = eng.mass_matrix(qpos), rigid_mass_matrix(eng, qpos)
    assert np.allclose(raw - rigid, np.diag(ARMATURE), rtol=0, atol=1e-12)
    tau_raw = eng.inverse_dynamics(qpos, qvel, qacc)
    assert np.allclose(tau_raw + rigid_inertia_forces(eng, qpos, qvel, qacc), qacc * ARMATURE, rtol=0, atol=1e-12)


def test_formula_mass_matrix_has_no_armature_and_matches_the_rigid_part(chain):
    qpos, _, _ = states_with_accelerations(chain, 3)
    M = implied_mass_matrix(FormulaEnergy("exact", chain.mujoco), qpos)
    for eng in chain.engines.values():
        raw = eng.mass_matrix(qpos)
        # the armature is no rounding matter here: ignoring it would be a 1e-3-size error
        assert (np.linalg.norm(M - raw, axis=(1, 2)) / np.linalg.norm(raw, axis=(1, 2)) > 1e-3).all()
        assert np.allclose(raw - M, np.diag(ARMATURE), rtol=0, atol=1e-12)


def test_dynamics_check_passes_with_armature_taken_out(chain):
    qpos, qvel, qacc = states_with_accelerations(chain, 3)
    result = dynamics_of_pair(chain, qpos, qvel, qacc, formulas=["exact"])
    assert result.ok, result.reason()
    assert max(e.max_rel_error for e in result.errors_of("exact", "M")) < 1e-9
    assert max(e.max_rel_error for e in result.errors_of("exact", "Q*")) < 1e-6


def test_engines_with_different_armature_agree_once_each_removes_its_own():
    # MuJoCo from the MJCF (armature), Pinocchio from the URDF twin (no armature: URDF cannot carry it)
    pair = load_model("armature_chain.xml", pinocchio_source="armature_chain.urdf")
    assert np.allclose(pair.mujoco.model.dof_armature, ARMATURE)
    assert np.allclose(pair.pinocchio.model.armature, 0.0)
    qpos, qvel, qacc = states_with_accelerations(pair, 3)
    result = dynamics_of_pair(pair, qpos, qvel, qacc, formulas=["exact"])
    assert result.ok, result.reason()


def test_a_one_dof_model_goes_through_every_route() -> None:
    # Pinocchio's bindings hand a one-dof model's frame Jacobian out as a (6,) vector, not (6, 1).
    import koenig_check

    path = Path(__file__).resolve().parents[1] / "engines" / "models" / "hinge_armature.xml"
    dyn = koenig_check.dynamics(path, n_poses=3, formulas=["exact"])
    assert {e.route for e in dyn.errors if e.formula == "exact"} >= {"kane@mujoco", "kane@pinocchio"}
    assert dyn.ok
