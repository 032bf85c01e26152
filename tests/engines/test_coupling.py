"""Coupled joints are loaded, recorded as COUPLING findings, and sampled states satisfy joint relations.

Expected states are hand computations of the file's relation: URDF mimic ``q_f = m q_l + o``,
``q̇_f = m q̇_l``; MJCF joint equality ``y − y0 = a0 + a1 (x − x0) + a2 (x − x0)²``,
``ẏ = (a1 + 2 a2 (x − x0)) ẋ`` with ``x0``, ``y0`` the joints' ``ref``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.api import compare, make_poses
from koenig_check.engines import load_model, random_states
from koenig_check.findings import Kind

MODELS = Path(__file__).parent / "models"


def _mimic(x: np.ndarray, xd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return -2.0 * x + 0.3, -2.0 * xd


def _poly(x: np.ndarray, xd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    dx = x - 0.1
    return 0.2 + 0.1 + 0.5 * dx - 0.8 * dx**2, (0.5 - 1.6 * dx) * xd


RELATIONS = {"mimic_chain.urdf": _mimic, "joint_equality.xml": _poly}


@pytest.fixture(scope="module", params=sorted(RELATIONS))
def coupled(request):
    return request.param, load_model(MODELS / request.param)


def test_coupling_is_one_finding_that_does_not_change_the_energy(coupled) -> None:
    _name, pair = coupled
    (found,) = [f for f in pair.findings if f.kind is Kind.COUPLING]
    assert found.engine == "both" and not found.affects_energy
    assert "elbow" in found.element + str(found.values.get("follower", ""))
    assert "shoulder" in str(found.values.get("leader"))
    assert "satisfy" in found.hint


@pytest.mark.parametrize("kind", ["random", "keyframes-like", "grid", "engine-sampler"])
def test_sampled_states_satisfy_the_joint_relation(coupled, kind) -> None:
    name, pair = coupled
    model = pair.mujoco.model
    if kind == "random":
        ps = make_poses(model, "random", n_poses=30, seed=4)
        qpos, qvel, notes = ps.qpos, ps.qvel, ps.notes
    elif kind == "grid":
        ps = make_poses(model, "grid", n_poses=5, grid_joints=("shoulder", "elbow"))
        qpos, qvel, notes = ps.qpos, ps.qvel, ps.notes
    elif kind == "engine-sampler":
        qpos, qvel = random_states(model, 30, seed=4)
        notes = ("position and velocity",)
    else:
        from koenig_check.engines.coupling import apply_joint_relations

        rng = np.random.default_rng(1)
        qpos, qvel, notes = apply_joint_relations(model, rng.normal(size=(7, 2)), rng.normal(size=(7, 2)))
    shoulder, elbow = (int(model.joint(j).qposadr[0]) for j in ("shoulder", "elbow"))
    y, yd = RELATIONS[name](qpos[:, shoulder], qvel[:, shoulder])
    np.testing.assert_allclose(qpos[:, elbow], y, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(qvel[:, elbow], yd, rtol=1e-12, atol=1e-12)
    assert np.any(qvel[:, shoulder] != 0)
    assert any("position and velocity" in n for n in notes)


def test_engines_agree_on_the_coupled_model(coupled) -> None:
    name, _pair = coupled
    check = compare(MODELS / name, n_poses=6, seed=2)
    assert check.ok, check.reason()


def test_allow_coupled_is_accepted_as_a_deprecated_no_op() -> None:
    with pytest.warns(DeprecationWarning, match="deprecated"):
        check = compare(MODELS / "mimic_chain.urdf", n_poses=3, allow_coupled=True)
    assert check.ok, check.reason()


def test_keyframe_poses_satisfy_the_joint_relation_through_the_keyframe_path(tmp_path: Path) -> None:
    """The keyframe path (``--pose-kind keyframes``) imposes the relation as the other pose kinds do.

    Keyframe ``bent`` (shoulder 0.5, elbow -1.0, rates 0.3, 0.7) by hand: elbow = 0.3 + 0.5·0.4 − 0.8·0.4²
    = 0.372, elbow rate = (0.5 − 1.6·0.4)·0.3 = −0.042.  The CLI's records hold MuJoCo's own energy at
    that state, which MuJoCo computes again here from the hand state.
    """
    import mujoco

    from koenig_check.cli import main
    from koenig_check.run.records import read_records

    path = MODELS / "joint_equality_keyframe.xml"
    model = load_model(path).mujoco.model
    poses = make_poses(model, "keyframes", seed=4)
    assert poses.ids == ("key:bent", "key:still")
    np.testing.assert_allclose(poses.qpos[0], [0.5, 0.372], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(poses.qvel[0], [0.3, -0.042], rtol=1e-12, atol=1e-12)
    y, yd = _poly(poses.qpos[:, 0], poses.qvel[:, 0])
    np.testing.assert_allclose(poses.qpos[:, 1], y, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(poses.qvel[:, 1], yd, rtol=1e-12, atol=1e-12)
    assert any("elbow_follows" in n for n in poses.notes)

    out = tmp_path / "r"
    assert main(["compare", str(path), "--pose-kind", "keyframes", "--formulas", "exact", "--out", str(out)]) == 0
    records = read_records(out / "records.parquet")
    row = (records["pose"] == "key:bent") & (records["reference"] == "mujoco") & (records["scope"] == "total")
    assert row.sum() >= 1
    data = mujoco.MjData(model)
    data.qpos[:], data.qvel[:] = [0.5, 0.372], [0.3, -0.042]
    mujoco.mj_forward(model, data)
    mujoco.mj_energyVel(model, data)
    np.testing.assert_allclose(records["reference_value"][row], data.energy[1], rtol=1e-12)


#: A URDF with "--" inside a comment: TinyXML2 (MuJoCo, Pinocchio) reads it, Python's Expat refuses it.
DASHED_COMMENT = """<robot name="dashed">
  <!-- a comment -- with two dashes -->
  <link name="base"/>
  <link name="a"><inertial><origin xyz="0.1 0 0"/><mass value="1"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="continuous"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/></joint>
</robot>
"""


def test_a_urdf_only_tinyxml_reads_is_compared_and_its_mimic_check_says_it_was_not_made(tmp_path: Path) -> None:
    """The mimic reader used to end the model with Expat's raw "not well-formed (invalid token)"."""
    import xml.etree.ElementTree as ET

    import mujoco
    import pinocchio as pin

    import koenig_check
    from koenig_check.findings import Kind

    path = tmp_path / "dashed.urdf"
    path.write_text(DASHED_COMMENT, encoding="utf-8")
    with pytest.raises(ET.ParseError):
        ET.parse(path)
    assert mujoco.MjModel.from_xml_path(str(path)).nv == 1 and pin.buildModelFromUrdf(str(path)).nv == 1
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert check.ok and not check.failures, check.reason()
    notes = [f for f in check.comparisons[0].findings if f.kind is Kind.LOAD and f.element == "mimic joints"]
    assert len(notes) == 1 and "not looked for" in notes[0].summary and "MuJoCo reads it" in notes[0].summary
