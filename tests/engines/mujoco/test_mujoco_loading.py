"""Loading into MuJoCo: inertia checks and balancing, meshes it cannot read, mass from geometry, fused static
links, compiler warnings and rescaled masses.

(What loading does for both engines: ``tests/engines/test_loading.py``.)
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from engine_helpers import RTOL, rel_err
from urdf_builders import urdf_chain, urdf_joint, urdf_link, urdf_text, write_model

from koenig_check.engines import InertiaError, load_model, random_states
from koenig_check.findings import Kind

BAD_TRIANGLE = (0.001, 0.001, 0.01, 0.0, 0.0, 0.0)


def test_triangle_inequality_violation_names_the_link(tmp_path):
    path = urdf_chain(tmp_path, urdf_link("l2", 0.5, BAD_TRIANGLE))
    with pytest.raises(InertiaError) as info:
        load_model(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg and "link 'l2'" in msg
    assert "A + B >= C" in msg and "0.001, 0.001, 0.01" in msg and "balance_inertia=True" in msg


def test_balance_inertia_loads_and_records_the_change(tmp_path):
    path = urdf_chain(tmp_path, urdf_link("l2", 0.5, BAD_TRIANGLE))
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
    path = urdf_chain(tmp_path, urdf_link("l2", 0.5, (0.1, 0.1, 0.1, 0.2, 0.0, 0.0)))
    for balance in (False, True):
        with pytest.raises(InertiaError, match=r"link 'l2'.*not positive semi-definite \(principal moments -0\.1"):
            load_model(path, balance_inertia=balance)


def test_massless_moving_link_is_refused_by_mujoco(tmp_path):
    path = urdf_chain(tmp_path, urdf_link("l2", None))
    with pytest.raises(InertiaError, match=r"link 'l2'.*without mass.*Pinocchio accepts it"):
        load_model(path)


def test_unreadable_meshes_load_inertia_only(tmp_path):
    ascii_stl = tmp_path / "ascii.stl"
    ascii_stl.write_text("solid x\nendsolid x\n")
    dae = tmp_path / "mesh.dae"
    dae.write_text("<COLLADA/>")

    def collision(file):
        return f'<collision><geometry><mesh filename="{file}"/></geometry></collision>'

    l2 = urdf_link("l2", 0.7, extra=collision("package://nowhere/missing.stl") + collision(str(dae)))
    l1_geoms = collision(str(ascii_stl))
    text = urdf_text(
        urdf_link("base") + urdf_link("l1", extra=l1_geoms) + l2,
        urdf_joint("j1", "base", "l1") + urdf_joint("j2", "l1", "l2"),
    )
    pair = load_model(write_model(tmp_path, text))
    notes = " | ".join(pair.notes)
    assert "inertia-only" in notes and "missing file" in notes and "no MuJoCo decoder for .dae" in notes
    assert "MuJoCo refused" in notes and "ascii" in notes
    assert pair.mujoco.model.ngeom == 0
    qpos, qvel = random_states(pair.mujoco.model, 5, seed=1)
    e_mj = pair.mujoco.kinetic_energy(qpos, qvel).rigid
    assert rel_err(pair.pinocchio.kinetic_energy(qpos, qvel).rigid, e_mj) < RTOL


def test_links_without_inertial_get_no_mass_from_geometry(tmp_path):
    box = '<collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>'
    path = urdf_chain(
        tmp_path,
        urdf_link("l2", 1.0),
        extra_links=urdf_link("l3", None, extra=box),
        extra_joints=urdf_joint("f3", "l2", "l3", kind="fixed"),
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
    path = urdf_chain(
        tmp_path,
        urdf_link("l2", 1.0),
        extra_links=urdf_link("tip", 0.0, (1e-3, 2e-3, 3e-3, 0, 0, 0)),
        extra_joints=urdf_joint("f3", "l2", "tip", kind="fixed"),
    )
    pair = load_model(path)
    (found,) = pair.import_differences["j2"]
    assert set(pair.import_differences) == {"j2"}
    assert found.kind is Kind.COMPILER and found.element == "link tip"
    assert found.cause == "mujoco.any.fusestatic-massless-inertia"
    assert found.values["principal moments in the file"] == pytest.approx([1e-3, 2e-3, 3e-3])
    qpos, qvel = random_states(pair.mujoco.model, 1, seed=2)
    sm, sp = pair.mujoco.segment_states(qpos, qvel), pair.pinocchio.segment_states(qpos, qvel)
    j2 = list(sm.names).index("j2")
    diff = np.linalg.eigvalsh(sp.inertia_body[j2] - sm.inertia_body[j2])
    assert np.allclose(diff, [1e-3, 2e-3, 3e-3])


def test_mujoco_warnings_become_notes_not_log_files(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    pair = load_model("double_pendulum_simple", check=False)
    assert any(
        f.kind is Kind.LOAD and "warning" in f.summary and "equal lower and upper limits" in f.summary
        for f in pair.findings
    )
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()


def test_masses_rescaled_by_mujoco_compiler_are_import_differences(tmp_path):
    path = write_model(
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
