"""Each construct's export checked by the independent route: MuJoCo's and Pinocchio's own mass matrices.

The original is read by MuJoCo itself; the export by MuJoCo and by Pinocchio, at the same joint values
paired by name.  Round trips: MJCF → URDF → MuJoCo's URDF import equals the original's M(q); URDF → MJCF →
Pinocchio equals Pinocchio's M(q) of the URDF.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from export_helpers import (
    MODELS,
    RTOL,
    in_order,
    mujoco_matrix,
    mujoco_model,
    one_dof_joint_names,
    pinocchio_matrix,
    pinocchio_model,
    random_joint_values,
    relative_difference,
    sibling_joints,
)

import koenig_check

#: Each construct's small MJCF file (in tests/export/models) and what it is there for.
CONSTRUCTS = {
    "defaults.xml": "default classes (joint axis and range, geom masses)",
    "include.xml": "an <include> inside a body",
    "several_roots.xml": "several root bodies",
    "posed_root.xml": "a jointless posed root",
    "mesh_inertia.xml": "mesh-derived inertia",
    "settotalmass.xml": "settotalmass",
    "hinge_ref.xml": "hinges with ref and an anchor off the body origin",
    "slide.xml": "a slide joint with ref",
    "ball.xml": "a ball joint (refused for URDF, kept in MJCF)",
    "free_root.xml": "a free root",
    "armature.xml": "armature",
    "equality.xml": "a joint equality (mimic)",
    "multi_joint.xml": "a body with two joints, posed off its parent's origin (refused for URDF)",
}
URDF_REFUSED = {"ball.xml", "multi_joint.xml"}
POSES = 4


def _cases() -> list[tuple[str, str]]:
    cases = [(name, "mjcf") for name in CONSTRUCTS]
    cases += [(name, "urdf") for name in CONSTRUCTS if name not in URDF_REFUSED]
    return [*cases, ("arm.urdf", "mjcf")]


def _export(tmp_path: Path, name: str, to: str) -> koenig_check.export.ExportResult:
    out = tmp_path / (Path(name).stem + ("_export.urdf" if to == "urdf" else "_export.xml"))
    return koenig_check.export(MODELS / name, to=to, out=out, poses=3)


@pytest.mark.parametrize(("name", "to"), _cases(), ids=[f"{n}-{t}" for n, t in _cases()])
def test_export_has_the_original_mass_matrix_in_both_engines(tmp_path: Path, name: str, to: str) -> None:
    result = _export(tmp_path, name, to)
    assert result.equivalent, result.proof.summary()
    original = mujoco_model(MODELS / name)
    floating = result.floating_base
    export_mj = mujoco_model(result.path, floating=floating)
    export_pin = pinocchio_model(result.path, floating=floating)
    rng = np.random.default_rng(7)
    for _ in range(POSES):
        values = random_joint_values(one_dof_joint_names(original), rng)
        reference, order = mujoco_matrix(original, values)
        siblings = sibling_joints(result.path) if to == "mjcf" else {}
        for matrix, labels in (mujoco_matrix(export_mj, values), pinocchio_matrix(export_pin, values, siblings)):
            assert sorted(labels) == sorted(order)
            assert relative_difference(reference, in_order(matrix, labels, order)) < RTOL


@pytest.mark.parametrize("name", ["hinge_ref.xml", "free_root.xml", "mesh_inertia.xml", "defaults.xml"])
def test_round_trip_mjcf_urdf_mujoco_import(tmp_path: Path, name: str) -> None:
    """MJCF → URDF → MuJoCo's own URDF import gives the original's M(q)."""
    result = _export(tmp_path, name, "urdf")
    original = mujoco_model(MODELS / name)
    imported = mujoco_model(result.path, floating=result.floating_base)
    rng = np.random.default_rng(3)
    for _ in range(POSES):
        values = random_joint_values(one_dof_joint_names(original), rng)
        reference, order = mujoco_matrix(original, values)
        matrix, labels = mujoco_matrix(imported, values)
        assert relative_difference(reference, in_order(matrix, labels, order)) < RTOL


def test_round_trip_urdf_mjcf_pinocchio(tmp_path: Path) -> None:
    """URDF → MJCF → Pinocchio gives Pinocchio's M(q) of the URDF (off-diagonal, rotated inertias included)."""
    result = _export(tmp_path, "arm.urdf", "mjcf")
    urdf = pinocchio_model(MODELS / "arm.urdf")
    mjcf = pinocchio_model(result.path)
    names = [urdf.names[j] for j in range(1, urdf.njoints)]
    rng = np.random.default_rng(5)
    for _ in range(POSES):
        values = random_joint_values(names, rng)
        reference, order = pinocchio_matrix(urdf, values)
        matrix, labels = pinocchio_matrix(mjcf, values)
        assert relative_difference(reference, in_order(matrix, labels, order)) < RTOL
