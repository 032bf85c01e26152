"""The proof's reference is MuJoCo's reading of the original; an engine that misreads the original is told apart."""

from __future__ import annotations

from pathlib import Path

import numpy as np
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
