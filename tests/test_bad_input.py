"""Bad input: a clear one-line error naming the file and the element, and nothing else lost."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from koenig_check.api import compare
from koenig_check.engines import load_model
from koenig_check.findings import Kind
from koenig_check.run.pose_file import PoseFileError, load_pose_file

MODELS = Path(__file__).resolve().parents[1] / "models"

LINK = (
    '<link name="{name}"><inertial><origin xyz="0.1 0 0"/><mass value="{mass}"/>'
    '<inertia ixx="{ixx}" iyy="{iyy}" izz="{izz}" ixy="{ixy}" ixz="0" iyz="0"/></inertial></link>'
)
JOINT = (
    '<joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/>'
    '<origin xyz="0.2 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
)


def _urdf(tmp_path: Path, arm: dict, name: str = "robot.urdf") -> Path:
    good = {"name": "upper", "mass": 1, "ixx": 0.01, "iyy": 0.02, "izz": 0.02, "ixy": 0}
    links = [LINK.format(**good), LINK.format(**{**good, **arm, "name": "forearm"})]
    joints = [
        JOINT.format(name="shoulder", parent="base", child="upper"),
        JOINT.format(name="elbow", parent="upper", child="forearm"),
    ]
    path = tmp_path / name
    path.write_text(f'<robot name="r"><link name="base"/>{"".join(links)}{"".join(joints)}</robot>')
    return path


def _one_line_naming(err: BaseException, *needles: str) -> str:
    text = str(err)
    assert "\n" not in text, text
    for needle in needles:
        assert needle in text, (needle, text)
    return text


@pytest.mark.parametrize(
    ("arm", "needles"),
    [
        ({"mass": 0}, ["forearm", "mass"]),
        ({"mass": -2}, ["forearm", "mass"]),
        ({"ixx": 0.01, "iyy": 0.01, "izz": 0.05}, ["forearm", "A + B >= C", "principal moments"]),
        ({"ixx": -0.01}, ["forearm", "principal moments"]),
        ({"mass": "nan"}, ['<link name="forearm"> <mass> value="nan"']),
        ({"mass": "inf"}, ["link 'forearm'", "mass inf kg", "not finite"]),
        ({"mass": "-inf"}, ["link 'forearm'", "mass -inf kg", "not finite"]),
        ({"ixy": "NaN"}, ['<link name="forearm"> <inertia> ixy="NaN"']),
        ({"ixy": "inf"}, ["link 'forearm'", "inertia (ixx iyy izz ixy ixz iyz) 0.01 0.02 0.02 inf 0 0"]),
    ],
    ids=[
        "zero-mass",
        "negative-mass",
        "triangle-inequality",
        "not-positive-definite",
        "nan-mass",
        "inf-mass",
        "minus-inf-mass",
        "nan-inertia",
        "inf-inertia",
    ],
)
def test_non_physical_links_are_named_with_their_moments(tmp_path: Path, arm: dict, needles: list[str]) -> None:
    path = _urdf(tmp_path, arm)
    with pytest.raises(ValueError) as info:
        load_model(path)
    _one_line_naming(info.value, str(path), *needles)


def test_balance_inertia_opt_in_loads_and_records_the_change(tmp_path: Path) -> None:
    path = _urdf(tmp_path, {"ixx": 0.01, "iyy": 0.01, "izz": 0.05})
    pair = load_model(path, balance_inertia=True)
    notes = " ".join(pair.notes)
    assert "forearm" in notes and "balance" in notes


def test_moving_link_without_inertial_is_named(tmp_path: Path) -> None:
    path = tmp_path / "no_inertial.urdf"
    good = LINK.format(name="upper", mass=1, ixx=0.01, iyy=0.02, izz=0.02, ixy=0)
    path.write_text(
        f'<robot name="r"><link name="base"/>{good}<link name="forearm"/>'
        + JOINT.format(name="shoulder", parent="base", child="upper")
        + JOINT.format(name="elbow", parent="upper", child="forearm")
        + "</robot>"
    )
    with pytest.raises(ValueError) as info:
        load_model(path)
    _one_line_naming(info.value, str(path), "forearm")


def test_non_symmetric_full_inertia_in_mjcf_is_named(tmp_path: Path) -> None:
    # MJCF fullinertia is symmetric by construction; a non-PD one is the reachable failure.
    path = tmp_path / "bad_inertia.xml"
    path.write_text(
        '<mujoco><compiler inertiafromgeom="false"/><worldbody><body name="arm"><joint name="j" axis="0 0 1"/>'
        '<inertial pos="0 0 0" mass="1" fullinertia="0.01 0.01 0.01 0.5 0 0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(ValueError) as info:
        load_model(path)
    _one_line_naming(info.value, str(path), "arm")


#: A geom MuJoCo refuses for its own value, and how the one-line error must name it: the body the user finds it in
#: and the geom (by name, or by its place among the body's geoms: MuJoCo's message names an unnamed geom '').
GEOM_REFUSALS = {
    "unnamed-geom": (
        '<mujoco><worldbody><body name="arm"><joint name="hinge" type="hinge"/>'
        '<geom type="sphere" size="0.1" mass="-1"/></body></worldbody></mujoco>',
        "body 'arm', geom #1 (unnamed, line 1)",
    ),
    "named-geom": (
        '<mujoco><worldbody><body name="arm"><joint name="hinge" type="hinge"/>'
        '<geom name="rod" type="sphere" size="0.1" mass="-1"/></body></worldbody></mujoco>',
        "body 'arm', geom 'rod' (line 1)",
    ),
    "second-geom-of-a-later-body": (
        '<mujoco><worldbody><geom type="plane" size="1 1 1"/>\n'
        '<body name="upper"><joint type="hinge"/><geom type="sphere" size="0.1"/>\n'
        '<body name="fore"><joint type="hinge"/><geom type="sphere" size="0.1"/>\n'
        '<geom type="box" size="0.1 0.1 0.1" density="-5"/></body></body></worldbody></mujoco>',
        "body 'fore', geom #2 (unnamed, line 4)",
    ),
}


@pytest.mark.parametrize("case", list(GEOM_REFUSALS))
def test_a_geom_mujoco_refuses_is_named_by_its_body_and_place(tmp_path: Path, case: str) -> None:
    """MuJoCo's reason whole, and the element the user can find: never ``body ''`` (the geom's empty name)."""
    content, element = GEOM_REFUSALS[case]
    path = tmp_path / "geom.xml"
    path.write_text(content)
    for repair in (False, True):  # no body repair changes a geom's own mass: the same refusal
        with pytest.raises(ValueError) as info:
            load_model(path, repair_inertia=repair)
        text = _one_line_naming(info.value, str(path), element, "mass, inertia or density are negative in geom")
        assert "body ''" not in text and "--repair-inertia" not in text
    proc = _cli("parity", str(path))
    first, *rest = proc.stderr.strip().splitlines()
    assert proc.returncode == 1 and element in first and all(line.startswith("    ") for line in rest)
    assert any(line.strip().startswith("MuJoCo says: ") for line in rest), proc.stderr  # MuJoCo's own words


@pytest.mark.parametrize(
    ("content", "needles"),
    [
        ("", ["file is empty"]),
        ("plain text", ["not well-formed XML"]),
        ("<mujoco><worldbody><body name='a'>", ["not well-formed XML"]),
        ("<sdf version='1.6'/>", ["neither <mujoco> (MJCF) nor <robot> (URDF)"]),
        ('<!DOCTYPE r [<!ENTITY a "aaaa">]><robot name="&a;"/>', ["DOCTYPE/ENTITY"]),
        (
            '<mujoco><worldbody><body name="link"><joint type="hinge"/>'
            '<geom name="rod" type="sphere" size="0.1" mass="nan"/></body></worldbody></mujoco>',
            ['<geom name="rod"> mass="nan"', "NaN"],
        ),
        (
            '<robot name="r"><link name="base"/><link name="arm"><inertial><mass value="1"/>'
            '<inertia ixx="0.1" iyy="NaN" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>',
            ['<link name="arm"> <inertia> iyy="NaN"', "NaN"],
        ),
        (
            '<mujoco><worldbody><body name="link" pos="0 nan 1"><joint type="hinge"/>'
            '<geom type="sphere" size="0.1"/></body></worldbody></mujoco>',
            ['<body name="link"> pos="0 nan 1"'],
        ),
        (
            '<mujoco><worldbody><body name="link"><joint type="hinge" axis="0 -NaN 1"/>'
            '<geom type="sphere" size="0.1"/></body></worldbody></mujoco>',
            ['<joint> axis="0 -NaN 1"'],
        ),
    ],
    ids=[
        "empty",
        "not-xml",
        "truncated",
        "not-mjcf-or-urdf",
        "entities",
        "nan-geom-mass",
        "nan-urdf-inertia",
        "nan-pos",
        "signed-nan-axis",
    ],
)
def test_unreadable_model_files_fail_before_the_engines(tmp_path: Path, content: str, needles: list[str]) -> None:
    path = tmp_path / "model.xml"
    path.write_text(content)
    with pytest.raises(ValueError) as info:
        load_model(path)
    _one_line_naming(info.value, str(path), *needles)


def test_a_body_called_nan_is_not_a_nan_number(tmp_path: Path) -> None:
    path = tmp_path / "named.xml"
    path.write_text(
        '<mujoco><worldbody><body name="nan"><joint name="NaN" type="hinge"/>'
        '<geom type="sphere" size="0.1"/></body></worldbody></mujoco>'
    )
    assert load_model(path).mujoco.model.nbody == 2


def test_elements_called_nan_referenced_by_name_are_not_nan_numbers(tmp_path: Path) -> None:
    """A site called nan named by an actuator's refsite, a sensor's refname and a tendon's sidesite."""
    path = tmp_path / "refs.xml"
    path.write_text(
        '<mujoco><worldbody><body name="b"><joint name="j" type="hinge" axis="0 0 1"/>'
        '<geom name="g" type="sphere" size="0.1" mass="1"/><site name="nan" pos="0 0 0.1"/>'
        '<site name="s2" pos="0 0.1 0"/><site name="s3" pos="0.1 0 0"/></body></worldbody>'
        '<tendon><spatial name="t"><site site="s2"/><geom geom="g" sidesite="nan"/><site site="s3"/></spatial></tendon>'
        '<actuator><general name="a" site="s2" refsite="nan" gear="1 0 0 0 0 0"/></actuator>'
        '<sensor><framepos name="fp" objtype="site" objname="s2" reftype="site" refname="nan"/></sensor></mujoco>'
    )
    assert load_model(path).mujoco.model.nsite == 3


