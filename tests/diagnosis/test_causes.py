"""Root causes of engine disagreements, one small MJCF per trap of Pinocchio 4.1's MJCF parser.

Each test asserts the verdict (``koenig_check.compare(...).ok`` and its one-line reason, which must carry the
cause's own message) and the typed cause (kind, engine, element, values); the disagreement itself is confirmed
independently from the engines' own mass matrices (:mod:`independent_energy`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

import koenig_check
from independent_energy import engines_agree
from koenig_check.causes import cause as catalogued
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.reason import short_cause
from koenig_check.engines import load_model
from koenig_check.findings import Finding, Kind, KoenigCheckError
from koenig_check.modelfile.compiler import compiler_findings
from koenig_check.report.parity_table import format_parity

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"


def _compare(name: str) -> Any:
    return koenig_check.compare(CAUSES / name, n_poses=3, formulas=["exact"])


def _load_error(name: str) -> KoenigCheckError:
    with pytest.raises(KoenigCheckError) as info:
        load_model(CAUSES / name)
    return info.value


def _only(causes: list[Finding], kind: Kind) -> Finding:
    found = [c for c in causes if c.kind is kind]
    assert len(found) == 1, [c.message() for c in causes]
    return found[0]


def test_include_inside_a_body_is_named() -> None:
    err = _load_error("include_in_body.xml")
    cause = _only(err.causes, Kind.IGNORED_CONSTRUCT)
    assert (cause.engine, cause.element, cause.root_cause, cause.affects_energy) == (
        "pinocchio",
        "include arm_part.xml",
        True,
        True,
    )
    assert cause.values["in"] == "body upper"
    assert cause.values["joints"] == ("elbow",) and cause.values["bodies"] == ("forearm",)
    check = _compare("include_in_body.xml")
    assert not check.ok
    ((_label, reason),) = check.failures
    assert cause.message() in reason and "include_in_body.xml" in reason and "\n" not in reason


def test_include_in_worldbody_is_named_when_pinocchio_fails() -> None:
    err = _load_error("include_in_worldbody.xml")
    assert "No such node (body)" in str(err)  # Pinocchio's own reason stays in the message
    cause = _only(err.causes, Kind.IGNORED_CONSTRUCT)
    assert (cause.engine, cause.element) == ("pinocchio", "include robot_part.xml")
    assert cause.values["in"] == "mujoco" and cause.values["joints"] == ("shoulder",)
    check = _compare("include_in_worldbody.xml")  # the reason names it in a few words, the failure whole
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.failures[0][1]


def test_root_bodies_after_the_first_are_named_with_their_joints() -> None:
    err = _load_error("several_roots.xml")
    causes = [c for c in err.causes if c.kind is Kind.IGNORED_CONSTRUCT]
    assert [c.element for c in causes] == ["body b", "body d"]
    b, d = causes
    assert b.values["joints"] == ("jb", "jc") and b.affects_energy and b.segments == ("jb", "jc")
    assert d.values["joints"] == () and not d.affects_energy  # welded to the world: no kinetic energy
    assert all(c.engine == "pinocchio" and c.root_cause for c in causes)
    check = _compare("several_roots.xml")
    assert not check.ok and short_cause(b) in check.reason() and b.message() in check.failures[0][1]


def test_posed_jointless_root_is_a_frame_note_and_the_engines_agree() -> None:
    pair = load_model(CAUSES / "posed_root.xml")
    assert engines_agree(pair, n_poses=3) is True
    report = import_parity(pair)
    frame = _only(report.causes, Kind.FRAME)
    assert (frame.engine, frame.element, frame.affects_energy, frame.root_cause) == (
        "pinocchio",
        "body base",
        False,
        True,
    )
    assert frame.values["mujoco pos"] == pytest.approx((0.3, -0.2, 1.0))
    assert frame.values["pinocchio pos"] == pytest.approx((0.0, 0.0, 0.0))
    # compared after removing the constant transform: no segment's COM, anchor or axis is flagged
    assert report.clean and not report.differing_segments and not report.differing_dofs, format_parity(report)
    assert koenig_check.compare(CAUSES / "posed_root.xml", n_poses=3, formulas=["exact"]).ok


def test_class_mass_is_named_even_when_the_raw_file_does_not_compile(monkeypatch) -> None:
    # dm_control's fruitfly.xml compiles only through the loader's mesh fixes: the cause then carries
    # the engines' own segment masses instead of MuJoCo's density × volume.
    import koenig_check.diagnosis.pair_causes as causes

    def fails(*_args: Any) -> dict:
        raise ValueError("Error: Error opening file 'head_body.msh'")

    monkeypatch.setattr(causes, "_mass_values", fails)
    pair = load_model(CAUSES / "class_mass.xml")
    cause = _only(import_parity(pair).causes, Kind.MASS)
    assert cause.element == "geom pole"
    r = 0.045  # the pole's segment: 0.1 kg in MuJoCo, density 1000 × capsule volume in Pinocchio
    assert cause.values["mujoco mass of segments"] == pytest.approx(0.1)
    assert cause.values["pinocchio mass of segments"] == pytest.approx(1000 * (np.pi * r**2 + 4 / 3 * np.pi * r**3))


def test_geom_mass_from_a_default_class_is_named_with_both_masses() -> None:
    pair = load_model(CAUSES / "class_mass.xml")
    assert engines_agree(pair) is False
    report = import_parity(pair)
    cause = _only(report.causes, Kind.MASS)
    assert (cause.engine, cause.element, cause.affects_energy) == ("pinocchio", "geom pole", True)
    assert cause.values["class"] == "pole" and cause.values["geoms"] == ("pole",)
    assert cause.values["mujoco"] == pytest.approx(0.1)
    # density 1000 × capsule volume (r = 0.045, length 1): π r² l + 4/3 π r³, computed here by hand
    r = 0.045
    assert cause.values["pinocchio"] == pytest.approx(1000 * (np.pi * r**2 * 1.0 + 4 / 3 * np.pi * r**3))
    assert cause.segments == ("hinge",)
    assert report.headline().startswith("root cause: " + cause.message())
    check = _compare("class_mass.xml")
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.agreements[0].reason


def test_geom_mass_written_on_the_geom_is_honoured() -> None:
    pair = load_model(CAUSES / "class_mass_explicit.xml")
    assert engines_agree(pair) is True
    assert import_parity(pair).causes == []
    assert _compare("class_mass_explicit.xml").ok


def test_joint_positions_from_a_default_class_are_named() -> None:
    """The rodent's construct: equal masses, joints placed at the body origin by Pinocchio."""
    pair = load_model(CAUSES / "class_joint_pos.xml")
    assert engines_agree(pair) is False
    report = import_parity(pair)
    assert report.total_mass[0] == pytest.approx(report.total_mass[1], rel=1e-12)
    cause = _only(report.causes, Kind.ANCHOR)
    assert cause.engine == "pinocchio" and cause.values["class"] == "lumbar"  # also for class lumbar_bend below it
    assert set(cause.values["joints"]) == {"vertebra_1_extend", "vertebra_1_bend", "vertebra_2_extend"}
    assert cause.values["mujoco"] == pytest.approx((0.03, 0.0, -0.03))
    assert cause.values["pinocchio"] == pytest.approx((0.0, 0.0, 0.0))
    check = _compare("class_joint_pos.xml")
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.agreements[0].reason


