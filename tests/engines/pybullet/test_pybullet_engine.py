"""PyBullet as an engine: a mass matrix by hand, and MuJoCo's and Pinocchio's every answer on the project's URDFs.

Each quantity of the Engine interface (energy, M, inverse dynamics, segment states) is compared within PyBullet's
declared precision (3e-6: it diagonalizes every inertia) on the project's URDF models, fixed and floating; the
floating base exercises the state map's conventions (the base's inertial frame, ``(ω, v_COM)`` in its axes, the
classical acceleration ``calculateInverseDynamics`` takes).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from urdf_engine_checks import CASE_IDS, CASES, ELBOWS, check_agrees, check_two_link_arm, precision

from koenig_check.engines import load_model

pytest.importorskip("pybullet")

ENGINE = "pybullet"


@pytest.mark.parametrize("elbow", ELBOWS)
def test_two_link_arm_mass_matrix_by_hand(tmp_path: Path, elbow: float) -> None:
    check_two_link_arm(tmp_path, ENGINE, elbow)


@pytest.mark.parametrize(("model", "floating"), CASES, ids=CASE_IDS)
def test_agrees_with_mujoco_and_pinocchio(model: str, floating: bool) -> None:
    check_agrees(model, floating, ENGINE)


def test_its_printing_does_not_reach_the_output(capfd: pytest.CaptureFixture[str]) -> None:
    """PyBullet prints its parser's warnings from C; a link without <inertial> makes it warn at every load."""
    from koenig_check.causes import cause, fixture_path

    pair = load_model(str(fixture_path(cause("pybullet.urdf.link-without-inertial"))))
    assert pair.attach(ENGINE) is not None
    out, err = capfd.readouterr()
    assert "No inertial data" not in out + err and "b3Warning" not in out + err


def test_a_massless_links_inertia_is_in_its_segment_as_pybullet_counts_it(tmp_path: Path) -> None:
    """PyBullet keeps the inertia of a link of mass 0 (as Pinocchio does): its segments must too, or the states'
    energy would not be PyBullet's own."""
    from urdf_engine_checks import MASSLESS_FOOT, exact_energy

    from koenig_check.engines import random_states

    path = tmp_path / "massless_foot.urdf"
    path.write_text(MASSLESS_FOOT)
    pair = load_model(str(path))
    engine = pair.attach(ENGINE)
    qpos, qvel = random_states(pair.mujoco.model, 4, seed=2)
    own = engine.kinetic_energy(qpos, qvel).total
    assert np.abs(exact_energy(engine.segment_states(qpos, qvel)) - own).max() <= 1e-12 * own.max()
    leg_about_hip = 0.01 + 0.1**2  # the leg's moment about the hip axis (x): by hand
    M = engine.mass_matrix(qpos[:1])[0, 0, 0]
    assert M == pytest.approx(leg_about_hip + 0.004, rel=precision(ENGINE))  # the foot's ixx, no mass, counted