def test_missing_file_is_named(tmp_path: Path) -> None:
    with pytest.raises(ValueError) as info:
        load_model(tmp_path / "nowhere.urdf")
    _one_line_naming(info.value, "nowhere.urdf")


def test_missing_and_unsupported_meshes_load_inertia_only(tmp_path: Path) -> None:
    text = (MODELS / "gimbal.urdf").read_text()
    meshes = (
        '<visual><geometry><mesh filename="missing_visual.stl"/></geometry></visual>'
        '<collision><geometry><mesh filename="missing.stl"/></geometry></collision>'
        '<collision><geometry><mesh filename="shape.dae"/></geometry></collision>'
    )
    text = text.replace("</link>", meshes + "</link>", 2)
    (tmp_path / "shape.dae").write_text("<COLLADA/>")
    path = tmp_path / "gimbal_meshes.urdf"
    path.write_text(text)
    pair = load_model(path)
    notes = " ".join(pair.notes)
    assert "missing.stl" in notes and "shape.dae" in notes
    reference = load_model(MODELS / "gimbal.urdf")
    q = np.zeros((1, reference.mujoco.nq))
    v = np.ones((1, reference.mujoco.nv))
    np.testing.assert_allclose(
        pair.mujoco.kinetic_energy(q, v).rigid, reference.mujoco.kinetic_energy(q, v).rigid, rtol=1e-12
    )


