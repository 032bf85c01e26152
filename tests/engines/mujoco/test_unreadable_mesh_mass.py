"""A mesh MuJoCo cannot read that gives a body its mass: a one-line error naming the file, the geom and the body.

Dropping such a mesh with its geom (what is done for a URDF's collision meshes, which never carry mass) leaves
a moving body without mass; MuJoCo's refusal of that body would send the user to ``--repair-inertia``, which
would load a different robot.  A mesh that carries no mass (a URDF collision mesh, an MJCF body with its own
``<inertial>``) is still dropped, and the terminal row says so.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.engines import ModelLoadError, load_model
from koenig_check.findings import Kind

BODY = """<mujoco model="m">{compiler}
  <asset><mesh name="arm" file="{file}"/></asset>
  <worldbody>
    <body name="link1">{inertial}
      <joint name="j1" type="hinge" axis="0 0 1"/>
      <geom name="g1" type="mesh" mesh="arm"/>
      <geom name="g2" type="box" size="0.1 0.1 0.1" pos="0.3 0 0"/>
    </body>
  </worldbody>
</mujoco>"""

ASCII_STL = "solid x\nendsolid x\n"  # MuJoCo's decoder refuses it at compile time


def _mjcf(tmp_path: Path, file: str, inertial: str = "", compiler: str = "") -> Path:
    path = tmp_path / "mesh_body.xml"
    path.write_text(BODY.format(file=file, inertial=inertial, compiler=compiler))
    return path


@pytest.mark.parametrize("repair", [False, True], ids=["plain", "repair_inertia"])
@pytest.mark.parametrize(
    ("file", "content", "said"),
    [
        ("meshes/arm_missing.stl", None, "not found"),
        ("arm.stl", ASCII_STL, "MuJoCo"),  # refused by MuJoCo's decoder, while compiling
    ],
    ids=["missing", "refused"],
)
def test_mesh_carrying_mass_is_named_not_repaired(
    tmp_path: Path, file: str, content: str | None, said: str, repair: bool
) -> None:
    if content is not None:
        (tmp_path / file).write_text(content)
    path = _mjcf(tmp_path, file)
    with pytest.raises(ModelLoadError) as info:
        load_model(path, repair_inertia=repair)
    message = str(info.value)
    assert "\n" not in message and str(path) in message
    assert f"'{file}'" in message and said in message
    assert "geom 'g1'" in message and "body 'link1'" in message
    assert "repair" not in message and "mjMINVAL" not in message


@pytest.mark.parametrize(
    ("inertial", "compiler"),
    [
        ('<inertial pos="0 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>', ""),  # the body's own inertia
        ("", '<compiler inertiafromgeom="false"/>'),  # geoms carry no mass at all
    ],
    ids=["explicit_inertial", "inertiafromgeom_false"],
)
def test_mesh_without_mass_is_dropped_and_noted(tmp_path: Path, inertial: str, compiler: str) -> None:
    if compiler:
        inertial = '<inertial pos="0 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>'
    pair = load_model(_mjcf(tmp_path, "meshes/arm_missing.stl", inertial, compiler))
    (dropped,) = [f for f in pair.findings if f.kind is Kind.LOAD and "arm_missing.stl" in f.element]
    assert not dropped.affects_energy


def test_terminal_names_the_missing_mesh_and_gives_no_repair_advice(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _mjcf(tmp_path, "meshes/arm_missing.stl")
    for extra in ([], ["--repair-inertia"]):
        code = main(["compare", str(path), "--poses", "4", "--records", "none", "--out", str(tmp_path / "o"), *extra])
        out, err = capsys.readouterr()
        assert code == 1, out + err
        assert "arm_missing.stl" in err and "geom 'g1'" in err and "DISAGREE" not in out
        assert "repair" not in err and "repair" not in out


def test_terminal_row_notes_a_dropped_collision_mesh(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    urdf = (
        '<robot name="r"><link name="base"/>'
        '<link name="l1"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.02" izz="0.02" ixy="0" ixz="0" '
        'iyz="0"/></inertial><collision><geometry><mesh filename="meshes/does_not_exist.stl"/></geometry>'
        "</collision></link>"
        '<joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
    )
    path = tmp_path / "collision_missing.urdf"
    path.write_text(urdf)
    code = main(["compare", str(path), "--poses", "4", "--records", "none", "--out", str(tmp_path / "o")])
    out, _ = capsys.readouterr()
    assert code == 0, out
    (row,) = [line for line in out.splitlines() if line.startswith("collision_missing.urdf")]
    assert "agree" in row and "does_not_exist.stl" in out.split("Formulas:")[0]
