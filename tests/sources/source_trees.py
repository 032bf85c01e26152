"""Offline stand-ins for where robots live: a Menagerie tree, a ROS package with a xacro file, robot_descriptions.

Everything is written into a test's temporary directory; nothing is downloaded or cloned.
"""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import pytest

#: A robot of mujoco-menagerie's registry whose entry points are its default model and a scene.
MENAGERIE_ROBOT = "agilex_piper"
MENAGERIE_MODEL_FILE = "piper.xml"  # the registry's default_model entry file
MENAGERIE_SCENE_FILE = "scene.xml"

#: Our own two-hinge arm, standing in for the robot's file (same name and place as in Menagerie).
ARM_MJCF = """<mujoco model="piper">
  <compiler angle="radian" inertiafromgeom="false"/>
  <worldbody>
    <body name="link1" pos="0 0 0.1">
      <joint name="joint1" type="hinge" axis="0 0 1" range="-2.6 2.6"/>
      <inertial pos="0 0.01 0.05" mass="0.9" diaginertia="0.004 0.003 0.002"/>
      <geom type="capsule" size="0.03" fromto="0 0 0 0 0 0.1"/>
      <body name="link2" pos="0 0 0.1">
        <joint name="joint2" type="hinge" axis="0 1 0" range="-2 2"/>
        <inertial pos="0.12 0 0" mass="0.6" diaginertia="0.001 0.005 0.005"/>
        <geom type="capsule" size="0.02" fromto="0 0 0 0.24 0 0"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

SCENE_MJCF = f"""<mujoco model="piper scene">
  <include file="{MENAGERIE_MODEL_FILE}"/>
  <worldbody>
    <light pos="0 0 2"/>
  </worldbody>
</mujoco>
"""


def write_robot_dir(directory: Path) -> Path:
    """A Menagerie robot directory: the default model and a scene that includes it."""
    directory.mkdir(parents=True, exist_ok=True)
    (directory / MENAGERIE_MODEL_FILE).write_text(ARM_MJCF)
    (directory / MENAGERIE_SCENE_FILE).write_text(SCENE_MJCF)
    return directory


def menagerie_root(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Serve a checkout through ``MENAGERIE_ROOT``; return the robot's directory."""
    root = tmp_path / "menagerie"
    robot_dir = write_robot_dir(root / MENAGERIE_ROBOT)
    no_network(tmp_path, monkeypatch)
    monkeypatch.setenv("MENAGERIE_ROOT", str(root))
    return robot_dir


def menagerie_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A prepared ``MENAGERIE_CACHE_DIR``: the robot published as the package publishes it; its directory."""
    import mujoco_menagerie as mm

    oid = mm.get(MENAGERIE_ROBOT).oid
    cache = tmp_path / "menagerie-cache"
    robot_dir = write_robot_dir(cache / "models" / f"{MENAGERIE_ROBOT}-{oid[:16]}")
    (robot_dir / ".complete").write_text(json.dumps({"oid": oid, "files": {}}))
    no_network(tmp_path, monkeypatch)
    monkeypatch.setenv("MENAGERIE_CACHE_DIR", str(cache))
    return robot_dir


def no_network(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """No checkout, an empty cache and a mirror that does not exist: a download fails at once, offline."""
    monkeypatch.delenv("MENAGERIE_ROOT", raising=False)
    monkeypatch.setenv("MENAGERIE_CACHE_DIR", str(tmp_path / "empty-menagerie-cache"))
    monkeypatch.setenv("MENAGERIE_BASE_URL", (tmp_path / "no-such-mirror").as_uri())


# ------------------------------------------------------------------------------------------------ xacro
#: A two-link arm with a macro, properties, an $(arg) and package:// meshes.
ARM_XACRO = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="length" default="0.5"/>
  <xacro:property name="L" value="$(arg length)"/>
  <xacro:property name="m" value="1.5"/>
  <xacro:macro name="link_box" params="name mass length">
    <link name="${name}">
      <inertial>
        <origin xyz="0 0 ${length/2}"/>
        <mass value="${mass}"/>
        <inertia ixx="${mass*(length*length+0.01)/12}" iyy="${mass*(length*length+0.01)/12}"
                 izz="${mass*0.02/12}" ixy="0" ixz="0" iyz="0"/>
      </inertial>
      <collision><geometry><mesh filename="package://arm_pkg/meshes/link.stl"/></geometry></collision>
    </link>
  </xacro:macro>
  <link name="base"/>
  <xacro:link_box name="upper" mass="${m}" length="${L}"/>
  <xacro:link_box name="lower" mass="${m*0.5}" length="${L*0.8}"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="10"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="lower"/><origin xyz="0 0 ${L}"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="10"/>
  </joint>
</robot>
"""

