"""Drake's column in the dynamics check: every route against Drake's M and inverse dynamics."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.findings import Kind
from koenig_check.implied_dynamics.analysis import ENGINE_PARITY
from koenig_check.implied_dynamics.markdown import terminal_lines

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed: its tests are skipped")

ALL = ("mujoco", "pinocchio", "drake")


@pytest.mark.parametrize("model", ["gimbal.xml", "armature_chain.xml", "free_body.urdf"])
def test_exact_agrees_with_drake_by_every_route(model: str) -> None:
    floating = model.endswith(".urdf")
    dyn = koenig_check.dynamics(model, n_poses=3, formulas=["exact", "koenig_world"], engines=ALL, floating=floating)
    assert set(dyn.engine_mass) == set(ALL)
    drake_exact = [e for e in dyn.errors if e.engine == "drake" and e.formula == "exact"]
    assert {e.route for e in drake_exact} == {"lagrange@mujoco", "lagrange@pinocchio", "kane@mujoco", "kane@pinocchio"}
    assert all(e.max_rel_error <= (dyn.m_rtol if e.quantity == "M" else dyn.q_rtol) for e in drake_exact)
    parity = [e for e in dyn.errors if e.formula == ENGINE_PARITY and e.engine == "drake"]
    assert len(parity) == 2 and all(e.max_rel_error < 1e-12 for e in parity)
    assert dyn.ok
    assert any("M vs drake" in line for line in terminal_lines(dyn))


def test_drake_not_run_where_the_engines_agree_by_default() -> None:
    dyn = koenig_check.dynamics("gimbal.xml", n_poses=2, formulas=["exact"])
    assert "drake" not in dyn.engine_mass
    assert any(
        f.kind is Kind.ENGINE_NOT_USED and f.summary.startswith("Drake not used: not needed") for f in dyn.findings
    )


def test_drake_reflected_inertia_is_taken_out_of_its_mass_matrix_and_forces() -> None:
    # Drake alone reads the rotor inertia (0.5 kg m² × gear ratio 3² = 4.5 kg m² reflected on 'spin'); with it
    # taken out, Drake's rigid M and Q* equal MuJoCo's, which has no armature here.
    path = Path(__file__).resolve().parents[1] / "models" / "tiebreak" / "rotor_inertia.urdf"
    dyn = koenig_check.dynamics(path, n_poses=3, formulas=["exact"], engines=ALL)
    np.testing.assert_allclose(dyn.engine_mass["drake"], dyn.engine_mass["mujoco"], rtol=1e-12)
    np.testing.assert_allclose(dyn.engine_forces["drake"], dyn.engine_forces["mujoco"], rtol=1e-12, atol=1e-12)
    raw = dyn.engine_mass["drake"][:, 0, 0] + 4.5  # by hand: the reflected inertia the engine's M carries
    assert np.all(raw > dyn.engine_mass["mujoco"][:, 0, 0] + 4.4)
