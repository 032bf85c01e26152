"""Each Newton cause on its fixture: Newton reads it (or refuses it), the departure is named, the effect sized.

Expected values come from hand computation on the fixture (the URDF convention) or from Newton called directly
(its own exception text), never from the code under test.  Compared with MuJoCo, Pinocchio and Newton, one
``compare`` call per fixture.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from koenig_check.engines.registry import ENGINE_TEXT

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

import koenig_check
from koenig_check.causes import cause, fixture_path
from koenig_check.engines.newton import PRECISION
from koenig_check.engines.newton import causes as ids
from koenig_check.findings import Finding, Kind

ENGINES = ("mujoco", "pinocchio", "newton")


@cache
def _findings(cause_id: str) -> tuple[bool, tuple[Finding, ...]]:
    check = koenig_check.compare(str(fixture_path(cause(cause_id))), n_poses=4, engines=ENGINES)
    return check.ok, tuple(f for comp in check.comparisons for f in comp.findings)


def _named(cause_id: str) -> Finding:
    found = [f for f in _findings(cause_id)[1] if f.cause == cause_id]
    assert found, f"{cause_id} not named on its fixture"
    return found[0]


def test_collapse_fixed_joints_sized_against_the_hand_merge() -> None:
    # Fixture: link1 2 kg, COM 0.1, Izz 0.02; link2 1 kg welded at 0.3, its COM 0.1 further, Izz 0.006.
    # About the hinge: M = 0.02 + 2·0.1² + 0.006 + 1·0.4² = 0.206 (every engine, Newton's default too).
    # Newton's collapse: merged COM 0.2 right, Izz = 0.02 + 0.006 + 1·0.3² = 0.116 instead of 0.086, M = 0.236.
    finding = _named(ids.COLLAPSE)
    assert finding.values["M change"] == pytest.approx((0.236 - 0.206) / 0.206, rel=PRECISION)
    assert finding.values["links merged"] == ["link2"]
    assert not finding.affects_energy  # an option Newton's users pass, not Newton's default reading


def test_link_without_inertial_gets_collision_mass() -> None:
    # link2 has no <inertial> and a 0.1 m collision box: Newton gives it 1000·0.1³ = 1 kg, Izz = 1·(0.1²+0.1²)/12.
    finding = _named(ids.NO_INERTIAL)
    assert finding.values["links"] == ["link2"]
    assert finding.values["mass in Newton"][0] == pytest.approx(1.0, rel=PRECISION)
    assert finding.values["inertia in Newton"][0] == pytest.approx([0.02 / 12] * 3, rel=PRECISION)
    # M about j1: without link2 0.004 + 1·0.1² = 0.014; with it + 0.02/12 + 1·0.2² (welded 0.2 from the hinge).
    assert finding.values["M change"] == pytest.approx((0.02 / 12 + 0.04) / 0.014, rel=PRECISION)
    assert finding.affects_energy and finding.root_cause and finding.segments == ("j1",)


def test_inertia_validation_adds_a_micro_inertia_to_a_point_mass() -> None:
    # The foot: 0.01 kg, zero inertia, 0.1 from the knee; M = 1e-5 + 0.1·0.05² + 0.01·0.1² = 3.6e-4 as written.
    finding = _named(ids.VALIDATION)
    assert finding.values["links"] == ["foot"] and finding.values["inertia in the file"] == [[0.0, 0.0, 0.0]]
    assert finding.values["inertia in Newton"][0] == pytest.approx([1.0001e-6] * 3, rel=PRECISION)
    assert finding.values["M change"] == pytest.approx(1.0001e-6 / 3.6e-4, rel=1e-3)


@pytest.mark.parametrize("cause_id", [ids.NO_INERTIAL, ids.VALIDATION])
def test_newton_abstains_where_it_changes_the_robot(cause_id: str) -> None:
    ok, findings = _findings(cause_id)
    unable = [f for f in findings if f.kind is Kind.ENGINE_UNABLE and f.engine == "newton"]
    assert not ok and unable  # named by the user, it could not check the file as written: the model fails
    assert not [f for f in findings if f.kind is Kind.VERDICT]  # and it does not vote


def test_floating_false_would_lose_the_root_joint() -> None:
    finding = _named(ids.FLOATING_FALSE)
    assert finding.values["joints"] == ["j1"] and cause(ids.FLOATING_FALSE).loses_joints


@pytest.mark.parametrize(
    ("cause_id", "parser"), [(ids.MIMIC_FIXED, "add_urdf"), (ids.SOLVER_PGS, "add_mjcf"), (ids.BOX_FROMTO, "add_mjcf")]
)
def test_a_refusal_carries_newtons_whole_text(cause_id: str, parser: str) -> None:
    import newton

    builder = newton.ModelBuilder()
    with pytest.raises(Exception) as raised:
        getattr(builder, parser)(str(fixture_path(cause(cause_id))))
    finding = _named(cause_id)
    assert finding.kind is Kind.ENGINE_NOT_USED and finding.engine == "newton"
    assert finding.summary == f"Newton not used: Newton's {parser} refuses the file"  # a few words, one line
    assert finding.values[ENGINE_TEXT] == f"{type(raised.value).__name__}: {raised.value}".rstrip()  # whole, apart
    assert not _findings(cause_id)[0]  # Newton was asked for: the check was not made


NEWTON_IDS = {c.id for c in ids.CAUSES}


@pytest.mark.parametrize(
    ("model", "expected"), [("double_pendulum.urdf", set()), ("double_pendulum.xml", {ids.FLOATING_FALSE})]
)
def test_a_file_without_these_constructs_names_none(model: str, expected: set[str]) -> None:
    """An MJCF arm's root body has its own hinge: only floating=False's loss of it applies (not a departure)."""
    check = koenig_check.compare(model, n_poses=3, engines=ENGINES)
    assert check.ok
    assert {f.cause for comp in check.comparisons for f in comp.findings} & NEWTON_IDS == expected


def test_the_fixtures_measured_mass_matrices_are_newtons() -> None:
    from koenig_check.engines.newton.causes import measure

    assert measure(fixture_path(cause(ids.COLLAPSE))).mass_matrix[("j1", "j1")] == pytest.approx(0.236, rel=PRECISION)
    assert np.isclose(
        measure(fixture_path(cause(ids.VALIDATION))).mass_matrix[("knee", "knee")], 3.6e-4 + 1.0001e-6, rtol=PRECISION
    )


def test_multi_joint_body_turns_about_the_first_joints_pos() -> None:
    # The foot: ankle_y at z = 0.08, ankle_x at z = 0.04 (body frame); COM (0.05, 0, -0.02), 0.5 kg, Ixx 0.001.
    # About ankle_x (x axis through z = 0.04): 0.001 + 0.5·0.06² = 0.0028; Newton turns it about z = 0.08:
    # 0.001 + 0.5·0.1² = 0.006.
    finding = _named(ids.MULTI_JOINT_POS)
    assert finding.element == "joint ankle_x" and finding.kind is Kind.ANCHOR
    assert finding.values["mujoco"] == pytest.approx([0, 0, 0.04]) and finding.values["newton"] == pytest.approx(
        [0, 0, 0.08], abs=1e-7
    )
    from koenig_check.engines.newton.causes import measure

    measured = measure(fixture_path(cause(ids.MULTI_JOINT_POS))).mass_matrix
    assert measured[("ankle_x", "ankle_x")] == pytest.approx(0.006, rel=PRECISION)
    ok, findings = _findings(ids.MULTI_JOINT_POS)
    assert not ok and any(f.kind is Kind.ENGINE_UNABLE and f.engine == "newton" for f in findings)


def test_a_change_within_newtons_precision_is_no_departure(tmp_path) -> None:
    """A 1e-4 kg point-mass gripper on a 2 kg arm: the validation's 1e-6 kg·m² is below 1e-5 of every M entry."""
    text = fixture_path(cause(ids.VALIDATION)).read_text()
    text = text.replace('<mass value="0.1"/>', '<mass value="2.0"/>').replace('ixx="0.00001"', 'ixx="0.5"')
    text = text.replace('iyy="0.00001"', 'iyy="0.5"').replace('izz="0.00001"', 'izz="0.5"')
    path = tmp_path / "heavy_arm.urdf"
    path.write_text(text)
    check = koenig_check.compare(str(path), n_poses=3, engines=ENGINES)
    found = [f for comp in check.comparisons for f in comp.findings if f.cause == ids.VALIDATION]
    assert check.ok and found and found[0].kind is Kind.LOAD and not found[0].affects_energy
    assert 0 < found[0].values["M change"] <= PRECISION
