"""What the parity table calls its masses."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.cli import main


def test_parity_says_moving_mass_and_the_whole_models_mass(capsys: pytest.CaptureFixture[str]) -> None:
    """ur5's base is welded to the world: its mass is the model's, not what moves."""
    assert main(["parity", "ur5"]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("moving mass:"))
    moving = float(line.split("MuJoCo ")[1].split(" kg")[0])
    whole = float(line.split("in Pinocchio: ")[1].split(" kg")[0])
    assert whole == pytest.approx(moving + 4.0)  # base_link's 4 kg, from ur5_robot.urdf


MODELS = Path(__file__).parent / "models"


def test_a_dof_whose_segment_is_massless_in_pinocchio_says_so_not_nan(capsys: pytest.CaptureFixture[str]) -> None:
    """brax's half_cheetah (bshin, fshin): a segment whose only geom Pinocchio reads as visual has no Jacobian of its
    own there; the dof row says what is missing (issue 28, item 4), and the other dof is still compared."""
    import pinocchio as pin

    path = MODELS / "massless_in_pinocchio.xml"
    model = pin.buildModelFromMJCF(str(path))  # Pinocchio's own reading: b (joint j2) weighs nothing
    assert model.inertias[model.getJointId("j2")].mass == 0.0 and model.inertias[model.getJointId("j")].mass > 0
    main(["parity", str(path)])
    out = capsys.readouterr().out
    assert "nan" not in out.lower()
    rows = {line.split()[0]: line for line in out.splitlines() if line.startswith(("j ", "j2 "))}
    assert "Jacobian not compared: segment j2 massless in Pinocchio" in rows["j2"]
    assert rows["j"].split()[3] == "0.00e+00" and rows["j"].endswith("same")