#: The same arm expanded by hand (m = 1.5; upper: mass m, length L; lower: mass m/2, length 0.8 L;
#: I_xx = I_yy = mass (length² + 0.01) / 12, I_zz = mass 0.02 / 12), for L = 0.5 and L = 0.8.
HAND_EXPANDED = {
    "0.5": dict(com1="0.25", ixx1="0.0325", com2="0.2", ixx2="0.010625", elbow="0.5"),
    "0.8": dict(com1="0.4", ixx1="0.08125", com2="0.32", ixx2="0.026225", elbow="0.8"),
}

HAND_URDF = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz="0 0 {com1}"/><mass value="1.5"/>
      <inertia ixx="{ixx1}" iyy="{ixx1}" izz="0.0025" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <link name="lower">
    <inertial><origin xyz="0 0 {com2}"/><mass value="0.75"/>
      <inertia ixx="{ixx2}" iyy="{ixx2}" izz="0.00125" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="10"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="lower"/><origin xyz="0 0 {elbow}"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="10"/>
  </joint>
</robot>
"""


def write_binary_stl(path: Path) -> Path:
    """A small tetrahedron as a binary STL (MuJoCo reads binary STL only)."""
    a, b, c, d = (0, 0, 0), (0.05, 0, 0), (0, 0.05, 0), (0, 0, 0.05)
    triangles = [(a, c, b), (a, b, d), (a, d, c), (b, c, d)]
    data = bytearray(80) + struct.pack("<I", len(triangles))
    for triangle in triangles:
        data += struct.pack("<3f", 0, 0, 0)
        for vertex in triangle:
            data += struct.pack("<3f", *vertex)
        data += b"\0\0"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(bytes(data))
    return path


def write_arm_package(root: Path) -> Path:
    """``root/arm_pkg``: package.xml, urdf/arm.urdf.xacro, meshes/link.stl; return the xacro file."""
    package = root / "arm_pkg"
    (package / "urdf").mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text(
        '<?xml version="1.0"?><package format="2"><name>arm_pkg</name><version>0.0.1</version>'
        "<description>test arm</description><maintainer email='a@b.c'>a</maintainer><license>MIT</license>"
        "</package>"
    )
    write_binary_stl(package / "meshes" / "link.stl")
    xacro = package / "urdf" / "arm.urdf.xacro"
    xacro.write_text(ARM_XACRO)
    return xacro


def write_hand_expanded(directory: Path, length: str, mesh: Path) -> Path:
    """The hand-expanded URDF of the arm for one length."""
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"arm_hand_L{length.replace('.', '')}.urdf"
    path.write_text(HAND_URDF.format(mesh=mesh.as_posix(), **HAND_EXPANDED[length]))
    return path


# ------------------------------------------------------------------------------------- robot_descriptions
def install_stub_descriptions(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, modules: dict[str, str]) -> Path:
    """A stub ``robot_descriptions`` package on ``sys.path`` with the given modules (name -> source text).

    The real package (if imported earlier) is hidden from ``sys.modules`` for the test; use it through the
    ``stub_descriptions`` fixture, which puts the real modules back afterwards.
    """
    stubs = tmp_path / "stubs"
    package = stubs / "robot_descriptions"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text(f"DESCRIPTIONS = {{name: None for name in {sorted(modules)!r}}}\n")
    for name, text in modules.items():
        (package / f"{name}.py").write_text(text)
    for name in descriptions_modules():
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.syspath_prepend(str(stubs))
    return package


def descriptions_modules() -> list[str]:
    """The ``robot_descriptions`` modules imported in this process."""
    return [m for m in sys.modules if m == "robot_descriptions" or m.startswith("robot_descriptions.")]
