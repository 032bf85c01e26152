"""What a failing check says (``verdict_lines``): the engines' gap read from its data, never a sentence cut apart."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.api import compare
from koenig_check.engines import load_model
from koenig_check.run.pose_kinds import make_poses
from koenig_check.testing.failure_text import verdict_lines

CLASS_MASS = Path(__file__).resolve().parents[1] / "models" / "causes" / "class_mass.xml"  # Pinocchio ignores it
#: A keyframe name holding the very text a reason used to be split at: the gap must name the pose whole.
KEY = "home; cause: none"


def _unfolded(lines: list[str]) -> list[str]:
    """The lines before folding: a continuation (indented deeper than its line) joined back to it."""
    out: list[str] = []
    for line in lines:
        if out and line.startswith("      "):
            out[-1] += " " + line.strip()
        else:
            out.append(line)
    return out


@pytest.fixture
def keyed_class_mass(tmp_path: Path) -> Path:
    path = tmp_path / "keyed.xml"
    key = f'<keyframe><key name="{KEY}" qpos="0.2 0.7"/></keyframe>'
    path.write_text(CLASS_MASS.read_text().replace("</worldbody>", "</worldbody>" + key))
    return path


def test_the_engines_gap_names_its_pose_whole_and_its_values(keyed_class_mass: Path) -> None:
    check = compare([keyed_class_mass], pose_kind="keyframes", engines=("mujoco", "pinocchio"))
    engines_lines = [line for line in _unfolded(verdict_lines(check)) if line.startswith("  engines: ")]
    assert len(engines_lines) == 1
    line = engines_lines[0]
    # The engines' own energies at that keyframe (its velocity drawn as compare draws it): an independent route.
    model = load_model(keyed_class_mass)
    pose = make_poses(model.mujoco.model, "keyframes")
    mj = float(model.mujoco.kinetic_energy(pose.qpos, pose.qvel).rigid[0])
    pn = float(model.pinocchio.kinetic_energy(pose.qpos, pose.qvel).rigid[0])
    assert abs(mj - pn) > 1e-3 * max(mj, pn)  # they disagree: Pinocchio ignores the class's geom mass
    assert line.endswith(f"at pose key:{KEY} (MuJoCo {mj:.9g} J, Pinocchio {pn:.9g} J)"), line
    cause = check.agreements[0].cause
    assert cause and cause not in line  # the cause has its own line ("root cause: ..."), not repeated here
    assert any(cause in other for other in _unfolded(verdict_lines(check)) if other.startswith("  root cause: "))


def test_the_agreement_s_reason_is_built_from_its_symptoms_and_cause(keyed_class_mass: Path) -> None:
    agreement = compare([keyed_class_mass], pose_kind="keyframes", engines=("mujoco", "pinocchio")).agreements[0]
    assert not agreement.agrees and agreement.symptoms and agreement.cause
    assert agreement.reason == "; ".join([*agreement.symptoms, f"cause: {agreement.cause}"])
