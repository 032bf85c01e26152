"""xacro files: a macro, properties, an $(arg) and package:// meshes, against the same arm expanded by hand."""

from __future__ import annotations

import os

import numpy as np
import pytest
from source_trees import write_hand_expanded

from koenig_check import compare
from koenig_check.cli import main
from koenig_check.engines import load_model
from koenig_check.engines.errors import ModelLoadError
from koenig_check.engines.load_options import LoadOptions, parse_xacro_args
from koenig_check.sources.catalogue import resolve_model
from koenig_check.sources.xacro import cache_dir

#: (xacro arguments, the length the hand-expanded file was written for)
CASES = {"default": ({}, "0.5"), "length=0.8": ({"length": "0.8"}, "0.8")}
#: Poses at which the mass matrices are compared (shoulder, elbow).
POSES = np.array([[0.0, 0.0], [0.4, -1.1], [-2.0, 2.5], [1.3, 0.7]])


def _mesh(arm_xacro):
    return arm_xacro.parents[1] / "meshes" / "link.stl"


@pytest.mark.parametrize("case", sorted(CASES))
def test_expansion_is_the_hand_expanded_robot(case, arm_xacro, tmp_path):
    args, length = CASES[case]
    hand = write_hand_expanded(tmp_path / "hand", length, _mesh(arm_xacro))
    pair, expected = load_model(arm_xacro, xacro_args=args), load_model(hand)
    assert pair.source.origin == "xacro" and pair.source.format == "urdf"
    for engine, reference in zip(pair.engines.values(), expected.engines.values(), strict=True):
        np.testing.assert_allclose(engine.mass_matrix(POSES), reference.mass_matrix(POSES), rtol=1e-12, atol=1e-15)
    assert pair.mujoco.model.nmesh == expected.mujoco.model.nmesh == 1  # the package:// mesh was found and read
    assert not [f for f in pair.findings if "mesh" in f.element]


def test_arg_changes_the_robot(arm_xacro):
    """The $(arg) is not ignored: two lengths, two mass matrices."""
    short, long = (load_model(arm_xacro, xacro_args={"length": v}) for v in ("0.5", "0.8"))
    assert not np.allclose(short.mujoco.mass_matrix(POSES), long.mujoco.mass_matrix(POSES), rtol=1e-3)


def test_package_uri_resolved_to_the_package_file(arm_xacro):
    text = resolve_model(arm_xacro).path.read_text()
    assert "package://" not in text
    assert _mesh(arm_xacro).resolve().as_uri() in text


@pytest.mark.parametrize("case", sorted(CASES))
def test_compare_agrees_under_a_label_with_the_args(case, arm_xacro):
    args, _ = CASES[case]
    check = compare(arm_xacro, n_poses=5, xacro_args=args)
    assert check.ok, check.reason()
    suffix = " [length=0.8]" if args else ""
    assert [c.model for c in check.comparisons] == [f"arm.urdf.xacro{suffix}"]


def test_find_through_ros_package_path(arm_xacro, tmp_path, monkeypatch):
    """A xacro file outside the package includes it by $(find arm_pkg): found through ROS_PACKAGE_PATH only."""
    top = tmp_path / "elsewhere" / "robot.urdf.xacro"
    top.parent.mkdir()
    top.write_text(
        '<?xml version="1.0"?><robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="$(find arm_pkg)/urdf/arm.urdf.xacro"/></robot>'
    )
    with pytest.raises(ModelLoadError, match=r"robot\.urdf\.xacro.*arm_pkg") as info:
        resolve_model(top)
    assert "\n" not in str(info.value)
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(arm_xacro.parents[2]))
    hand = write_hand_expanded(tmp_path / "hand", "0.5", _mesh(arm_xacro))
    np.testing.assert_allclose(
        load_model(top).pinocchio.mass_matrix(POSES), load_model(hand).pinocchio.mass_matrix(POSES), rtol=1e-12
    )


def test_bad_xacro_fails_alone_in_a_batch(arm_xacro, tmp_path):
    bad = tmp_path / "bad.urdf.xacro"
    bad.write_text('<robot name="b" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="${nope}"/></robot>')
    check = compare([bad, arm_xacro], n_poses=3)
    assert [c.model for c in check.comparisons] == ["arm.urdf.xacro"]
    [(label, reason)] = check.failures
    assert label == "bad.urdf.xacro" and "bad.urdf.xacro" in reason and "nope" in reason


