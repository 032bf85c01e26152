"""Loading both formats into both engines: meshes, inertia checks, floating bases, load notes, failures."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import mujoco
import numpy as np
import pytest
from engine_helpers import EXPECTED_LOAD_FAILURES, RTOL, rel_err

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


def _urdf(links: str, joints: str) -> str:
    return f'<robot name="t">{links}{joints}</robot>'


def _link(name: str, mass: float | None = 1.0, inertia=(0.1, 0.2, 0.25, 0.0, 0.0, 0.0), extra: str = "") -> str:
    if mass is None:
        return f'<link name="{name}">{extra}</link>'
    ixx, iyy, izz, ixy, ixz, iyz = inertia
    return (
        f'<link name="{name}"><inertial><origin xyz="0.05 0.02 0.01"/><mass value="{mass}"/>'
        f'<inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="{ixy}" ixz="{ixz}" iyz="{iyz}"/></inertial>{extra}</link>'
    )


def _joint(name: str, parent: str, child: str, kind: str = "revolute", xyz: str = "0 0 0.3") -> str:
    limit = '<limit lower="-2" upper="2" effort="1" velocity="1"/>' if kind == "revolute" else ""
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{xyz}" rpy="0.1 0 0.2"/><axis xyz="0 1 0"/>{limit}</joint>'
    )


def _write(tmp_path, text: str, name: str = "robot.urdf"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _chain(tmp_path, l2: str, extra_links: str = "", extra_joints: str = ""):
    text = _urdf(
        _link("base") + _link("l1") + l2 + extra_links,
        _joint("j1", "base", "l1") + _joint("j2", "l1", "l2") + extra_joints,
    )
    return _write(tmp_path, text)


BAD_TRIANGLE = (0.001, 0.001, 0.01, 0.0, 0.0, 0.0)


def test_triangle_inequality_violation_names_the_link(tmp_path):
    path = _chain(tmp_path, _link("l2", 0.5, BAD_TRIANGLE))
    with pytest.raises(InertiaError) as info:
        load_model(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg and "link 'l2'" in msg
    assert "A + B >= C" in msg and "0.001, 0.001, 0.01" in msg and "balance_inertia=True" in msg


def test_balance_inertia_loads_and_records_the_change(tmp_path):
    path = _chain(tmp_path, _link("l2", 0.5, BAD_TRIANGLE))
    pair = load_model(path, balance_inertia=True)
    (found,) = [f for f in pair.findings if f.kind is Kind.REPAIR]
    assert found.engine == "mujoco" and found.element == "link l2" and found.segments == ("j2",)
    assert "balanceinertia" in found.summary and found.affects_energy and found.root_cause
    assert found.values["moments before"] == pytest.approx([0.001, 0.001, 0.01])
    after = np.array(found.values["moments after"])
    assert after[0] + after[1] >= after[2] * (1 - 1e-9)
    assert set(pair.import_differences) == {"j2"}
    # MuJoCo's compiled inertia is the balanced one, Pinocchio keeps the file's
    qpos, qvel = random_states(pair.mujoco.model, 2, seed=0)
    sm = pair.mujoco.segment_states(qpos, qvel).select(segments=["j2"])
    sp = pair.pinocchio.segment_states(qpos, qvel).select(segments=["j2"])
    assert np.allclose(np.linalg.eigvalsh(sp.inertia_body[0]), [0.001, 0.001, 0.01])
    assert np.allclose(np.sort(np.linalg.eigvalsh(sm.inertia_body[0])), np.sort(after))


def test_not_positive_definite_inertia_is_refused_even_with_balance(tmp_path):
    path = _chain(tmp_path, _link("l2", 0.5, (0.1, 0.1, 0.1, 0.2, 0.0, 0.0)))
    for balance in (False, True):
        with pytest.raises(InertiaError, match=r"link 'l2'.*not positive semi-definite \(principal moments -0\.1"):
            load_model(path, balance_inertia=balance)


def test_massless_moving_link_is_refused_by_mujoco(tmp_path):
    path = _chain(tmp_path, _link("l2", None))
    with pytest.raises(InertiaError, match=r"link 'l2'.*without mass.*Pinocchio accepts it"):
        load_model(path)


def test_unreadable_meshes_load_inertia_only(tmp_path):
    ascii_stl = tmp_path / "ascii.stl"
    ascii_stl.write_text("solid x\nendsolid x\n")
    dae = tmp_path / "mesh.dae"
    dae.write_text("<COLLADA/>")

    def collision(file):
        return f'<collision><geometry><mesh filename="{file}"/></geometry></collision>'

    l2 = _link("l2", 0.7, extra=collision("package://nowhere/missing.stl") + collision(str(dae)))
    l1_geoms = collision(str(ascii_stl))
    text = _urdf(
        _link("base") + _link("l1", extra=l1_geoms) + l2, _joint("j1", "base", "l1") + _joint("j2", "l1", "l2")
    )
    pair = load_model(_write(tmp_path, text))
    notes = " | ".join(pair.notes)
    assert "inertia-only" in notes and "missing file" in notes and "no MuJoCo decoder for .dae" in notes
    assert "MuJoCo refused" in notes and "ascii" in notes
    assert pair.mujoco.model.ngeom == 0
    qpos, qvel = random_states(pair.mujoco.model, 5, seed=1)
    e_mj = pair.mujoco.kinetic_energy(qpos, qvel).rigid
    assert rel_err(pair.pinocchio.kinetic_energy(qpos, qvel).rigid, e_mj) < RTOL


def test_links_without_inertial_get_no_mass_from_geometry(tmp_path):
    box = '<collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>'
    path = _chain(
        tmp_path,
        _link("l2", 1.0),
        extra_links=_link("l3", None, extra=box),
        extra_joints=_joint("f3", "l2", "l3", kind="fixed"),
    )
    pair = load_model(path)
    assert any(f.kind is Kind.LOAD and "no mass" in f.summary and "l3" in f.values["links"] for f in pair.findings)
    seg = dict(
        zip(
            pair.mujoco.segment_names,
            pair.mujoco.segment_states(*random_states(pair.mujoco.model, 1)).mass,
            strict=True,
        )
    )
    assert seg["j2"] == pytest.approx(1.0)
    # the quirk being avoided: MuJoCo's URDF default (inertiafromgeom auto) gives l3 the box's mass
    spec = mujoco.MjSpec.from_file(str(path))
    assert spec.compiler.inertiafromgeom == mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_AUTO
    spec.compiler.fusestatic = False
    model = spec.compile()
    assert model.body("l3").mass[0] == pytest.approx(1000 * 0.1 * 0.2 * 0.3)


def test_massless_link_with_inertia_fused_by_mujoco_is_an_import_difference(tmp_path):
    path = _chain(
        tmp_path,
        _link("l2", 1.0),
        extra_links=_link("tip", 0.0, (1e-3, 2e-3, 3e-3, 0, 0, 0)),
        extra_joints=_joint("f3", "l2", "tip", kind="fixed"),
    )
    pair = load_model(path)
    (found,) = pair.import_differences["j2"]
    assert set(pair.import_differences) == {"j2"}
    assert found.kind is Kind.COMPILER and found.element == "link tip" and "fusestatic dropped" in found.summary
    assert found.values["principal moments in the file"] == pytest.approx([1e-3, 2e-3, 3e-3])
    qpos, qvel = random_states(pair.mujoco.model, 1, seed=2)
    sm, sp = pair.mujoco.segment_states(qpos, qvel), pair.pinocchio.segment_states(qpos, qvel)
    j2 = list(sm.names).index("j2")
    diff = np.linalg.eigvalsh(sp.inertia_body[j2] - sm.inertia_body[j2])
    assert np.allclose(diff, [1e-3, 2e-3, 3e-3])


def test_floating_base_uses_the_same_free_joint_name(tmp_path):
    path = _chain(tmp_path, _link("l2"))
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
    path = _write(tmp_path, "<mujoco><worldbody><body><joint type='nonsense'/></body></worldbody></mujoco>", "bad.xml")
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


def test_mujoco_warnings_become_notes_not_log_files(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    pair = load_model("double_pendulum_simple", check=False)
    assert any(
        f.kind is Kind.LOAD and "warning" in f.summary and "equal lower and upper limits" in f.summary
        for f in pair.findings
    )
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()


def test_masses_rescaled_by_mujoco_compiler_are_import_differences(tmp_path):
    path = _write(
        tmp_path,
        """<mujoco><compiler settotalmass="6"/><worldbody>
        <body name="a"><joint name="ja" axis="0 1 0"/><inertial pos="0.1 0 0" mass="1" diaginertia="0.1 0.2 0.25"/>
          <body name="b" pos="0.3 0 0"><joint name="jb" axis="1 0 0"/>
            <inertial pos="0 0.1 0" mass="2" diaginertia="0.1 0.2 0.25"/></body></body>
        </worldbody></mujoco>""",
        "scaled.xml",
    )
    pair = load_model(path)
    assert set(pair.import_differences) == {"ja", "jb"}
    assert any(f.kind is Kind.LOAD and "warning" in f.summary and "settotalmass" in f.summary for f in pair.findings)
    assert all(f.kind is Kind.COMPILER and f.affects_energy for fs in pair.import_differences.values() for f in fs)
    states = [e.segment_states(*random_states(pair.mujoco.model, 1)) for e in pair.engines.values()]
    assert states[0].mass == pytest.approx([2.0, 4.0]) and states[1].mass == pytest.approx([1.0, 2.0])


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