def test_joint_positions_written_on_the_joints_are_honoured() -> None:
    pair = load_model(CAUSES / "class_joint_pos_explicit.xml")
    assert engines_agree(pair) is True
    assert import_parity(pair).causes == []


def test_childclass_geom_types_are_read_as_mujoco_resolves_them() -> None:
    pair = load_model(CAUSES / "childclass_geom_type.xml")
    assert engines_agree(pair) is True  # Pinocchio applies geom types from classes
    lines = [f for f in compiler_findings(CAUSES / "childclass_geom_type.xml", pair.mujoco.model) if "<inertial>" in f]
    assert len(lines) == 2 and all("['capsule']" in f for f in lines), lines
    assert import_parity(pair).causes == [] and _compare("childclass_geom_type.xml").ok


def test_nothing_moves_says_so_and_offers_floating() -> None:
    err = _load_error("nothing_moves.xml")
    (cause,) = err.causes
    assert (cause.kind, cause.engine, cause.element, cause.affects_energy) == (
        Kind.NOTHING_MOVES,
        "file",
        "model",
        False,
    )
    assert "--floating" in cause.hint
    assert "nothing to compare" in str(err) and "--floating" in str(err) and "nothing_moves.xml" in str(err)
    assert koenig_check.compare(CAUSES / "nothing_moves.xml", floating=True, n_poses=2, formulas=["exact"]).ok


