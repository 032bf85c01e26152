"""A construct of Pinocchio's MJCF traps is a root cause only where the engines' segments show its symptom.

A geom mass from a default class, or a mesh geom, is what Pinocchio 4.1's MJCF parser reads otherwise; in these
files it changes nothing (the class's mass equals density × volume; the mesh sits in a body with its own
``<inertial>``).  The engines agree, shown independently from their own mass matrices
(:mod:`independent_energy`); naming the construct as a root cause would fail ``parity`` on a clean model.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from independent_energy import engines_agree
from koenig_check.cli import main
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.pair_causes import model_causes
from koenig_check.engines import load_model

MODELS = Path(__file__).resolve().parents[1] / "models"
CAUSES = MODELS / "causes"
#: Files with a construct of the traps that changes nothing: the engines agree.
HARMLESS = MODELS / "harmless"


@pytest.mark.parametrize("name", ["class_mass_as_density.xml", "mesh_with_inertial.xml"])
def test_a_construct_that_changes_nothing_is_no_root_cause(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    pair = load_model(HARMLESS / name)
    assert engines_agree(pair) is True  # mj_fullM and crba: the same robot
    causes, _ = model_causes(pair)
    assert causes == [], [c.message() for c in causes]
    report = import_parity(pair)
    assert report.clean and report.causes == []
    assert main(["parity", str(HARMLESS / name), "--engines", "mujoco,pinocchio"]) == 0
    _out, err = capsys.readouterr()
    assert err == ""


def test_the_class_mass_is_a_cause_where_it_differs_from_density_times_volume(tmp_path: Path) -> None:
    """The same file with a class mass of 5 kg instead of 8: Pinocchio keeps 8 kg, the construct is named."""
    path = tmp_path / "class_mass_5kg.xml"
    path.write_text((HARMLESS / "class_mass_as_density.xml").read_text().replace('mass="8"', 'mass="5"'))
    pair = load_model(path)
    assert engines_agree(pair) is False
    (cause,) = model_causes(pair)[0]
    assert (cause.element, cause.values["mujoco"], cause.values["pinocchio"]) == (
        "geom arm_box",
        5.0,
        pytest.approx(8.0),
    )


def test_causes_that_change_the_energy_come_before_those_that_do_not(tmp_path: Path) -> None:
    """A <frame> holding a world geom (a rail) comes first in the file and changes nothing that moves; the class
    mass of the pole changes the energy (the engines' own mass matrices differ).  The parity report lists the
    pole's cause first."""
    path = tmp_path / "class_mass_rail.xml"
    text = (CAUSES / "class_mass.xml").read_text()
    rail = '    <frame pos="0 0 -0.5"><geom name="rail" type="box" size="2 0.05 0.05"/></frame>\n'
    path.write_text(text.replace("  <worldbody>\n", "  <worldbody>\n" + rail, 1))
    pair = load_model(path)
    assert engines_agree(pair) is False
    causes, _ = model_causes(pair)
    assert [(c.element, c.affects_energy) for c in causes] == [("geom pole", True), ("frame #1 in worldbody", False)]
    assert [c.element for c in import_parity(pair).causes] == ["geom pole", "frame #1 in worldbody"]
