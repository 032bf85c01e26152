"""Root causes in the order of their effect on the energy: dm_control's Jaco leads with its meshes."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from common import dm_control_root

import koenig_check
from koenig_check.causes import cause
from koenig_check.diagnosis.cause_effect import by_effect, effect
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.reason import ordered_causes
from koenig_check.engines import load_model
from koenig_check.findings import Finding, Kind


def _mass(engine: str, mujoco_kg: float, other_kg: float, name: str) -> Finding:
    values = {"mujoco": mujoco_kg, engine: other_kg}
    return Finding(Kind.MASS, engine, f"geom {name}", "mass read another way", values, True, True)


def test_mass_causes_are_ordered_by_the_mass_they_change_and_others_keep_their_place() -> None:
    small, large = _mass("pinocchio", 0.5, 0.51, "small"), _mass("pinocchio", 0.1, 3.0, "large")
    frame = Finding(Kind.IGNORED_CONSTRUCT, "pinocchio", "frame f", "skipped", {}, True, True)
    anchor = Finding(Kind.ANCHOR, "drake", "joint j", "moved", {"mujoco": [0, 0, 9.0], "drake": [0, 0, 0]}, True, True)
    assert effect(large) == pytest.approx(2.9) and effect(frame) is None and effect(anchor) is None  # m is no kg
    assert by_effect([frame, small, anchor, large]) == [frame, large, anchor, small]


def _moving_mass(pair) -> tuple[float, float]:
    """Each engine's moving mass, from its own model (the bodies that a joint moves)."""
    model = pair.mujoco.model
    moving = [b for b in range(1, model.nbody) if model.body_weldid[b] != 0]
    pin = pair.pinocchio.model
    moving_pin = [pin.inertias[i].mass for i in range(1, pin.njoints)]
    return float(model.body_mass[moving].sum()), float(np.sum(moving_pin))


@pytest.mark.parametrize("name", ["jaco_hand.xml", "jaco_arm.xml"])
def test_jaco_leads_with_its_meshes_not_with_a_class_mass(name: str) -> None:
    pytest.importorskip("dm_control")
    path = dm_control_root() / "third_party" / "kinova" / name
    pair = load_model(path)
    model = pair.mujoco.model
    meshes = {model.geom(g).name for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH}
    mj_kg, pin_kg = _moving_mass(pair)
    causes = ordered_causes(import_parity(pair).as_findings())
    lead = causes[0]
    # the lead cause is the meshes': every geom it names is a mesh, and it carries most of the engines' mass gap
    assert lead.kind is Kind.MASS and set(lead.values["geoms"]) <= meshes and lead.cause == "pinocchio.mjcf.mesh-mass"
    assert abs(lead.values["pinocchio"] - lead.values["mujoco"]) > 0.5 * abs(pin_kg - mj_kg)
    classes = [c for c in causes if c.cause == "pinocchio.mjcf.class-geom-mass"]
    assert classes and causes.index(classes[0]) > 0  # the class's mass comes after
    reason = koenig_check.compare(path, n_poses=2, formulas=["exact"]).reason()
    assert reason.startswith(f"{name}: root cause: geom {lead.element.split()[1].rstrip(',')} (+")
    assert cause("pinocchio.mjcf.mesh-mass").brief in reason.split("; and ")[0]


def test_the_reason_names_the_root_cause_that_changes_the_most_mass_first() -> None:
    """Found in file order (0.01 kg first), named by effect: the 2.9 kg cause leads, also in the one-line reason."""
    from koenig_check.diagnosis.reason import disagreement_cause

    small, large = _mass("pinocchio", 0.5, 0.51, "small"), _mass("pinocchio", 0.1, 3.0, "large")
    assert ordered_causes([small, large]) == [large, small]
    text = disagreement_cause([small, large])  # one cause on two geoms: named together, the larger first
    assert text == "pinocchio: geoms large, small: mass read another way"