def test_mesh_geoms_are_named_when_pinocchio_gets_another_mass() -> None:
    pair = load_model(CAUSES / "mesh_geom.xml")
    assert engines_agree(pair) is False
    cause = _only(import_parity(pair).causes, Kind.MASS)
    assert (cause.engine, cause.element, cause.segments) == ("pinocchio", "geom shell", ("jb",))
    assert cause.values["mujoco"] == pytest.approx(0.3) and cause.values["pinocchio"] == pytest.approx(1.0)
    check = _compare("mesh_geom.xml")
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.agreements[0].reason


def test_a_visual_mesh_geom_is_said_to_count_as_nothing_not_1_kg(tmp_path) -> None:
    """robosuite's inspire and fourier hands: a visual mesh (contype=0 conaffinity=0) beside each collision mesh."""
    import pinocchio as pin

    path = tmp_path / "mesh_visual.xml"
    look = '<geom name="look" type="mesh" mesh="tet" mass="0.2" contype="0" conaffinity="0"/>'
    path.write_text((CAUSES / "mesh_geom.xml").read_text().replace('<geom name="shell"', look + '<geom name="shell"'))
    pmodel = pin.buildModelFromMJCF(str(path))
    assert pmodel.inertias[pmodel.getJointId("jb")].mass == pytest.approx(1.0)  # shell 1 kg, look nothing
    cause = _only(import_parity(load_model(path)).causes, Kind.MASS)
    assert cause.values["geoms"] == ("shell", "look") and cause.values["visual geoms"] == ("look",)  # weighed first
    assert cause.values["mujoco"] == pytest.approx(0.5) and cause.values["pinocchio"] == pytest.approx(1.0)
    assert "look: contype=0 and conaffinity=0, read as visual only, count as nothing" in cause.summary


def test_include_of_a_welded_part_is_named_and_changes_the_energy() -> None:
    pair = load_model(CAUSES / "include_welded_in_body.xml")  # the joints pair: only mass is missing
    assert engines_agree(pair) is False
    cause = _only(import_parity(pair).causes, Kind.IGNORED_CONSTRUCT)
    assert (cause.element, cause.affects_energy, cause.segments) == ("include tool_part.xml", True, ("shoulder",))
    assert cause.values["bodies"] == ("tool",) and cause.values["joints"] == ()
    check = _compare("include_welded_in_body.xml")
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.agreements[0].reason


def test_bodies_inside_a_frame_are_named_when_joints_do_not_pair() -> None:
    err = _load_error("frame_body.xml")
    assert "only in MuJoCo: j2)" in str(err)  # the pairing error stays whole, its names listed (not a Python list)
    cause = _only(err.causes, Kind.IGNORED_CONSTRUCT)
    assert (cause.engine, cause.element, cause.affects_energy) == ("pinocchio", "frame #1 in body base", True)
    assert cause.values["bodies"] == ("arm",) and cause.values["joints"] == ("j2",)
    assert cause.message() in str(err) and "\n" not in str(err)


def test_a_root_body_inside_a_frame_is_named_when_pinocchio_fails() -> None:
    err = _load_error("frame_root.xml")
    assert "No such node (body)" in str(err)
    cause = _only(err.causes, Kind.IGNORED_CONSTRUCT)
    assert cause.element == "frame #1 in worldbody" and cause.values["bodies"] == ("base",)


def test_geoms_inside_a_frame_are_named_with_the_segment_they_weigh_on() -> None:
    pair = load_model(CAUSES / "frame_geom.xml")
    assert engines_agree(pair) is False  # independent: the engines' own mass matrices differ
    causes = [c for c in import_parity(pair).causes if c.kind is Kind.IGNORED_CONSTRUCT]
    assert len(causes) == 1, [c.message() for c in causes]
    cause = causes[0]
    assert (cause.engine, cause.element, cause.segments) == ("pinocchio", "frame #1 in body base", ("j1",))
    assert cause.values["geoms"] == 1 and cause.affects_energy
    # MuJoCo's segment carries the frame's 2 kg sphere, Pinocchio's does not.
    q0, zero = pair.mujoco.model.qpos0[None], np.zeros((1, 1))
    masses = {name: e.segment_states(q0, zero).mass[0] for name, e in pair.engines.items()}
    assert masses == pytest.approx({"mujoco": 3.0, "pinocchio": 1.0})


