"""An edited copy of an MJCF file reads its includes and meshes as the original, next to it or elsewhere."""

from __future__ import annotations

import tempfile
from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.modelfile.edited_copy import edited_copy
from koenig_check.modelfile.validate import parse_xml

#: A tetrahedron whose mass MuJoCo computes from its volume: a mesh not found changes the model or refuses it.
TETRAHEDRON = "v 0 0 0\nv 0.2 0 0\nv 0 0.3 0\nv 0 0 0.4\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"

ARM = """<mujocoinclude><body name="arm" pos="0 0 0.1"><joint name="elbow" axis="0 1 0"/>
<geom type="mesh" mesh="tet"/></body></mujocoinclude>"""


def _model(folder: Path, compiler: str, mesh_file: str, include: bool) -> Path:
    """A model with a mesh (and an included body) at paths relative to the model file."""
    (folder / Path(mesh_file).parent).mkdir(parents=True, exist_ok=True)
    (folder / mesh_file).write_text(TETRAHEDRON)
    body = '<include file="parts/arm.xml"/>' if include else ""
    if include:
        (folder / "parts").mkdir(exist_ok=True)
        (folder / "parts" / "arm.xml").write_text(ARM)
    path = folder / "robot.xml"
    path.write_text(
        f'<mujoco model="robot">{compiler}<asset><mesh name="tet" file="{Path(mesh_file).name}"/></asset>'
        f'<worldbody><body name="base"><joint name="shoulder" axis="0 0 1"/><geom type="mesh" mesh="tet"/>'
        f"{body}</body></worldbody></mujoco>"
    )
    return path


CASES = {
    "no compiler, mesh next to the file": ("", "tet.obj", False),
    "meshdir": ('<compiler meshdir="assets"/>', "assets/tet.obj", False),
    "assetdir and an include": ('<compiler assetdir="assets"/>', "assets/tet.obj", True),
}


def _read_only_folder(monkeypatch: pytest.MonkeyPatch, folder: Path) -> None:
    """Refuse, as a read-only install does, a temporary file in ``folder`` (the tests may run as root)."""
    make = tempfile.NamedTemporaryFile

    def refuse(*args, **kwargs):  # type: ignore[no-untyped-def]
        if kwargs.get("dir") is not None and Path(kwargs["dir"]) == folder:
            raise PermissionError(13, "Permission denied", str(folder))
        return make(*args, **kwargs)

    monkeypatch.setattr(tempfile, "NamedTemporaryFile", refuse)


@pytest.mark.parametrize("read_only", [False, True], ids=["next to it", "read-only folder"])
@pytest.mark.parametrize("case", list(CASES))
def test_the_copy_is_the_same_model_for_mujoco(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, case: str, read_only: bool
) -> None:
    compiler, mesh_file, include = CASES[case]
    path = _model(tmp_path / "robot", compiler, mesh_file, include)
    original = mujoco.MjModel.from_xml_path(str(path))
    if read_only:
        _read_only_folder(monkeypatch, path.parent)
    tree = parse_xml(path)
    tree.getroot().set("model", "edited")  # an edit, as a parser needs one
    with edited_copy(path, tree, "test") as copy:
        assert (copy.parent == path.parent) is not read_only
        assert copy.name.startswith(".robot-test-" if not read_only else "robot-test-")
        model = mujoco.MjModel.from_xml_path(str(copy))
    assert not copy.exists()
    assert model.nbody == original.nbody == (3 if include else 2)  # the world, base (and the included arm)
    assert original.body_mass[1] > 0
    np.testing.assert_array_equal(model.body_mass, original.body_mass)
    np.testing.assert_array_equal(model.body_inertia, original.body_inertia)
    np.testing.assert_array_equal(model.body_ipos, original.body_ipos)
