"""--repair-inertia: the smallest change MuJoCo accepts, recorded per link, and its effect on the energy.

``repair_needed.urdf`` has a link with a negative principal moment (moments −0.01, 0.01, 0.05 from
ixx = iyy = 0.02, ixy = 0.03, izz = 0.01) and a massless link moved by a joint.  Expected values are
computed here by hand: the least largest change t of the sorted moments (A, B, C) with A + t >= 0
and (A + t) + (B + s) >= C − s is t = (C − A − B)/3 = 0.05/3, s = t here; the z axis (the yaw axis)
is the principal axis of B, so the repair adds ½ ω² t to the energy of a pure yaw motion.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from engine_helpers import EXPECTED_LOAD_FAILURES

from koenig_check.api import compare
from koenig_check.engines import InertiaError, ModelLoadError, list_models, load_model, resolve_model
from koenig_check.engines.mujoco.inertia_repair import MJMINVAL
from koenig_check.findings import Kind

MODEL = Path(__file__).resolve().parents[1] / "models" / "repair_needed.urdf"
FILE_TENSOR = np.array([[0.02, 0.03, 0.0], [0.03, 0.02, 0.0], [0.0, 0.0, 0.01]])
T_HAND = (0.05 - (-0.01) - 0.01) / 3.0  # = 0.05/3
MOMENTS_AFTER = np.array([-0.01 + T_HAND, 0.01 + T_HAND, 0.05 - T_HAND])


@pytest.fixture(scope="module")
def repaired():
    return load_model(MODEL, repair_inertia=True)


def test_without_the_opt_in_the_refusal_names_the_option() -> None:
    with pytest.raises(InertiaError) as info:
        load_model(MODEL)
    msg = str(info.value)
    assert "\n" not in msg and str(MODEL) in msg and "link 'tilted'" in msg and "--repair-inertia" in msg


def test_each_repaired_link_is_one_finding_with_its_values(repaired) -> None:
    found = {f.element: f for f in repaired.findings if f.kind is Kind.REPAIR}
    assert set(found) == {"link tilted", "link virtual"}
    tilted, virtual = found["link tilted"], found["link virtual"]
    assert tilted.engine == "mujoco" and tilted.affects_energy and tilted.root_cause and tilted.segments == ("yaw",)
    np.testing.assert_allclose(tilted.values["moments before"], [-0.01, 0.01, 0.05], atol=1e-15)
    np.testing.assert_allclose(tilted.values["moments after"], MOMENTS_AFTER, rtol=1e-12)
    assert tilted.values["mass before"] == tilted.values["mass after"] == 2.0
    assert virtual.values["mass before"] == 0.0 and MJMINVAL <= virtual.values["mass after"] <= 10 * MJMINVAL
    assert all(MJMINVAL <= m <= 10 * MJMINVAL for m in virtual.values["moments after"])


def test_the_repair_message_shows_the_raised_mass_not_zero(repaired) -> None:
    """The raised mass sits at MuJoCo's bound, below the round-off threshold: the message must still show it."""
    virtual = next(f for f in repaired.findings if f.kind is Kind.REPAIR and f.element == "link virtual")
    after = virtual.values["mass after"]
    assert f"mass before 0, mass after {after:.6g}" in virtual.message()


def test_mujoco_loads_the_repair_and_pinocchio_keeps_the_file(repaired) -> None:
    mj = repaired.mujoco.model
    body = mj.body("tilted")
    np.testing.assert_allclose(np.sort(body.inertia), np.sort(MOMENTS_AFTER), rtol=1e-12)
    pin_inertia = repaired.pinocchio.model.inertias[repaired.pinocchio.model.getJointId("yaw")]
    np.testing.assert_allclose(pin_inertia.inertia, FILE_TENSOR, atol=1e-15)


def test_the_repair_changes_the_energy_by_its_hand_computed_size(repaired) -> None:
    w = np.array([0.7, -1.3, 2.1])
    qvel = np.zeros((3, 3))
    qvel[:, 0] = w  # yaw only: the repaired link spins about its z axis, the principal axis of B
    qpos = np.zeros((3, 3))
    t_mj = repaired.mujoco.kinetic_energy(qpos, qvel).rigid
    t_pin = repaired.pinocchio.kinetic_energy(qpos, qvel).rigid
    np.testing.assert_allclose(t_mj - t_pin, 0.5 * w**2 * T_HAND, rtol=1e-9)


def test_the_verdict_is_a_disagreement_named_after_the_repair() -> None:
    check = compare(MODEL, repair_inertia=True, n_poses=5)
    assert not check.ok
    # the one line: the repair of both links is one root cause naming them, the most important first
    assert "root cause: links tilted, virtual: inertia changed so that MuJoCo accepts it" in check.reason()
    assert check.agreements[0].gap.startswith("MuJoCo and Pinocchio differ by")
    details = check.agreements[0].reason  # summary.md and the report: every cause, in order
    assert "cause: mujoco: links tilted, virtual: inertia changed so that MuJoCo accepts it" in details


ROBOTS = [s.name for s in list_models() if s.origin == "example-robot-data"]
#: example-robot-data robots that do not load even with the repair: nothing moves on a fixed base, or no robot name.
UNLOADABLE = {("iris_simple", False), ("quadrotor_base", False), ("ur3", False), ("ur3", True)}


@pytest.mark.parametrize("floating", [False, True], ids=["fixed", "floating"])
@pytest.mark.parametrize("name", ROBOTS)
def test_every_example_robot_data_urdf_loads_with_repair_or_gives_a_one_line_reason(name: str, floating: bool) -> None:
    if (name, floating) in UNLOADABLE:
        with pytest.raises(ModelLoadError) as info:
            load_model(name, floating=floating, repair_inertia=True, check=False)
        msg = str(info.value)
        assert "\n" not in msg and str(resolve_model(name).path) in msg
        return
    pair = load_model(name, floating=floating, repair_inertia=True, check=False)
    repairs = [f for f in pair.findings if f.kind is Kind.REPAIR]
    if name in EXPECTED_LOAD_FAILURES and name != "ur3":  # MuJoCo refuses the file's values
        assert repairs and all(f.engine == "mujoco" and f.element.startswith("link ") for f in repairs)
    else:
        assert not repairs
