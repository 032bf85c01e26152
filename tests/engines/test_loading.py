"""Loading both formats into both engines: floating bases, another file for Pinocchio, couplings, failures.

(What loading into MuJoCo alone checks and changes: ``tests/engines/mujoco/test_mujoco_loading.py``.)
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import mujoco
import pytest
from engine_helpers import EXPECTED_LOAD_FAILURES, RTOL, rel_err
from urdf_builders import urdf_chain, urdf_link, write_model

from koenig_check.engines import (
    ROOT_JOINT_NAME,
    InertiaError,
    ModelLoadError,
    load_model,
    random_states,
    resolve_model,
)
from koenig_check.findings import Kind
from koenig_check.sources.catalogue import project_models_dir


def test_floating_base_uses_the_same_free_joint_name(tmp_path):
    path = urdf_chain(tmp_path, urdf_link("l2"))
    pair = load_model(path, floating=True)
    assert pair.mujoco.joint_names[0] == ROOT_JOINT_NAME == pair.pinocchio.model.names[1]
    assert pair.pinocchio.model.joints[1].shortname() == "JointModelFreeFlyer"
    assert pair.mujoco.model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    assert pair.mujoco.segment_names == (ROOT_JOINT_NAME, "j1", "j2")


def test_floating_on_a_file_that_already_floats_keeps_its_free_joint():
    pair = load_model("free_body.xml", floating=True)
    assert pair.mujoco.joint_names == ("root",) and pair.pinocchio.model.names[1] == "root"
    assert pair.mujoco.model.njnt == 1


def test_floating_urdf_with_a_world_root_link_moves_the_same_link():
    pair = load_model("TwoDofs", floating=True)  # world -> ground fixed joint with rpy 0 0 -1.57
    assert any("root link 'world'" in n for n in pair.notes)
    qpos, qvel = random_states(pair.mujoco.model, 5, seed=3)
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=list(sm.names))
    assert rel_err(sp.rotation, sm.rotation) < RTOL and rel_err(sp.v_com, sm.v_com) < RTOL


def test_changed_link_mass_is_detected_on_the_named_segment(tmp_path):
    original = project_models_dir() / "serial7.urdf"
    changed = tmp_path / "serial7_changed.urdf"
    shutil.copy(original, changed)
    text = changed.read_text()
    block = re.search(r'<link name="link5">.*?<mass value="([^"]+)"', text, flags=re.S)
    old = block.group(1)
    start, end = block.span(1)
    changed.write_text(text[:start] + str(float(old) * 1.25) + text[end:])
    pair = load_model(original, pinocchio_source=changed)
    qpos, qvel = random_states(pair.mujoco.model, 20, seed=4)
    sm = pair.mujoco.segment_states(qpos, qvel)
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=list(sm.names))
    differ = [n for n, a, b in zip(sm.names, sm.mass, sp.mass, strict=True) if abs(a - b) > RTOL * a]
    assert differ == ["j5"]
    assert sp.mass[list(sm.names).index("j5")] == pytest.approx(1.25 * float(old))
    e_mj, e_pin = pair.mujoco.kinetic_energy(qpos, qvel).rigid, pair.pinocchio.kinetic_energy(qpos, qvel).rigid
    assert rel_err(e_pin, e_mj) > 1e-6


@pytest.mark.parametrize("name", sorted(EXPECTED_LOAD_FAILURES))
def test_example_robot_data_robots_that_do_not_load(name):
    """Each failure is a one-line error naming the file and the offending element."""
    element = EXPECTED_LOAD_FAILURES[name]
    elements = element if isinstance(element, tuple) else (element, element)
    for floating, expected in zip((False, True), elements, strict=True):
        with pytest.raises(ModelLoadError) as info:
            load_model(name, floating=floating, check=False)
        msg = str(info.value)
        assert "\n" not in msg and str(resolve_model(name).path) in msg and expected in msg
        if isinstance(info.value, InertiaError):  # the refusal says which option would load the file
            assert "--repair-inertia" in msg


def test_unparsable_file_is_a_one_line_error(tmp_path):
    path = write_model(
        tmp_path, "<mujoco><worldbody><body><joint type='nonsense'/></body></worldbody></mujoco>", "bad.xml"
    )
    with pytest.raises(ModelLoadError) as info:
        load_model(path)
    assert str(path) in str(info.value) and "\n" not in str(info.value)


def test_mimic_joints_are_loaded_and_recorded_as_couplings():
    # Behaviour changed by design (issue 8): coupled joints used to be refused unless allow_coupled=True.
    pair = load_model("panda", check=False)
    (found,) = [f for f in pair.findings if f.kind is Kind.COUPLING]
    assert found.element == "joint panda_finger_joint2" and found.values["leader"] == "panda_finger_joint1"
    assert not found.affects_energy and "satisfy" in found.hint
    assert "panda_finger_joint2" in pair.mujoco.segment_names and "panda_finger_joint2" in pair.pinocchio.segment_names


def test_allow_coupled_is_a_deprecated_no_op():
    with pytest.warns(DeprecationWarning, match="allow_coupled"):
        pair = load_model("panda", check=False, allow_coupled=True)
    assert [f.kind for f in pair.findings].count(Kind.COUPLING) == 1


def test_a_model_without_moving_mass_is_refused_naming_its_links(tmp_path) -> None:
    """Energies at round-off of zero are no disagreement: nothing to compare, and which links have no mass."""
    import koenig_check
    from koenig_check.cli import main
    from koenig_check.engines.errors import NoMassError

    path = Path(__file__).parent / "models" / "massless.urdf"
    with pytest.raises(NoMassError, match=r"no mass to compare.*\(arm, hand: MuJoCo 4e-15 kg, Pinocchio 0 kg") as err:
        load_model(path, repair_inertia=True)
    assert err.value.links == ("arm", "hand") and "\n" not in str(err.value)
    check = koenig_check.compare(path, repair_inertia=True, n_poses=2)
    assert not check.ok and not check.comparisons and not check.summaries  # no formula ran on it
    assert "no mass to compare" in check.reason()
    assert main(["compare", str(path), "--repair-inertia", "--poses", "2"]) == 1
