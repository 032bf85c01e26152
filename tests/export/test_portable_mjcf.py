"""MJCF → portable MJCF: each construct's export read by MuJoCo, Pinocchio and Drake as MuJoCo reads the original.

The numbers written parse back to the same doubles: the export compiles to the original's compiled arrays.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from export_constructs import CONSTRUCTS, check_against_original, export_to
from export_helpers import MODELS, RTOL, in_order, mujoco_matrix, mujoco_model, one_dof_joint_names, relative_difference

import koenig_check

#: Compiled arrays that must survive the export bit for bit (no ref folded in these models).
EXACT = ("body_mass", "body_ipos", "body_inertia", "body_pos", "jnt_axis", "jnt_pos", "jnt_range", "dof_armature")


@pytest.mark.parametrize("name", list(CONSTRUCTS))
def test_portable_mjcf_has_the_original_mass_matrix_in_both_engines(tmp_path: Path, name: str) -> None:
    result = export_to(tmp_path, name, "mjcf")
    assert result.equivalent, result.proof.summary()
    check_against_original(result, name, "mjcf")


@pytest.mark.parametrize("name", ["mesh_inertia.xml", "settotalmass.xml", "defaults.xml", "armature.xml"])
def test_portable_mjcf_compiles_to_the_same_numbers(tmp_path: Path, name: str) -> None:
    result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
    original, export = mujoco_model(MODELS / name), mujoco_model(result.path)
    for field in EXACT:
        assert np.array_equal(getattr(original, field), getattr(export, field)), field
    assert np.abs(original.body_iquat - export.body_iquat).max() <= 4 * np.finfo(float).eps


def _drake_matrix(path: Path, values: dict[str, np.ndarray], names: list[str]) -> np.ndarray:
    """Drake's own M(q) of an MJCF file, rows in the order of ``names`` (every joint a revolute one)."""
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import MultibodyPlant

    plant = MultibodyPlant(0.0)
    Parser(plant).AddModels(str(path))
    plant.Finalize()
    context = plant.CreateDefaultContext()
    for name in names:
        plant.GetJointByName(name).set_angle(context, float(values[name][0]))
    matrix = plant.CalcMassMatrix(context)
    index = [plant.GetJointByName(name).velocity_start() for name in names]
    return matrix[np.ix_(index, index)]


@pytest.mark.parametrize("name", ["multi_joint.xml", "hinge_ref.xml", "defaults.xml", "several_roots.xml"])
def test_drake_mass_matrix_of_the_portable_mjcf(tmp_path: Path, name: str) -> None:
    pytest.importorskip("pydrake")
    result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
    original = mujoco_model(MODELS / name)
    names = one_dof_joint_names(original)
    rng = np.random.default_rng(9)
    for _ in range(3):
        values = {n: np.array([rng.uniform(-1, 1)]) for n in names}
        reference, labels = mujoco_matrix(original, values)
        assert relative_difference(in_order(reference, labels, names), _drake_matrix(result.path, values, names)) < RTOL