def test_cli_xacro_arg(arm_xacro, capsys):
    assert main(["compare", os.fspath(arm_xacro), "--xacro-arg", "length=0.8", "--poses", "3"]) == 0
    assert "arm.urdf.xacro [length=0.8]  agree" in capsys.readouterr().out


def test_cli_xacro_arg_without_value_is_a_usage_error(arm_xacro, capsys):
    with pytest.raises(SystemExit) as info:
        main(["compare", os.fspath(arm_xacro), "--xacro-arg", "length"])
    assert info.value.code == 2
    assert "expected NAME=VALUE, got 'length'" in capsys.readouterr().err


@pytest.mark.parametrize(
    "given",
    [{"length": 0.8, "hands": True}, ["length=0.8", "hands=true"], [("hands", True), ("length", "0.8")]],
)
def test_xacro_args_spellings_are_one_option(given):
    assert parse_xacro_args(given) == (("hands", "true"), ("length", "0.8"))
    assert LoadOptions(xacro_args=given) == LoadOptions(xacro_args={"length": "0.8", "hands": "true"})
    hash(LoadOptions(xacro_args=given))  # the pipeline keys loaded models by their options


@pytest.mark.parametrize("bad", [["length"], ["=0.8"], [3]])
def test_malformed_xacro_args_are_refused(bad):
    with pytest.raises((TypeError, ValueError)):
        LoadOptions(xacro_args=bad)


MACROS_ONLY = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side">
    <link name="${side}_wheel"><inertial><mass value="1"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  </xacro:macro>
</robot>
"""


@pytest.mark.parametrize("floating", [False, True])
def test_a_file_of_macros_only_fails_alone_naming_its_macros(arm_xacro, tmp_path, floating):
    parts = tmp_path / "parts.urdf.xacro"  # like hector's quadrotor_base.urdf.xacro: included, never called
    parts.write_text(MACROS_ONLY)
    check = compare([parts, arm_xacro], n_poses=3, floating=floating)
    reasons = dict(check.failures)  # the arm is still compared (floating, it fails for its own massless base)
    assert [c.model for c in check.comparisons] == ([] if floating else ["arm.urdf.xacro"])
    assert "link 'base'" in reasons.get("arm.urdf.xacro (floating)", "link 'base'")
    [label] = [name for name in reasons if name.startswith("parts.urdf.xacro")]
    reason = reasons[label]
    assert "without any <link>" in reason and "macros (wheel)" in reason
    assert str(tmp_path) not in check.failure_lines[label]  # the line is short and whole
    assert check.failure_lines[label].endswith("expand the file that uses it")


def test_failures_name_the_xacro_file_not_its_expansion(tmp_path):
    bad = tmp_path / "bad.urdf.xacro"  # expands, then MuJoCo refuses the inertia (A + B < C)
    bad.write_text(
        '<robot name="b"><link name="base"/><link name="l1"><inertial><mass value="1"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="5"/></inertial></link>'
        '<joint name="j" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
    )
    check = compare(bad, n_poses=2)
    [(label, reason)] = check.failures
    expanded = str(cache_dir())
    assert expanded in reason  # the engine read the expansion...
    line = check.failure_lines[label]
    assert expanded not in line and "link 'l1'" in line  # ...the user is told about the file they gave


def test_a_missing_package_is_said_once_without_python_spelling(arm_xacro, tmp_path):
    """rtb-data's kr6r700sixx.xacro: xacro printed "<class 'xacrodoc.packages.PackageNotFoundError'>: Package not
    found: pkg Package not found: pkg"."""
    bad = tmp_path / "needs_pkg.xacro"
    bad.write_text(
        '<robot name="b" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="$(find no_such_support)/urdf/macro.xacro"/></robot>'
    )
    check = compare([bad, arm_xacro], n_poses=2)
    assert [c.model for c in check.comparisons] == ["arm.urdf.xacro"]  # the batch goes on
    [(label, reason)] = check.failures
    assert reason.endswith("xacro cannot expand needs_pkg.xacro: Package not found: no_such_support")
    assert check.failure_lines[label] == "needs_pkg.xacro: xacro cannot expand needs_pkg.xacro: " + (
        "Package not found: no_such_support"
    )
