"""Each PyBullet cause on its fixture: read by PyBullet, the departure named by its id, its effect sized by hand.

The effects are computed here from the fixtures' numbers (a box's inertia, the parallel-axis theorem) or read
from PyBullet's own ``calculateMassMatrix`` (:func:`koenig_check.engines.pybullet.causes.measure`), never from the
finding under test.
"""

from __future__ import annotations

import numpy as np
import pytest

import koenig_check
from koenig_check.causes import cause, fixture_path
from koenig_check.engines import load_model
from koenig_check.findings import Finding, Kind

pytest.importorskip("pybullet")

ALL = ("mujoco", "pinocchio", "pybullet", "idyntree")


def _fixture(cause_id: str) -> str:
    return str(fixture_path(cause(cause_id)))


def _with_cause(findings: list[Finding], cause_id: str) -> Finding:
    (found,) = [f for f in findings if f.cause == cause_id]
    return found


def test_loading_without_the_inertia_flag_is_sized_on_the_robot() -> None:
    cause_id = "pybullet.urdf.inertia-from-collision"
    pair = load_model(_fixture(cause_id))
    assert pair.attach("pybullet") is not None
    found = _with_cause(pair.optional_findings, cause_id)
    # By hand: the file's M is Izz + m d² = 0.03 + 2 · 0.2²; from the 0.1 m collision cube, m (a² + b²) / 12 + m d².
    as_written = 0.03 + 2.0 * 0.2**2
    from_cube = 2.0 * (0.1**2 + 0.1**2) / 12 + 2.0 * 0.2**2
    assert found.values["M change"] == pytest.approx(abs(from_cube - as_written) / as_written, rel=1e-6)
    assert found.kind is Kind.LOAD and not found.affects_energy  # advice: the robot checked was read as written


def test_merging_fixed_links_is_sized_on_the_robot() -> None:
    from koenig_check.engines.pybullet.causes import measure

    cause_id = "pybullet.urdf.merge-fixed-links"
    pair = load_model(_fixture(cause_id))
    assert pair.attach("pybullet") is not None
    found = _with_cause(pair.optional_findings, cause_id)
    # By hand: arm 0.008 + 1 · 0.15², tool 0.001 + 0.5 · 0.3²; PyBullet's merged M from its own calculateMassMatrix.
    as_written = 0.008 + 1.0 * 0.15**2 + 0.001 + 0.5 * 0.3**2
    merged = measure(fixture_path(cause(cause_id))).mass_matrix[("shoulder", "shoulder")]
    assert found.values["M change"] == pytest.approx(abs(merged - as_written) / as_written, rel=1e-6)
    assert found.values["M change"] > 0.1


def test_a_link_without_inertial_takes_pybullet_out_of_the_vote() -> None:
    """PyBullet was given another robot (1 kg on the camera): named, it could not check the model; no verdict."""
    cause_id = "pybullet.urdf.link-without-inertial"
    check = koenig_check.compare(_fixture(cause_id), n_poses=3, formulas=["exact"], engines=ALL)
    findings = check.comparisons[0].findings
    root = _with_cause(findings, cause_id)
    assert root.root_cause and root.values["links"] == ["camera"] and root.segments == ("shoulder",)
    (unable,) = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.engine == "pybullet" and unable.segments == ("camera",) and not check.ok
    assert not [f for f in findings if f.kind is Kind.VERDICT]  # MuJoCo, Pinocchio and iDynTree agree
    # The effect by hand: 1 kg at 0.3 m with a unit moment adds 1 + 0.3² to the file's 0.008 + 0.15².
    pair = load_model(_fixture(cause_id))
    M = pair.attach("pybullet").mass_matrix(np.zeros((1, 1)))[0, 0, 0]
    assert M == pytest.approx(0.008 + 0.15**2 + 1.0 + 0.3**2, rel=1e-7)


def test_a_root_without_inertial_departs_only_when_the_base_floats() -> None:
    cause_id = "pybullet.urdf.floating-root-without-inertial"
    fixed = koenig_check.compare(_fixture(cause_id), n_poses=3, formulas=["exact"], engines=ALL)
    note = _with_cause(fixed.comparisons[0].findings, cause_id)
    assert fixed.ok and note.kind is Kind.LOAD and not note.root_cause
    floating = koenig_check.compare(_fixture(cause_id), n_poses=3, formulas=["exact"], engines=ALL, floating=True)
    findings = floating.comparisons[0].findings
    root = _with_cause(findings, cause_id)
    assert root.root_cause and root.segments == ("root_joint",) and not floating.ok
    assert [f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE] == ["pybullet"]
    pair = load_model(_fixture(cause_id), floating=True)
    q0, zero = np.asarray(pair.mujoco.model.qpos0)[None], np.zeros((1, pair.mujoco.nv))
    masses = {e: pair.engine(e).segment_states(q0, zero).mass[0] for e in ("mujoco", "pybullet")}
    assert masses["mujoco"] == pytest.approx(5.0, rel=1e-12)  # the trunk, welded to base_link
    assert masses["pybullet"] == pytest.approx(5.0 + 1.0, rel=1e-12)  # and PyBullet's 1 kg on base_link


