"""engines/finite.py: a non-finite number is refused, a large finite one is the engines' to judge (a note).

sdformat's ``urdf_gazebo_extensions.urdf`` places 100 kg sensor links hundreds of metres away; MuJoCo fuses them
into their carrier, whose inertia then passes 1e6 kg m².  Both engines load it and agree; our plausibility bound
refused it (issue 28, item 3).  ``far_sensors.urdf`` is its small twin.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import koenig_check
from koenig_check.engines import ModelLoadError, load_model
from koenig_check.engines.finite import check_finite
from koenig_check.findings import Kind

MODELS = Path(__file__).parent / "models"
FAR = MODELS / "far_sensors.urdf"


def test_hand_inertia_of_the_fused_link() -> None:
    """The model is what its comment says (by hand: 2 × 100 × 333² + 2 × 1 + 0.01 about y and z, 2.01 about x)."""
    model = mujoco.MjModel.from_xml_path(str(FAR))
    link0 = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "link0")
    big = 2 * 100 * 333.0**2 + 2 * 1.0 + 0.01
    assert model.body_mass[link0] == pytest.approx(201.0, rel=1e-15)
    assert sorted(model.body_inertia[link0]) == pytest.approx([2.01, big, big], rel=1e-12)
    assert big > 1e6  # above the old bound


def test_large_finite_value_is_a_note_not_a_refusal() -> None:
    check = koenig_check.compare(FAR, n_poses=5)
    assert check.ok, check.reasons()
    (comparison,) = check.comparisons
    notes = [f for f in comparison.findings if f.kind is Kind.LOAD and "value" in f.values]
    assert {f.engine for f in notes} == {"mujoco", "pinocchio"}
    mujoco_note = next(f for f in notes if f.engine == "mujoco")
    assert mujoco_note.element == "body link0" and mujoco_note.values["value"] > 1e6
    assert not any(f.affects_energy for f in notes)


@pytest.mark.parametrize("value", [np.nan, np.inf])
def test_non_finite_value_is_still_refused(value: float) -> None:
    """The engines' compiled arrays poked (the parsers refuse such files before): still an error, naming the body."""
    pair = load_model(FAR)
    mj_model = pair.mujoco.model
    link0 = mujoco.mj_name2id(mj_model, mujoco.mjtObj.mjOBJ_BODY, "link0")
    mj_model.body_inertia[link0, 2] = value
    with pytest.raises(ModelLoadError) as info:
        check_finite(mj_model, pair.pinocchio.model, "far_sensors.urdf", ("mujoco", "pinocchio"))
    assert "far_sensors.urdf" in str(info.value) and "link0" in str(info.value)


def test_energies_agree_with_an_independent_route() -> None:
    """Each engine's own energy equals the hand value ½ I_zz q̇² of one hinge about z through the centre of mass."""
    pair = load_model(FAR)
    qpos, qvel = np.array([[0.3]]), np.array([[1.7]])
    big = 2 * 100 * 333.0**2 + 2 * 1.0 + 0.01
    for engine in (pair.mujoco, pair.pinocchio):
        energy = engine.kinetic_energy(qpos, qvel).rigid
        assert float(energy[0]) == pytest.approx(0.5 * big * 1.7**2, rel=1e-12)
