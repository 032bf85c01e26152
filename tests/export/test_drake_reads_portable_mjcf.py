"""Drake reads the portable MJCF as MuJoCo reads the original, checked with Drake's own mass matrix."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from export_helpers import MODELS, RTOL, in_order, mujoco_matrix, mujoco_model, one_dof_joint_names, relative_difference

import koenig_check

pytest.importorskip("pydrake")


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
    result = koenig_check.export(MODELS / name, to="mjcf", out=tmp_path / name, poses=2)
    original = mujoco_model(MODELS / name)
    names = one_dof_joint_names(original)
    rng = np.random.default_rng(9)
    for _ in range(3):
        values = {n: np.array([rng.uniform(-1, 1)]) for n in names}
        reference, labels = mujoco_matrix(original, values)
        assert relative_difference(in_order(reference, labels, names), _drake_matrix(result.path, values, names)) < RTOL