def test_a_missing_mesh_is_pybullets_refusal_with_its_own_text() -> None:
    cause_id = "pybullet.urdf.missing-mesh"
    check = koenig_check.compare(_fixture(cause_id), n_poses=3, formulas=["exact"], engines=ALL)
    findings = check.comparisons[0].findings
    refusal = _with_cause(findings, cause_id)
    assert refusal.kind is Kind.ENGINE_NOT_USED and refusal.values["missing meshes"] == ["meshes/no_such_arm.stl"]
    assert "cannot find 'meshes/no_such_arm.stl'" in refusal.summary  # PyBullet's own words, kept whole
    assert [f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE] == ["pybullet"] and not check.ok


def test_an_mjcf_is_pybullets_refusal() -> None:
    cause_id = "pybullet.mjcf.load-mjcf"
    engines = ("mujoco", "pinocchio", "pybullet")
    check = koenig_check.compare(_fixture(cause_id), n_poses=3, formulas=["exact"], engines=engines)
    findings = check.comparisons[0].findings
    assert _with_cause(findings, cause_id).kind is Kind.ENGINE_NOT_USED
    assert [f.engine for f in findings if f.kind is Kind.ENGINE_UNABLE] == ["pybullet"] and not check.ok


def test_options_that_change_nothing_are_not_said() -> None:
    """double_pendulum.urdf has no fixed joint: URDF_MERGE_FIXED_LINKS merges nothing, and nothing is said of it."""
    pair = load_model("double_pendulum.urdf")
    pybullet = pair.attach("pybullet")
    assert pybullet is not None
    said = {f.cause for f in pair.optional_findings}
    assert "pybullet.urdf.merge-fixed-links" not in said


UNBALANCED = """<robot name="unbalanced">
  <link name="base"/>
  <link name="arm"><inertial><origin xyz="0.2 0 0"/><mass value="2"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.25" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="swing" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def test_an_inertia_breaking_the_triangle_inequality_is_zeroed_and_pybullet_does_not_vote(tmp_path) -> None:
    """0.1 + 0.1 < 0.25: PyBullet sets the moments to zero (MuJoCo refuses it unless asked to repair it)."""
    path = tmp_path / "unbalanced.urdf"
    path.write_text(UNBALANCED)
    pair = load_model(str(path), repair_inertia=True)
    pybullet = pair.attach("pybullet")
    (zeroed,) = [f for f in pair.optional_findings if f.kind is Kind.INERTIA and f.engine == "pybullet"]
    assert zeroed.values["moments in PyBullet"] == [0.0, 0.0, 0.0] and zeroed.segments == ("swing",)
    assert pybullet.mass_matrix(np.zeros((1, 1)))[0, 0, 0] == 0.0  # the COM is on the axis: only Ixx was left
    check = koenig_check.compare(str(path), n_poses=2, formulas=["exact"], engines=ALL, repair_inertia=True)
    assert "pybullet" in [f.engine for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]


def test_an_inertia_zero_but_for_round_off_is_not_a_reason_to_abstain(tmp_path) -> None:
    """example-robot-data's icub_reduced writes inertias of 1e-20 breaking A + B >= C: PyBullet's zero is the same.

    Turned about z, the arm's M is 2 · 0.2² = 0.08 kg m² without its moments; 2.5e-20 is far below PyBullet's
    precision times that.
    """
    path = tmp_path / "round_off.urdf"
    text = UNBALANCED.replace('ixx="0.1" iyy="0.1" izz="0.25"', 'ixx="1e-20" iyy="1e-20" izz="2.5e-20"')
    path.write_text(text.replace('<axis xyz="1 0 0"/>', '<axis xyz="0 0 1"/>'))
    pair = load_model(str(path), repair_inertia=True)
    assert pair.attach("pybullet") is not None
    assert not [f for f in pair.optional_findings if f.cause == "pybullet.urdf.zeroed-inertia"]
    check = koenig_check.compare(str(path), n_poses=2, formulas=["exact"], engines=ALL, repair_inertia=True)
    assert "pybullet" not in [f.engine for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
