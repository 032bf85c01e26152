"""iDynTree as an engine: a mass matrix by hand, and MuJoCo's and Pinocchio's every answer on the project's URDFs.

Each quantity of the Engine interface (energy, M, inverse dynamics, segment states) is compared within iDynTree's
declared precision (1e-12) on the project's URDF models, fixed and floating; the fixed base takes the joint block
of iDynTree's free-floating M, the floating one its mixed-representation velocities.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from urdf_engine_checks import CASE_IDS, CASES, ELBOWS, check_agrees, check_two_link_arm, precision

from koenig_check.engines import load_model

pytest.importorskip("idyntree")

ENGINE = "idyntree"


@pytest.mark.parametrize("elbow", ELBOWS)
def test_two_link_arm_mass_matrix_by_hand(tmp_path: Path, elbow: float) -> None:
    check_two_link_arm(tmp_path, ENGINE, elbow)


@pytest.mark.parametrize(("model", "floating"), CASES, ids=CASE_IDS)
def test_agrees_with_mujoco_and_pinocchio(model: str, floating: bool) -> None:
    check_agrees(model, floating, ENGINE)


def test_an_mjcf_is_a_refusal_not_an_empty_robot() -> None:
    """ModelLoader returns True with 0 links on an MJCF: said as iDynTree's refusal, with its own words."""
    pair = load_model("double_pendulum.xml")
    assert pair.attach(ENGINE) is None
    refusal = pair.refusal(ENGINE)
    assert refusal is not None and refusal.cause == "idyntree.mjcf.no-mjcf-reader"


def test_a_massless_leaf_link_is_a_frame_its_inertia_dropped(tmp_path: Path) -> None:
    """iDynTree makes a massless link fixed to one other a frame (as MuJoCo drops its inertia): by hand."""
    from urdf_engine_checks import MASSLESS_FOOT, exact_energy

    from koenig_check.engines import random_states

    path = tmp_path / "massless_foot.urdf"
    path.write_text(MASSLESS_FOOT)
    pair = load_model(str(path))
    engine = pair.attach(ENGINE)
    qpos, qvel = random_states(pair.mujoco.model, 4, seed=2)
    own = engine.kinetic_energy(qpos, qvel).total
    assert np.abs(exact_energy(engine.segment_states(qpos, qvel)) - own).max() <= 1e-12 * own.max()
    M = engine.mass_matrix(qpos[:1])[0, 0, 0]
    assert M == pytest.approx(0.01 + 0.1**2, rel=precision(ENGINE))


def test_a_massless_link_with_inertia_takes_idyntree_out_of_the_vote() -> None:
    """The catalogued cause on its fixture: iDynTree drops the foot's inertia (a frame), MuJoCo's fusestatic too;
    Pinocchio and PyBullet keep it.  Named, iDynTree could not check the model; MuJoCo departs."""
    import koenig_check
    from koenig_check.causes import cause, fixture_path
    from koenig_check.findings import Kind

    cause_id = "idyntree.urdf.massless-link-inertia"
    path = str(fixture_path(cause(cause_id)))
    engines = ("mujoco", "pinocchio", "pybullet", "idyntree")
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=engines)
    findings = check.comparisons[0].findings
    (root,) = [f for f in findings if f.cause == cause_id]
    assert root.values["links"] == ["foot"] and root.segments == ("hip",) and root.root_cause
    assert [f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE] == ["idyntree"] and not check.ok
    pair = load_model(path)
    M = {e: pair.engine(e).mass_matrix(np.zeros((1, 1)))[0, 0, 0] for e in ("idyntree", "pinocchio")}
    assert M["idyntree"] == pytest.approx(0.01 + 0.1**2, rel=1e-12)  # by hand, the leg alone
    assert M["pinocchio"] == pytest.approx(0.01 + 0.1**2 + 0.004, rel=1e-12)  # and the foot's ixx