MIMIC = (
    '<robot name="m"><link name="base"/>'
    + LINK.format(name="a", mass=1, ixx=0.01, iyy=0.02, izz=0.02, ixy=0)
    + LINK.format(name="b", mass=1, ixx=0.01, iyy=0.02, izz=0.02, ixy=0)
    + JOINT.format(name="j1", parent="base", child="a")
    + JOINT.format(name="j2", parent="a", child="b").replace("</joint>", '<mimic joint="j1" multiplier="2"/></joint>')
    + "</robot>"
)
LOOP = """<mujoco><compiler inertiafromgeom="false"/><worldbody>
  <body name="a"><joint name="ja" axis="0 0 1"/><inertial pos="0.1 0 0" mass="1" diaginertia="0.01 0.02 0.02"/>
    <body name="b" pos="0.2 0 0"><joint name="jb" axis="0 0 1"/>
      <inertial pos="0.1 0 0" mass="1" diaginertia="0.01 0.02 0.02"/></body></body>
</worldbody>
<equality><connect name="close" body1="b" anchor="0.2 0 0"/></equality></mujoco>"""
TENDON = """<mujoco><compiler inertiafromgeom="false"/><worldbody>
  <body name="a"><joint name="ja" axis="0 0 1"/><inertial pos="0.1 0 0" mass="1" diaginertia="0.01 0.02 0.02"/>
    <body name="b" pos="0.2 0 0"><joint name="jb" axis="0 0 1"/>
      <inertial pos="0.1 0 0" mass="1" diaginertia="0.01 0.02 0.02"/></body></body>
</worldbody>
<tendon><fixed name="couple"><joint joint="ja" coef="1"/><joint joint="jb" coef="-1"/></fixed></tendon>
<equality><tendon name="tie" tendon1="couple"/></equality></mujoco>"""


