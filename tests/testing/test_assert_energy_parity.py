"""koenig_check.testing.assert_energy_parity: passes on an unaltered model, names the altered segment."""

from __future__ import annotations

import re
from pathlib import Path

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
