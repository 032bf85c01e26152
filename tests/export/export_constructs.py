"""The constructs the export tests run on, and the independent check they share.

The original is read by MuJoCo itself; the export by MuJoCo and by Pinocchio, at the same joint values
paired by name (:mod:`export_helpers`): nothing of koenig-check reads the mass matrices.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
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
from koenig_check.export import ExportResult

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


def export_to(tmp_path: Path, name: str, to: str) -> ExportResult:
    out = tmp_path / (Path(name).stem + ("_export.urdf" if to == "urdf" else "_export.xml"))
    """Export a construct's file through the API (a short proof: the test checks independently)."""
    return koenig_check.export(MODELS / name, to=to, out=out, poses=3)


def check_against_original(result: ExportResult, name: str, to: str) -> None:
    """The export's M(q) in MuJoCo and Pinocchio equals MuJoCo's M(q) of the original at random joint values."""
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