@pytest.mark.parametrize(
    ("name", "content", "needles"),
    [
        ("mimic.urdf", MIMIC, ["joint j2", "mimic", "leader j1", "multiplier 2"]),
        ("loop.xml", LOOP, ["equality close", "connect closes a loop", "(between b, world)"]),
        ("tendon.xml", TENDON, ["equality tie", "tendons couple", "joints ja, jb"]),
    ],
)
def test_coupled_joints_and_loops_are_loaded_and_named(tmp_path: Path, name: str, content: str, needles: list) -> None:
    # Behaviour changed by design (issue 8): these were refused; T(q, q̇) is defined on the tree's coordinates.
    path = tmp_path / name
    path.write_text(content)
    (found,) = [f for f in load_model(path).findings if f.kind is Kind.COUPLING]
    assert not found.affects_energy
    _one_line_naming(ValueError(found.message()), *needles)
    check = compare(path, n_poses=4)
    assert check.ok, check.reason()


def test_joints_missing_in_one_engine_are_listed(tmp_path: Path) -> None:
    renamed = tmp_path / "renamed.urdf"
    renamed.write_text((MODELS / "gimbal.urdf").read_text().replace('"inner_x"', '"inner_tilt"'))
    with pytest.raises(ValueError) as info:
        load_model(MODELS / "gimbal.urdf", pinocchio_source=renamed)
    _one_line_naming(info.value, "inner_x", "inner_tilt")


# ------------------------------------------------------------------------- poses
@pytest.fixture(scope="module")
def gimbal():
    return load_model(MODELS / "gimbal.xml").mujoco.model


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_pose_values_are_refused_with_row_and_joint(tmp_path: Path, gimbal, bad: float) -> None:
    rows = np.zeros((3, 4))
    rows[1, 3] = bad  # qvel of inner_x on the second row
    path = tmp_path / "poses.csv"
    np.savetxt(path, rows, delimiter=",", header="outer_z,inner_x,d_outer_z,d_inner_x")
    with pytest.raises(PoseFileError) as info:
        load_pose_file(path, gimbal)
    _one_line_naming(info.value, str(path), "row 2", "qvel[1] (inner_x)", "finite")


def test_non_finite_qpos_is_refused_with_row_and_joint(tmp_path: Path, gimbal) -> None:
    rows = np.zeros((3, 4))
    rows[2, 0] = np.nan  # qpos of outer_z on the third row
    path = tmp_path / "poses.csv"
    np.savetxt(path, rows, delimiter=",")
    with pytest.raises(PoseFileError) as info:
        load_pose_file(path, gimbal)
    _one_line_naming(info.value, str(path), "row 3", "qpos[0] (outer_z)", "finite")


def test_non_unit_quaternion_is_refused_with_row_and_joint(tmp_path: Path) -> None:
    model = load_model(MODELS / "free_body.xml").mujoco.model
    assert (model.nq, model.nv) == (7, 6)
    qpos = np.tile([0.1, 0.2, 0.3, 1.0, 0.0, 0.0, 0.0], (3, 1))
    qpos[1, 3:] = [0.0, 1.1, 0.0, 0.0]  # norm 1.1 on the second row
    path = tmp_path / "free.npz"
    np.savez(path, qpos=qpos, qvel=np.ones((3, 6)))
    with pytest.raises(PoseFileError) as info:
        load_pose_file(path, model)
    _one_line_naming(info.value, str(path), "row 2", "quaternion of joint 'root'", "norm 1.1")
    qpos[1, 3:] = [0.0, 0.6, 0.8, 0.0]  # unit, not identity: accepted
    np.savez(path, qpos=qpos, qvel=np.ones((3, 6)))
    assert load_pose_file(path, model).n_poses == 3