def test_geoms_of_a_body_with_its_own_inertial_are_not_causes() -> None:
    """Menagerie robotiq_2f85's construct: pad_box's class mass and position change nothing (its body has an
    <inertial>); the same class on pad_bare_box (no <inertial>) and class 'link' on finger_box are causes."""
    pair = load_model(CAUSES / "class_geom_inertial.xml")
    assert engines_agree(pair) is False
    causes = import_parity(pair).causes
    named = {(c.kind, c.values["class"]): c for c in causes}
    assert set(named) == {(Kind.MASS, "link"), (Kind.MASS, "pad"), (Kind.COM, "pad")}, [c.message() for c in causes]
    for cause in causes:
        assert "pad_box" not in cause.values["geoms"] and "pad_box" not in cause.element.split(", ")
    assert named[(Kind.MASS, "pad")].values["geoms"] == ("pad_bare_box",)
    # by hand: 0.02 kg from the class in MuJoCo, density 1000 × (0.02 m)³ in Pinocchio
    assert named[(Kind.MASS, "pad")].values["mujoco"] == pytest.approx(0.02)
    assert named[(Kind.MASS, "pad")].values["pinocchio"] == pytest.approx(1000 * 0.02**3)
    assert named[(Kind.COM, "pad")].values["geoms"] == ("pad_bare_box",)
    assert named[(Kind.MASS, "link")].values["geoms"] == ("finger_box",)


def test_geom_position_from_a_default_class_is_named() -> None:
    """MuJoCo puts the body's centre of mass at the class's geom position; Pinocchio at the body origin."""
    pair = load_model(CAUSES / "class_geom_pos.xml")
    assert engines_agree(pair) is False
    cause = _only(import_parity(pair).causes, Kind.COM)
    assert (cause.engine, cause.element, cause.affects_energy) == ("pinocchio", "geom arm_box", True)
    assert cause.values["class"] == "offset" and cause.segments == ("hinge",)
    assert cause.values["mujoco"] == pytest.approx((0.1, 0.0, 0.05))
    assert cause.values["pinocchio"] == pytest.approx((0.0, 0.0, 0.0))
    check = _compare("class_geom_pos.xml")
    assert not check.ok and short_cause(cause) in check.reason() and cause.message() in check.agreements[0].reason


def test_geoms_are_causes_again_when_the_compiler_takes_inertia_from_geoms(tmp_path: Path) -> None:
    """``inertiafromgeom="true"`` makes both engines use the geoms even where an <inertial> is written."""
    path = tmp_path / "class_geom_inertial_from_geoms.xml"
    text = (CAUSES / "class_geom_inertial.xml").read_text()
    path.write_text(text.replace("<mujoco>", '<mujoco>\n  <compiler inertiafromgeom="true"/>', 1))
    pair = load_model(path)
    mass = {c.values["class"]: c for c in import_parity(pair).causes if c.kind is Kind.MASS}
    assert mass["pad"].values["geoms"] == ("pad_box", "pad_bare_box")
    assert mass["pad"].values["mujoco"] == pytest.approx(2 * 0.02)
    assert mass["pad"].values["pinocchio"] == pytest.approx(2 * 1000 * 0.02**3)


def test_an_include_in_a_body_and_further_root_bodies_are_both_named() -> None:
    """gymnasium-robotics kitchen's construct: the included file's top element is <mujocoinclude>, the first
    root body has no name. Both root causes are named, each body by something the reader can find."""
    err = _load_error("include_and_roots.xml")
    found = {c.element: c for c in err.causes}
    assert set(found) == {"include arm_part_mujocoinclude.xml", "body kettle"}, [c.message() for c in err.causes]
    include = found["include arm_part_mujocoinclude.xml"]
    assert (include.cause, found["body kettle"].cause) == ("pinocchio.mjcf.include", "pinocchio.mjcf.root-bodies")
    assert include.values["joints"] == ("elbow",) and include.values["bodies"] == ("forearm",)
    assert include.root_cause and include.affects_energy
    assert found["body kettle"].values["joints"] == ("lid",)
    text = str(err)
    assert "?" not in text and "\n" not in text
    assert "first root body, unnamed, with joint 'shoulder'" in include.values["in"]
    assert "first root body, unnamed, with joint 'shoulder'" in found["body kettle"].message()
    check = _compare("include_and_roots.xml")
    # the first cause in a few words, the other counted as a root cause (never a name without its cause)
    include_short = f"{include.element}: {catalogued('pinocchio.mjcf.include').brief}"
    assert not check.ok and include_short in check.reason() and "; and 1 more root cause" in check.reason()
    assert all(c.message() in check.failures[0][1] for c in err.causes)
