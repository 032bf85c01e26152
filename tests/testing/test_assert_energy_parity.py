"""koenig_check.testing.assert_energy_parity: passes on an unaltered model, names the altered segment."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from koenig_check.testing import assert_energy_parity

MODELS = Path(__file__).resolve().parents[2] / "models"


@pytest.mark.parametrize("name", ["serial7.urdf", "serial7.xml", "gimbal.xml", "double_pendulum.urdf"])
def test_passes_on_unaltered_models(name: str) -> None:
    assert_energy_parity(MODELS / name, n_poses=10)


def test_passes_for_the_mjcf_against_its_urdf() -> None:
    assert_energy_parity(MODELS / "serial7.xml", pinocchio_model=MODELS / "serial7.urdf", n_poses=10)


def test_names_the_segment_of_a_link_whose_mass_changed(tmp_path: Path) -> None:
    text = (MODELS / "serial7.urdf").read_text()
    altered, n = re.subn(r'(<link name="link5">.*?<mass value=")1.2(")', r"\g<1>1.5\g<2>", text, count=1, flags=re.S)
    assert n == 1
    copy = tmp_path / "serial7_heavier_link5.urdf"
    copy.write_text(altered)
    with pytest.raises(AssertionError) as info:
        assert_energy_parity(MODELS / "serial7.urdf", pinocchio_model=copy, n_poses=10)
    message = str(info.value)
    assert "link link5 (joint j5) at pose random-" in message  # the link the user wrote, and its joint
    assert "import parity: mass differ" in message
    assert re.search(r"difference [+-]\d", message)


def test_armature_difference_between_mjcf_and_urdf_is_caught() -> None:
    # The URDF cannot carry armature: the energies differ by exactly the rotor term.
    with pytest.raises(AssertionError, match="armature energy at pose random-"):
        assert_energy_parity(MODELS / "armature_chain.xml", pinocchio_model=MODELS / "armature_chain.urdf", n_poses=5)
    assert_energy_parity(
        MODELS / "armature_chain.xml", pinocchio_model=MODELS / "armature_chain.urdf", n_poses=5, include_armature=False
    )


def test_total_energy_line_gives_each_engines_own_energy_at_the_worst_pose(tmp_path: Path) -> None:
    """The message's total line, recomputed with Pinocchio's own computeKineticEnergy on each file.

    serial7 is all revolute joints in file order (q = qpos, v = qvel); the unaltered file's energy is MuJoCo's (the
    engines agree on it, test_passes_on_unaltered_models), the copy's is Pinocchio's.  link5 is 2.5e-7 heavier in the
    copy (relative): the totals differ by less than that, beyond rtol 1e-9 yet far below a loose tolerance, and the
    line names the pose where the difference is largest.
    """
    import pinocchio as pin

    from koenig_check.engines import load_model
    from koenig_check.run.poses import random_poses

    text = (MODELS / "serial7.urdf").read_text()
    link5 = r'(<link name="link5">.*?<mass value=")1.2(")'
    altered, n = re.subn(link5, r"\g<1>1.2000003\g<2>", text, count=1, flags=re.S)
    assert n == 1
    copy = tmp_path / "serial7_slightly_heavier_link5.urdf"
    copy.write_text(altered)
    with pytest.raises(AssertionError) as info:
        assert_energy_parity(MODELS / "serial7.urdf", pinocchio_model=copy, n_poses=10, seed=3)
    found = re.search(
        r"total rigid-body energy at pose random-(\d+): MuJoCo (\S+) J, Pinocchio (\S+) J \((\S+) relative\)",
        str(info.value),
    )
    assert found, str(info.value)
    k, mj_energy, pin_energy, rel = int(found[1]), float(found[2]), float(found[3]), float(found[4])

    poses = random_poses(load_model(MODELS / "serial7.urdf").mujoco.model, 10, seed=3)
    energies = []
    for path in (MODELS / "serial7.urdf", copy):
        model = pin.buildModelFromUrdf(str(path))
        data = model.createData()
        assert model.nq == model.nv == poses.qpos.shape[1] == 7
        pairs = zip(poses.qpos, poses.qvel, strict=True)
        energies.append(np.array([pin.computeKineticEnergy(model, data, q, v) for q, v in pairs]))
    original, heavier = energies
    worst = int(np.argmax(np.abs(heavier - original) / np.abs(original)))
    assert poses.ids[k] == f"random-{k}" and k == worst
    assert mj_energy == pytest.approx(original[k], rel=1e-8)
    assert pin_energy == pytest.approx(heavier[k], rel=1e-8)
    assert rel == pytest.approx(abs(heavier[k] - original[k]) / original[k], rel=1e-2)
    assert 1e-8 < rel < 2.5e-7


def test_the_root_cause_comes_first_then_the_verdicts_of_three_engines() -> None:
    """As the plugin's failure: the root cause, then "three engines: ..." lines, then the symptoms."""
    pytest.importorskip("pydrake")
    causes = Path(__file__).resolve().parents[1] / "models" / "causes"
    with pytest.raises(AssertionError) as info:
        assert_energy_parity(causes / "class_mass.xml", engines=("mujoco", "pinocchio", "drake"))
    text = str(info.value)
    root = text.index("root cause: pinocchio: geom pole: geom mass from default class 'pole'")
    verdict = text.index("three engines: pinocchio: rigid-body energy: Pinocchio departs (MuJoCo and Drake agree)")
    assert root < verdict < text.index("body pole (joint hinge) at pose")
