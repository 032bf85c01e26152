"""``pytest --koenig-check`` on small projects (pytester): one item per model, the CLI's verdict, no helper frames.

Each project runs in a subprocess (``runpytest_subprocess``), and so does the command line it is held against:
pytester drops from ``sys.modules`` whatever a test imported (pydrake included), which would break the tests
after it.  Spies and a missing Drake are set up by the project's own conftest.py.
"""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
AGREES = ROOT / "models" / "double_pendulum.xml"
DISAGREES = ROOT / "tests" / "models" / "causes" / "class_mass.xml"  # Pinocchio ignores a class's geom mass
ROOT_CAUSE = "root cause: pinocchio: geom pole: geom mass from default class 'pole' not applied by Pinocchio"
#: Text of the plugin's and the helper's own source that a failure must not show.
HELPER_SOURCE = ("def runtest", "__tracebackhide__", "def assert_energy_parity", "problems.append", "Traceback")

#: A one-link arm whose mass is a xacro argument without a default: it expands only when the arg is given.
LINK_XACRO = """<?xml version="1.0"?>
<robot name="link" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="mass" default=""/>
  <link name="base">
    <inertial><mass value="2.0"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="arm">
    <inertial><origin xyz="0.2 0 0"/><mass value="$(arg mass)"/>
      <inertia ixx="0.001" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="hinge" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""

#: The project's conftest.py: spies on the loader, compare and dynamics (written to calls.json); no Drake;
#: a dynamics check that fails.
SPIES = """
import json, pathlib
import koenig_check, koenig_check.engines, koenig_check.engines.registry as registry

CALLS = pathlib.Path(__file__).parent / "calls.json"
calls = {"load": [], "compare": [], "dynamics": []}
_load, _compare = koenig_check.engines.load_model, koenig_check.compare


def _record(kind, value):
    calls[kind].append(value)
    CALLS.write_text(json.dumps(calls))


def load_model(model, options=None, **kwargs):
    _record("load", [pathlib.Path(str(model)).name, options.floating, [list(p) for p in options.xacro_args]])
    return _load(model, options, **kwargs)


def compare(models, **kwargs):
    model = next(iter(models.values())) if isinstance(models, dict) else models  # {label: model} from the plugin
    _record("compare", [pathlib.Path(str(model)).name, kwargs.get("rtol"), kwargs.get("n_poses"), kwargs.get("seed")])
    return _compare(models, **kwargs)


class Failing:
    ok = False

    def reason(self):
        return "exact: M off by 1e-3"


def dynamics(model, **options):
    _record("dynamics", [pathlib.Path(str(model)).name, options])
    return Failing()


