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


def _tetrahedron_stl(path: Path) -> None:
    """A binary STL of a unit right tetrahedron, written by hand (80-byte header, count, 4 facets)."""
    import struct

    corners = [(0.0, 0.0, 0.0), (0.1, 0.0, 0.0), (0.0, 0.1, 0.0), (0.0, 0.0, 0.1)]
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    data = b"\0" * 80 + struct.pack("<I", len(faces))
    for face in faces:
        data += struct.pack("<3f", 0.0, 0.0, 0.0) + b"".join(struct.pack("<3f", *corners[i]) for i in face) + b"\0\0"
    path.write_bytes(data)


#: A body whose inertia comes from an STL mesh (MuJoCo reads STL; Drake's MJCF parser reads .obj only).
STL_MODEL = """<mujoco model="stl_mesh">
  <asset><mesh name="tet" file="tet.stl"/></asset>
  <worldbody>
    <body name="holder" pos="0 0 0.5">
      <joint name="turn" type="hinge" axis="0 1 0"/>
      <geom type="mesh" mesh="tet" density="800"/>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.mark.parametrize(
    ("engines", "kept"), [(("mujoco", "pinocchio"), True), (None, False)], ids=["without drake", "every engine"]
)
def test_an_stl_mesh_is_written_where_no_drake_reads_the_export(tmp_path: Path, engines, kept: bool) -> None:
    """Without Drake among the readers, an STL mesh geom is written (MuJoCo compiles the same mesh); with it, the
    geom is left out and the not-carried line says how to keep it.  The inertia is explicit either way."""
    _tetrahedron_stl(tmp_path / "tet.stl")
    (tmp_path / "stl_mesh.xml").write_text(STL_MODEL, encoding="utf-8")
    (tmp_path / "out").mkdir()
    out = tmp_path / "out" / "export.xml"  # another folder: the mesh path is written relative to the export
    result = koenig_check.export(tmp_path / "stl_mesh.xml", to="mjcf", out=out, poses=2, engines=engines)
    assert result.equivalent, result.proof.summary()
    original, export = mujoco_model(tmp_path / "stl_mesh.xml"), mujoco_model(out)
    assert np.array_equal(original.body_mass, export.body_mass)  # the inertial is explicit in both cases
    shapes = [n for n in result.not_carried if n.construct == "geom shape"]
    if kept:
        assert not shapes and export.nmesh == 1 and export.ngeom == original.ngeom
        assert np.array_equal(export.mesh_vert, original.mesh_vert)  # MuJoCo reads the same file
    else:
        assert export.nmesh == 0 and "--engines without drake writes it" in shapes[0].reason


def test_a_urdf_with_stl_meshes_keeps_them_for_mujoco_and_pinocchio(tmp_path: Path) -> None:
    """example-robot-data's UR5 (STL collision meshes): every mesh MuJoCo's import read is in the export."""
    from koenig_check.engines import resolve_model

    path = resolve_model("ur5").path
    out = tmp_path / "ur5.xml"
    result = koenig_check.export(path, to="mjcf", out=out, poses=2, engines=("mujoco", "pinocchio"))
    assert result.equivalent, result.proof.summary()
    import xml.etree.ElementTree as ET

    collision = {
        Path(m.get("filename")).name for m in ET.parse(path).getroot().iterfind("link/collision/geometry/mesh")
    }
    written = {Path(m.get("file")).name for m in ET.parse(out).getroot().iterfind("asset/mesh")}
    assert collision and written == collision  # MuJoCo's import keeps the collision meshes: each is written
    export = mujoco_model(out)  # and MuJoCo reads them back
    assert export.nmesh == len(collision) and export.mesh_vertnum.min() > 0
    assert not [n for n in result.not_carried if n.construct == "geom shape"]
