"""The gravity verdict: which engine departs, the catalogued cause it names, and what must not count."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from gravity_arm import arm_xml, engines_of

import koenig_check.causes
from koenig_check.diagnosis.diagnose import diagnose
from koenig_check.engines import random_states
from koenig_check.engines.registry import installed
from koenig_check.findings import Kind

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = Path(koenig_check.causes.__file__).parent / "fixtures"
DRAKE = installed("drake")

#: fixture -> the cause id each departing engine's gravity finding must carry (Drake's only where installed).
EXPECTED = {
    "option_gravity_moon.xml": {"pinocchio": "pinocchio.mjcf.option-gravity"},
    "option_gravity_sideways.xml": {"pinocchio": "pinocchio.mjcf.option-gravity"},
    "flag_gravity_disable.xml": {
        "pinocchio": "pinocchio.mjcf.flag-gravity-disable",
        "drake": "drake.mjcf.flag-gravity-disable",
    },
    "welded_mount_tilted.xml": {"pinocchio": "pinocchio.mjcf.welded-root-pose"},
    "option_gravity_default.xml": {},  # the default written out: every engine agrees
    "class_joint_inherited.xml": {"drake": "drake.mjcf.class-joint-default"},  # a lost axis only gravity sees
}


def _diagnosis(path: Path, n: int = 6):
    loaded = engines_of(path)
    qpos, qvel = random_states(loaded.mujoco.model, n, 0)
    return loaded, diagnose(loaded, qpos=qpos, qvel=qvel)


@pytest.mark.parametrize("fixture", sorted(EXPECTED))
def test_each_gravity_cause_on_its_fixture(fixture: str) -> None:
    _, d = _diagnosis(FIXTURES / fixture)
    expected = {e: c for e, c in EXPECTED[fixture].items() if e != "drake" or DRAKE}
    named = {f.engine: f.cause for f in d.gravity.findings if f.root_cause}
    assert named == expected
    assert d.gravity.agrees is (not expected)
    for finding in d.gravity.findings:  # every engine's vector is stated with MuJoCo's
        if finding.root_cause and finding.element in ("option gravity", "flag gravity"):
            assert set(finding.values) == {"mujoco", finding.engine}


def test_moon_vectors_as_each_engine_read_them() -> None:
    _, d = _diagnosis(FIXTURES / "option_gravity_moon.xml")
    vectors = d.gravity.vectors()
    assert vectors["mujoco"] == (0.0, 0.0, -1.62)
    assert vectors["pinocchio"] == (0.0, 0.0, -9.81)  # Pinocchio's MJCF parser ignores <option>
    if DRAKE:
        assert vectors["drake"] == (0.0, 0.0, -1.62)
    gap = {g.quantity: g for g in d.gravity.gaps if g.engine == "pinocchio"}["g(q)"]
    assert gap.relative == pytest.approx(9.81 / 1.62 - 1, rel=1e-12)  # g(q) scales with |gravity|


def test_disable_flag_is_read_from_the_flag_bit_not_opt_gravity() -> None:
    loaded, d = _diagnosis(FIXTURES / "flag_gravity_disable.xml")
    assert np.array(loaded.mujoco.model.opt.gravity).tolist() == [0.0, 0.0, -9.81]  # the flag leaves it
    assert d.gravity.vectors()["mujoco"] == (0.0, 0.0, 0.0)
    assert np.all(d.gravity.readings["mujoco"].g == 0.0)


def test_a_tilt_of_1e_5_is_a_disagreement(write) -> None:
    """gymnasium's inverted_double_pendulum declares gravity (1e-5, 0, -9.81): g(q) differs by about 1e-6."""
    _, d = _diagnosis(write(arm_xml('<option gravity="1e-5 0 -9.81"/>')))
    gap = max((g for g in d.gravity.gaps if g.engine == "pinocchio"), key=lambda g: g.relative)
    assert 1e-8 < gap.relative < 1e-4
    assert not d.gravity.agrees
    assert [f.cause for f in d.gravity.findings if f.root_cause and f.engine == "pinocchio"] == [
        "pinocchio.mjcf.option-gravity"
    ]


def test_a_welded_heavy_body_changes_no_verdict(write) -> None:
    """MuJoCo's V counts a body welded to the world, Pinocchio's does not: only differences are compared."""
    anvil = '<body name="anvil" pos="0 3 2"><geom type="box" size=".2 .2 .2" mass="500"/></body>'
    text = arm_xml(extra="").replace("</worldbody>", anvil + "</worldbody>")
    _, d = _diagnosis(write(text))
    r = d.gravity.readings
    constant = r["mujoco"].v_gravity - r["pinocchio"].v_gravity
    assert np.all(np.abs(constant) > 500 * 9.81 * 1.9)  # the engines' constants differ by the anvil's m g z
    assert d.gravity.agrees


def test_springs_are_kept_apart_and_named(write) -> None:
    _, d = _diagnosis(write(arm_xml(spring=' stiffness="40" springref="0.3"')))
    assert d.gravity.agrees  # MuJoCo's spring energy is not gravity: Pinocchio has none and still agrees
    notes = [f for f in d.gravity.findings if f.element == "springs"]
    assert [f.engine for f in notes] == ["mujoco"]
    assert not notes[0].root_cause and notes[0].values["max |dV springs|"] > 1.0


def test_a_mass_cause_explaining_g_is_named_once() -> None:
    _, d = _diagnosis(ROOT / "tests" / "models" / "causes" / "class_mass.xml")
    assert not d.gravity.agrees
    mass = [f for f in d.findings if f.root_cause and f.kind is Kind.MASS]
    assert len(mass) == 1
    gravity = [f for f in d.gravity.findings if f.engine == "pinocchio"]
    assert len(gravity) == 1 and not gravity[0].root_cause  # no second root cause for the same construct
    assert gravity[0].values["explained by"] == mass[0].element
    assert gravity[0].values["explained by cause"] == mass[0].cause and not gravity[0].cause  # the id carried once
    assert [f for f in d.findings if f.cause == mass[0].cause] == mass
    assert [f for f in d.findings if f.element == mass[0].element] == mass  # the construct's element once
    assert not [f for f in d.findings if f.root_cause and f.kind is Kind.GRAVITY]


def test_urdf_carries_no_gravity_and_says_so() -> None:
    _, d = _diagnosis(ROOT / "models" / "gimbal.urdf")
    notes = [f for f in d.gravity.findings if f.engine == "file"]
    assert len(notes) == 1 and notes[0].kind is Kind.GRAVITY and not notes[0].root_cause
    assert notes[0].values["mujoco"] == (0.0, 0.0, -9.81)
    assert d.gravity.agrees
