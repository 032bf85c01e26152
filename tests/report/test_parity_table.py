"""What the parity table calls its masses."""

from __future__ import annotations

import pytest

from koenig_check.cli import main


def test_parity_says_moving_mass_and_the_whole_models_mass(capsys: pytest.CaptureFixture[str]) -> None:
    """ur5's base is welded to the world: its mass is the model's, not what moves."""
    assert main(["parity", "ur5"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("moving mass:"))
    moving = float(line.split("MuJoCo ")[1].split(" kg")[0])
    whole = float(line.split("in Pinocchio: ")[1].split(" kg")[0])
    assert whole == pytest.approx(moving + 4.0)  # base_link's 4 kg, from ur5_robot.urdf