koenig_check.engines.load_model = load_model
koenig_check.compare = compare
koenig_check.dynamics = dynamics
registry.installed = lambda name: name != "drake"
"""


@pytest.fixture(autouse=True)
def _xacro_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("KOENIG_CHECK_CACHE", str(tmp_path / "koenig-check-cache"))


def _project(pytester: pytest.Pytester, models: str, extra: str = "") -> Path:
    (pytester.path / "models").mkdir()
    shutil.copy(AGREES, pytester.path / "models" / "arm.xml")
    shutil.copy(DISAGREES, pytester.path / "models" / "cartpole.xml")
    (pytester.path / "models" / "link.urdf.xacro").write_text(LINK_XACRO)
    pytester.makepyprojecttoml(f"[tool.koenig-check]\nmodels = [\n{models}\n]\n{extra}")
    return pytester.path


def _failures(text: str) -> str:
    return text[text.index("= FAILURES =") : text.index("short test summary")]


def test_pass_and_failure_as_the_cli_root_cause_first_and_one_report(pytester):
    outside = [ROOT / "tests" / "models" / "causes" / "mesh_geom.xml"]  # an absolute path
    _project(pytester, '"models/arm.xml", "models/cartpole.xml", ' + ", ".join(f'"{m}"' for m in outside))
    pytester.makepyfile(
        test_parity="""
        from koenig_check.testing import assert_energy_parity

        def test_cartpole():
            assert_energy_parity("models/cartpole.xml")
        """
    )
    result = pytester.runpytest_subprocess("--koenig-check", "-v", "--koenig-check-report", "report")
    text = result.stdout.str()
    # one item per model, its id the model's label, passing exactly when `koenig-check compare` exits 0
    for model in [pytester.path / "models" / "arm.xml", pytester.path / "models" / "cartpole.xml", *outside]:
        exit_status = pytester.run(sys.executable, "-m", "koenig_check.cli", "compare", str(model)).ret
        assert f"pyproject.toml::{model.name} {'PASSED' if exit_status == 0 else 'FAILED'}" in text, model
    assert "pyproject.toml::arm.xml PASSED" in text and "pyproject.toml::cartpole.xml FAILED" in text
    model_failure, helper_failure = _failures(text).split("_ test_cartpole _")
    # the plugin's failure: the verdict, root cause first, nothing of the plugin's source
    assert ROOT_CAUSE in model_failure
    assert model_failure.index("root cause:") < model_failure.index("engines: MuJoCo and Pinocchio")
    # the helper's failure reads the same way
    assert "root cause: pinocchio: geom pole: geom mass from default class 'pole'" in helper_failure
    assert helper_failure.index("root cause:") < helper_failure.index("body pole (joint hinge) at pose")
    for source in HELPER_SOURCE:
        assert source not in model_failure and source not in helper_failure
    # the report of the whole run
    summary = (pytester.path / "report" / "summary.md").read_text()
    for name in ("arm.xml", "cartpole.xml", "mesh_geom.xml"):
        assert name in summary
    assert (pytester.path / "report" / "report.html").is_file()
    result.stdout.fnmatch_lines(["*koenig-check report: *report*"])


def test_without_the_flag_nothing_is_collected(pytester):
    _project(pytester, '"models/arm.xml", "models/cartpole.xml"')
    result = pytester.runpytest_subprocess()
    assert result.ret == pytest.ExitCode.NO_TESTS_COLLECTED
    result.stdout.fnmatch_lines(["*collected 0 items*"])


@pytest.mark.parametrize(
    ("args", "outcomes"),
    [
        ((), {"passed": 2}),  # the project's tests (testpaths) and the model, once
        (("pyproject.toml",), {"passed": 1}),  # only the models
        (("-k", "unit"), {"passed": 1}),  # -k applies to the models too
    ],
)
def test_models_join_the_project_tests_once(pytester, args, outcomes):
    _project(pytester, '"models/arm.xml"', '\n[tool.pytest.ini_options]\ntestpaths = ["tests"]\n')
    pytester.mkdir("tests")
    (pytester.path / "tests" / "test_unit.py").write_text("def test_unit():\n    assert True\n")
    pytester.runpytest_subprocess("--koenig-check", *args).assert_outcomes(**outcomes)


def test_inline_options_reach_the_loader_missing_drake_skips_dynamics_checked_bad_entry_alone(pytester):
    entries = [
        '{ model = "models/link.urdf.xacro", xacro_args = { mass = 0.7 }, floating = true, rtol = 1e-8, poses = 4, '
        "seed = 3 }",
        '{ model = "models/arm.xml", engines = ["mujoco", "pinocchio", "drake"] }',
        '{ model = "models/arm.xml", dynamics = true, repair_inertia = true, seed = 2 }',
        '{ model = "models/arm.xml", rtl = 1e-6 }',
    ]
    _project(pytester, ",\n".join(entries))
    (pytester.path / "conftest.py").write_text(SPIES)
    result = pytester.runpytest_subprocess("--koenig-check", "-v", "-rs")
    result.assert_outcomes(passed=1, skipped=1, failed=2)
    calls = json.loads((pytester.path / "calls.json").read_text())
    # the xacro has no default mass: it expanded with the table's, and every option reached the loader
    result.stdout.fnmatch_lines(["*::link.urdf.xacro ?mass=0.7? (floating) PASSED*"])
    assert ["link.urdf.xacro", True, [["mass", "0.7"]]] in calls["load"]
    assert ["link.urdf.xacro", 1e-8, 4, 3] in calls["compare"]
    # Drake asked for but not installed: skipped with the reason
    result.stdout.fnmatch_lines(["*SKIPPED*pydrake is not installed*koenig-check?drake?*"])
    # dynamics = true: also `koenig-check dynamics`, with the entry's load options
    assert calls["dynamics"] == [["arm.xml", {"seed": 2, "repair_inertia": True}]]
    result.stdout.fnmatch_lines(["*arm.xml#2: koenig-check dynamics would exit 1: exact: M off by 1e-3*"])
    # a bad entry fails alone, naming the key
    result.stdout.fnmatch_lines(["*models[[]3[]]*unknown key(s) ?'rtl'?; did you mean rtol?*"])


def test_report_directory_that_is_a_file_is_a_usage_error(pytester):
    _project(pytester, '"models/arm.xml"')
    (pytester.path / "report").write_text("not a directory")
    result = pytester.runpytest_subprocess("--koenig-check", "--koenig-check-report", "report")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    result.stderr.fnmatch_lines(["*--koenig-check-report*is a file*"])


def test_two_files_with_one_name_are_two_items_labelled_as_one_run_labels_them(pytester):
    for folder in ("left", "right"):
        (pytester.path / folder).mkdir()
        shutil.copy(AGREES, pytester.path / folder / "arm.xml")
    models = ["left/arm.xml", "right/arm.xml", "left/arm.xml"]
    pytester.makepyprojecttoml("[tool.koenig-check]\nmodels = [" + ", ".join(f'"{m}"' for m in models) + "]\n")
    result = pytester.runpytest_subprocess("--koenig-check", "--collect-only", "-q", "pyproject.toml")
    from koenig_check.run.labels import unique_labels

    expected = unique_labels([str(pytester.path / m) for m in models])
    assert len(set(expected)) == 3
    result.stdout.fnmatch_lines([f"pyproject.toml::{label}" for label in expected])
    # the run's report holds each model once, under its item's label (not three models called arm.xml)
    run = pytester.runpytest_subprocess("--koenig-check", "--koenig-check-report", "report", "pyproject.toml")
    run.assert_outcomes(passed=3)
    summary = (pytester.path / "report" / "summary.md").read_text()
    for label in expected:
        assert summary.count(f"\n## {label}\n") == 1, label


#: MuJoCo refuses a negative geom mass: the model cannot be checked at all.
NEGATIVE_MASS = (
    '<mujoco><worldbody><body name="arm"><joint name="hinge" type="hinge"/>'
    '<geom type="sphere" size="0.1" mass="-1"/></body></worldbody></mujoco>'
)


def test_a_model_that_cannot_be_checked_fails_as_the_cli_exits_1(pytester):
    """A model MuJoCo refuses, and one where Drake was asked for and cannot load it (talos_reduced.urdf: a fixed
    joint mimicking a revolute one), make ``koenig-check compare`` exit 1 (tests/diagnosis/test_policy.py): their
    items fail too, with the loader's own reason, never pass as if the model had been checked."""
    from koenig_check.engines.registry import installed

    _project(pytester, '"models/negative_mass.xml", { model = "talos", engines = ["mujoco", "pinocchio", "drake"] }')
    (pytester.path / "models" / "negative_mass.xml").write_text(NEGATIVE_MASS)
    result = pytester.runpytest_subprocess("--koenig-check", "-v", "-rfs")
    text = result.stdout.str()
    assert "::negative_mass.xml FAILED" in text
    refusal = " ".join(_failures(text).split())  # MuJoCo's reason, on the geom it names (tests/test_bad_input.py)
    assert "body 'arm', geom #1 (unnamed, line 1): MuJoCo rejects it (mass, inertia or density are negative" in refusal
    if installed("drake"):
        result.assert_outcomes(failed=2)
        assert "::talos FAILED" in text
        failures = " ".join(_failures(text).split())  # the reason's lines folded at 200 characters, joined
        assert "Drake asked for (--engines) but it could not check the model" in failures
        assert "Joint 'gripper_left_inner_double_joint' which has 0 DOF cannot mimic" in failures
    else:
        result.assert_outcomes(failed=1, skipped=1)


#: A URDF whose base link breaks A + B >= C: MuJoCo refuses it (issue 28: its own words in the failure).
ABC_URDF = """<robot name="abc">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"""


def test_a_refused_model_gives_the_engines_own_words(pytester):
    """One message per failed model: its reason first, then MuJoCo's words and the hint, indented, never cut."""
    import mujoco

    (pytester.path / "abc.urdf").write_text(ABC_URDF)
    with pytest.raises(ValueError) as info:  # MuJoCo's own refusal, read from MuJoCo
        mujoco.MjModel.from_xml_path(str(pytester.path / "abc.urdf"))
    words = [line.strip() for line in str(info.value).splitlines() if line.strip()]
    pytester.makepyprojecttoml('[tool.koenig-check]\nmodels = ["abc.urdf", { model = "abc.urdf", floating = true }]\n')
    result = pytester.runpytest_subprocess("--koenig-check", "-p", "no:cacheprovider")
    assert result.ret == 1
    text = result.stdout.str()
    for word in words:
        assert text.count(word) >= 2, text  # fixed and floating, each with MuJoCo's words
    assert "failed: link 'base': MuJoCo rejects its inertia" in text and "hint: --repair-inertia" in text
    assert "…" not in text
