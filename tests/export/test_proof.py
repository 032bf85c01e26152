"""The proof's reference is MuJoCo's reading of the original; an engine that misreads the original is told apart."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from export_helpers import (
    MODELS,
    in_order,
    mujoco_matrix,
    mujoco_model,
    one_dof_joint_names,
    pinocchio_matrix,
    pinocchio_model,
    random_joint_values,
    relative_difference,
)

import koenig_check
from koenig_check.export import prove


def test_an_engine_misreading_the_original_is_a_note_not_a_failure(tmp_path: Path) -> None:
    # independent route: Pinocchio's own reading of defaults.xml differs from MuJoCo's (default-class geom masses)
    values = random_joint_values(one_dof_joint_names(mujoco_model(MODELS / "defaults.xml")), np.random.default_rng(1))
    reference, order = mujoco_matrix(mujoco_model(MODELS / "defaults.xml"), values)
    matrix, labels = pinocchio_matrix(pinocchio_model(MODELS / "defaults.xml"), values)
    misread = relative_difference(reference, in_order(matrix, labels, order))
    assert misread > 1e-3

    result = koenig_check.export(MODELS / "defaults.xml", to="mjcf", out=tmp_path / "d.xml", poses=3)
    pinocchio = next(e for e in result.proof.engines if e.engine == "pinocchio")
    assert pinocchio.equivalent and pinocchio.own_reading > 1e-3
    assert any(note.startswith("pinocchio reads the original differently") for note in result.proof.notes())


def test_a_file_against_itself_is_equivalent_with_every_engine() -> None:
    proof = prove(MODELS / "hinge_ref.xml", MODELS / "hinge_ref.xml", poses=3)
    assert proof.equivalent, proof.summary()
    assert proof.summary().startswith("equivalent: max relative difference")
    assert {e.engine for e in proof.engines if e.compared} >= {"mujoco", "pinocchio"}


def test_a_missing_joint_is_a_problem_naming_it(tmp_path: Path) -> None:
    text = (MODELS / "slide.xml").read_text().replace('<joint name="tilt" type="hinge" axis="0 1 0"/>', "")
    assert "tilt" not in text
    stripped = tmp_path / "slide_without_tilt.xml"
    stripped.write_text(text)
    proof = prove(MODELS / "slide.xml", stripped, poses=2)
    assert not proof.equivalent
    assert proof.problems == ("joints missing in the export: tilt",)


def test_inverse_dynamics_is_compared_too(tmp_path: Path) -> None:
    """A mass moved from one link to another changes M, the energy and the inverse dynamics in every engine."""
    text = (MODELS / "slide.xml").read_text()
    heavier = tmp_path / "slide_heavier_pole.xml"
    heavier.write_text(text.replace('size="0.03" mass="0.5"', 'size="0.03" mass="0.6"'))
    proof = prove(MODELS / "slide.xml", heavier, poses=3)
    compared = [e for e in proof.engines if e.compared]
    assert compared and all(e.inverse_dynamics > 1e-3 and not e.equivalent for e in compared)
    clean = prove(MODELS / "slide.xml", MODELS / "slide.xml", poses=3)
    assert all(e.inverse_dynamics < 1e-12 for e in clean.engines if e.compared)


def _arm(com_height: float = 0.0, axis: str = "0 0 1", forearm_mass: float = 0.4) -> str:
    """A yaw hinge carrying a box (its COM ``com_height`` along the axis) and a pitching forearm."""
    return (
        '<mujoco><option gravity="0 0 0"/><worldbody><body name="arm">'
        f'<joint name="yaw" type="hinge" axis="{axis}"/>'
        f'<geom type="box" size="0.2 0.05 0.03" pos="0.2 0 {com_height}" mass="1"/>'
        '<body name="forearm" pos="0.4 0 0"><joint name="pitch" type="hinge" axis="0 1 0"/>'
        f'<geom type="capsule" fromto="0 0 0 0.3 0 0.1" size="0.02" mass="{forearm_mass}"/></body>'
        "</body></worldbody></mujoco>"
    )


def _write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_link_difference_no_engine_can_feel_still_fails_the_proof(tmp_path: Path) -> None:
    """The box's COM raised 0.1 m along the yaw axis: the mass matrix cannot see it, the proof's link check must.

    By hand: a COM moved along a hinge axis keeps its distance from the axis, so ``M`` and the energy stay the
    same (MuJoCo's own mass matrices below); its distance from the joint goes from 0.2 m to √(0.2² + 0.1²).
    """
    original = _write(tmp_path, "arm.xml", _arm())
    raised = _write(tmp_path, "arm_raised.xml", _arm(com_height=0.1))
    values = random_joint_values(one_dof_joint_names(mujoco_model(original)), np.random.default_rng(2))
    m_original, _ = mujoco_matrix(mujoco_model(original), values)
    m_raised, _ = mujoco_matrix(mujoco_model(raised), values)
    assert relative_difference(m_original, m_raised) < 1e-12  # no engine can feel it

    proof = prove(original, raised, poses=3)
    assert all(e.equivalent for e in proof.engines if e.compared)
    assert not proof.equivalent, proof.summary()
    com = [s for s in proof.segments if s.quantity == "COM distance from the joint"]
    assert com and {s.segment for s in com} == {"yaw"}
    for s in com:
        assert s.original == pytest.approx(0.2, rel=1e-9) and s.export == pytest.approx(np.hypot(0.2, 0.1), rel=1e-9)


def test_a_mass_matrix_difference_between_the_tolerance_and_a_loose_one_fails(tmp_path: Path) -> None:
    """The yaw axis tilted by 2e-5 rad: the mass matrix moves by about 1e-6 relative, far below 1e-3, above 1e-9.

    Nothing of a link changes (mass, COM distance from its joint, principal moments), so only each engine's mass
    matrix, energy and inverse dynamics can fail the proof; the reported difference is the largest over the proof's
    poses, recomputed here from MuJoCo's own ``mj_fullM`` of both files at the proof's seeded states.
    """
    original = _write(tmp_path, "arm.xml", _arm(com_height=0.1))
    tilted = _write(tmp_path, "arm_tilted.xml", _arm(com_height=0.1, axis="2e-5 0 1"))
    proof = prove(original, tilted, poses=4, seed=5)
    assert proof.segments == ()

    from koenig_check.engines.sampling import random_states

    model_a, model_b = mujoco.MjModel.from_xml_path(str(original)), mujoco.MjModel.from_xml_path(str(tilted))
    per_pose = []
    for qpos in random_states(model_a, 4, 5)[0]:
        m = []
        for model in (model_a, model_b):
            data = mujoco.MjData(model)
            data.qpos[:] = qpos
            mujoco.mj_forward(model, data)
            full = np.zeros((model.nv, model.nv))
            mujoco.mj_fullM(model, data, full)
            m.append(full)
        per_pose.append(np.abs(m[1] - m[0]).max() / np.abs(m[0]).max())
    expected = max(per_pose)
    assert 1e-8 < expected < 1e-4 and max(per_pose) > 1.05 * min(per_pose)  # the largest, not any pose's

    for e in proof.engines:
        if e.compared:
            assert not e.equivalent, e
            assert e.mass_matrix == pytest.approx(expected, rel=1e-3), e.engine
    assert not proof.equivalent