def test_pose_below_a_lower_joint_limit_is_flagged(tmp_path: Path, gimbal) -> None:
    path = tmp_path / "low.npz"
    np.savez(path, qpos=np.array([[0.1, 0.2], [0.0, -0.5], [0.0, -3.5]]), qvel=np.ones((3, 2)))
    poses = load_pose_file(path, gimbal)
    assert poses.n_poses == 3
    assert len(poses.notes) == 1, poses.notes  # only row 3 is outside: inner_x = -3.5 < -π
    assert "'inner_x' outside its range" in poses.notes[0] and "row 3" in poses.notes[0] and "-3.5" in poses.notes[0]


def test_npz_pose_file_and_out_of_limit_poses_are_flagged(tmp_path: Path, gimbal) -> None:
    path = tmp_path / "poses.npz"
    np.savez(path, qpos=np.array([[0.1, 0.2], [4.0, 0.0]]), qvel=np.ones((2, 2)))
    poses = load_pose_file(path, gimbal)
    assert poses.n_poses == 2 and poses.kind == "file"
    assert any("'outer_z' outside its range" in n and "row 2" in n for n in poses.notes)


def test_pose_file_shape_and_text_errors(tmp_path: Path, gimbal) -> None:
    path = tmp_path / "p.csv"
    path.write_text("1,2,3\n")
    with pytest.raises(PoseFileError, match=re.escape("row 1: 3 values, expected nq + nv = 2 + 2")):
        load_pose_file(path, gimbal)
    path.write_text("a,b,c,d\n1,2,x,4\n")
    with pytest.raises(PoseFileError, match="row 2: 'x' is not a number"):
        load_pose_file(path, gimbal)
    with pytest.raises(PoseFileError, match="pose file not found"):
        load_pose_file(tmp_path / "none.csv", gimbal)


def test_zero_velocity_scale_is_refused_with_the_reason() -> None:
    with pytest.raises(ValueError, match="velocity_scale must be a finite number > 0"):  # a usage error, raised
        compare([MODELS / "gimbal.xml"], n_poses=3, velocity_scale=0.0)


# ------------------------------------------------------------------------- batches and CLI
def test_a_failing_model_never_loses_the_others(tmp_path: Path) -> None:
    bad = _urdf(tmp_path, {"mass": -1}, "negative.urdf")
    check = compare([MODELS / "gimbal.xml", bad, MODELS / "double_pendulum.urdf"], n_poses=3)
    assert [c.model for c in check.comparisons] == ["gimbal.xml", "double_pendulum.urdf"]
    assert [m for m, _ in check.failures] == ["negative.urdf"] and "forearm" in check.failures[0][1]
    assert not check.ok and "negative.urdf" in check.reason()


def _cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", *args], capture_output=True, text=True, check=False, timeout=300
    )


def test_cli_never_shows_a_traceback_unless_debug(tmp_path: Path) -> None:
    path = tmp_path / "broken.urdf"
    path.write_text("<robot><link name='a'>")
    proc = _cli("parity", str(path))
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    first, *rest = proc.stderr.strip().splitlines()  # one message: a line naming the file, the rest indented
    assert str(path) in first and all(line.startswith("    ") for line in rest)
    debug = _cli("parity", str(path), "--debug")
    assert debug.returncode != 0 and "Traceback" in debug.stderr


def test_pose_file_entirely_at_rest_is_refused_and_partial_rest_is_noted(tmp_path: Path, gimbal) -> None:
    path = tmp_path / "rest.csv"
    np.savetxt(path, np.zeros((3, 4)), delimiter=",")
    with pytest.raises(PoseFileError, match="every pose has zero velocity"):
        load_pose_file(path, gimbal)
    rows = np.zeros((3, 4))
    rows[2, 2] = 1.0
    np.savetxt(path, rows, delimiter=",")
    poses = load_pose_file(path, gimbal)
    assert any("2 pose(s) at rest (first: row 1)" in n for n in poses.notes)


def test_a_failed_model_is_named_once_in_the_reason() -> None:
    check = compare(["my_robot.urdf", "gimbal.xml"], n_poses=2, formulas=["exact"])
    assert check.reason() == "my_robot.urdf: no such file (`koenig-check models` lists every name)"
