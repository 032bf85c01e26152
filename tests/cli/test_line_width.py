"""Every line the command line prints fits 200 characters (issue 21), on the models that disagree or are refused.

Each command runs on the disagreeing and refused models of the test corpus, copied under a directory nested to
about 150 characters, and on dm_control and example-robot-data models known to disagree or to be refused: every
line of stdout and stderr is at most 200 characters.  A one-line error stays one line (shorter, never folded).
The only line allowed to be longer is a single token the user typed that is itself longer (a path of more than
200 characters), alone on its line.  The pytest plugin's failure text is held to the same width.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from koenig_check import cli
from koenig_check.line_width import LINE_LIMIT
from process_memory import release_memory

ROOT = Path(__file__).resolve().parents[2]
TESTS = ROOT / "tests"
#: The disagreeing and refused models of the test corpus (relative to tests/).
CORPUS = [
    *(f"models/causes/{p.name}" for p in sorted((TESTS / "models" / "causes").glob("*.xml"))),
    *(f"models/tiebreak/{p.name}" for p in sorted((TESTS / "models" / "tiebreak").iterdir())),
    "engines/models/repair_needed.urdf",
    "engines/models/massless.urdf",
    "engines/models/mimic_chain.urdf",
    "engines/models/hfield.xml",
]
#: Files the corpus models include or read, copied next to them.
COMPANIONS = {"models/causes": ["*.xml"], "engines/models": ["*.xml", "*.urdf"]}


def _long_directory(base: Path, length: int) -> Path:
    """A directory under ``base`` whose path is ``length`` characters long."""
    deep = base
    while len(str(deep)) < length:
        deep = deep / "a_directory_with_a_rather_long_name"[: length - len(str(deep)) - 1]
    deep.mkdir(parents=True)
    return deep


@pytest.fixture(scope="module")
def deep(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The corpus copied under a directory nested to about 150 characters."""
    deep = _long_directory(tmp_path_factory.mktemp("lines"), 150)
    for rel in CORPUS:
        target = deep / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(TESTS / rel, target)
    for folder, patterns in COMPANIONS.items():
        for pattern in patterns:
            for p in (TESTS / folder).glob(pattern):
                shutil.copy(p, deep / folder / p.name)
    (deep / "out").mkdir()
    return deep


def over_width(text: str, given: tuple[str, ...] = ()) -> list[str]:
    """The lines of ``text`` over 200 characters, except one that is only a token the user gave, itself longer."""
    return [
        line
        for line in text.splitlines()
        if len(line) > LINE_LIMIT and not (line.strip() in given and len(line.strip()) > LINE_LIMIT - 10)
    ]


def run(capfd: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    """Run the command line in this process; its exit status, stdout and stderr (file descriptors included)."""
    capfd.readouterr()
    try:
        status = cli.main(list(argv))
    except SystemExit as exit_:
        status = int(exit_.code or 0)
    out, err = capfd.readouterr()
    return status, out, err


def assert_fits(capfd: pytest.CaptureFixture[str], *argv: str, given: tuple[str, ...] = ()) -> tuple[int, str, str]:
    """Run a command and assert every line it prints fits 200 characters; return what it printed."""
    status, out, err = run(capfd, *argv)
    long = over_width(out, given) + over_width(err, given)
    assert not long, f"{' '.join(argv)}: {len(long)} line(s) over {LINE_LIMIT}: " + " | ".join(
        f"{len(line)}: {line}" for line in long
    )
    return status, out, err


def assert_one_message(err: str) -> None:
    """One message per failure: a first line ``koenig-check: ...``, then only indented lines (issue 28's rule)."""
    lines = err.strip().splitlines()
    assert lines and lines[0].startswith("koenig-check: "), err
    assert all(line.startswith("    ") or line.startswith("koenig-check: ") for line in lines), err
    assert sum(line.startswith("koenig-check: ") for line in lines) == 1, err
    assert "…" not in err.replace(lines[0], ""), err  # the lines after the first are never cut


@pytest.mark.parametrize("rel", CORPUS)
def test_every_command_fits_on_the_corpus(deep: Path, rel: str, capfd: pytest.CaptureFixture[str]) -> None:
    model = str(deep / rel)
    status, _, err = assert_fits(capfd, "compare", model, "--poses", "2", "--quiet")
    if status == 1:
        assert_one_message(err)  # the reason: one sentence on one line, then the whole of it indented
    status, _, err = assert_fits(capfd, "parity", model)
    if status == 1:
        assert_one_message(err)
    stem = Path(rel).stem
    assert_fits(capfd, "export", model, "--to", "urdf", "--out", str(deep / "out" / f"{stem}.urdf"), "--poses", "2")
    assert_fits(capfd, "export", model, "--to", "mjcf", "--out", str(deep / "out" / f"{stem}.xml"), "--poses", "2")


@pytest.mark.parametrize("rel", ["models/tiebreak/all_differ.xml", "models/causes/class_mass.xml"])
def test_dynamics_table_fits(deep: Path, rel: str, capfd: pytest.CaptureFixture[str]) -> None:
    status, out, _ = assert_fits(capfd, "dynamics", str(deep / rel), "--poses", "2")
    assert status == 1 and "worst entry" in out


def _dm_control(rel: str) -> str:
    dm_control = pytest.importorskip("dm_control")
    return str(Path(dm_control.__file__).parent / rel)


#: Real files: (command line, its exit status).  cartpole and bolt disagree (bolt's feet: fusestatic),
#: quadruped is refused by Pinocchio (height field), alex_psyonic_hands by MuJoCo (inertia), hopper,
#: ball_in_cup and rodent (12 bodies) cannot be written as URDF (several joints in one body).
REAL = {
    "cartpole compare": (["compare", "dm:suite/cartpole.xml", "--poses", "2", "--quiet"], 1),
    "cartpole parity": (["parity", "dm:suite/cartpole.xml"], 1),
    "cartpole dynamics": (["dynamics", "dm:suite/cartpole.xml", "--poses", "2"], 1),
    "quadruped parity": (["parity", "dm:suite/quadruped.xml"], 1),
    "hopper to urdf": (["export", "dm:suite/hopper.xml", "--to", "urdf", "--out", "OUT/hopper.urdf"], 1),
    "ball_in_cup to urdf": (["export", "dm:suite/ball_in_cup.xml", "--to", "urdf", "--out", "OUT/cup.urdf"], 1),
    "rodent to urdf": (
        ["export", "dm:locomotion/walkers/assets/rodent.xml", "--to", "urdf", "--out", "OUT/rodent.urdf"],
        1,
    ),
    "bolt parity": (["parity", "bolt"], 1),
    "bolt dynamics": (["dynamics", "bolt", "--poses", "2"], 1),
    "alex_psyonic_hands compare": (["compare", "alex_psyonic_hands", "--poses", "2", "--quiet"], 1),
    "cheetah compare with drake": (
        ["compare", "dm:suite/cheetah.xml", "--engines", "mujoco,pinocchio,drake", "--poses", "2", "--quiet"],
        1,
    ),
    "cheetah parity": (["parity", "dm:suite/cheetah.xml"], 1),
}


@pytest.mark.parametrize("case", REAL.values(), ids=REAL.keys())
def test_every_command_fits_on_real_files(deep: Path, case: tuple[list[str], int], capfd) -> None:
    argv, expected = case
    argv = [_dm_control(a[3:]) if a.startswith("dm:") else a.replace("OUT", str(deep / "out")) for a in argv]
    status, _, err = assert_fits(capfd, *argv)
    assert status == expected, err
    release_memory()


def test_export_check_only_of_a_corrupted_export_fits(deep: Path, capfd: pytest.CaptureFixture[str]) -> None:
    original = deep / "models" / "tiebreak" / "hinge_ref.xml"
    exported = deep / "out" / "hinge_ref_check.urdf"
    assert run(capfd, "export", str(original), "--to", "urdf", "--out", str(exported))[0] == 0
    text = exported.read_text()
    exported.write_text(text.replace('<mass value="', '<mass value="1', 2))  # two links 10x heavier or more
    status, out, _ = assert_fits(capfd, "export", "--check-only", str(original), str(exported))
    assert status == 1 and "not equivalent" in out


#: Models ``models --check`` refuses with a long reason: MuJoCo's inertia refusals with their moments (up to 477
#: characters), Pinocchio's parser naming the file's whole path.
REFUSED_BY_NAME = ["alex_psyonic_hands", "anymal-kinova", "b1", "human", "ur3"]


def test_models_check_fits(monkeypatch: pytest.MonkeyPatch, capfd: pytest.CaptureFixture[str]) -> None:
    import koenig_check.sources.model_names as names

    every = names.model_names()
    monkeypatch.setattr(names, "model_names", lambda: [e for e in every if e.name in REFUSED_BY_NAME])
    status, out, _ = assert_fits(capfd, "models", "--check")
    assert status == 0
    refusals = [line.strip() for line in out.splitlines() if line.strip().startswith("no: ")]
    assert len(refusals) == len(REFUSED_BY_NAME), out
    assert any("link 'LeftPsyonicAbilityBaseLink': MuJoCo rejects its inertia" in r for r in refusals), out
    assert not any("/" in r for r in refusals), out  # the row names the model, its reason not the file's path


def test_models_and_selfcheck_fit(capfd: pytest.CaptureFixture[str]) -> None:
    assert assert_fits(capfd, "models")[0] == 0
    assert assert_fits(capfd, "selfcheck")[0] == 0


@pytest.mark.parametrize("command", ["compare", "parity", "models", "selfcheck", "dynamics", "export", "demo"])
def test_help_fits_a_wide_terminal(command: str, monkeypatch: pytest.MonkeyPatch, capfd) -> None:
    monkeypatch.setenv("COLUMNS", "400")  # argparse wraps at the terminal's width: at most 200 here too
    status, out, _ = assert_fits(capfd, command, "--help")
    assert status == 0 and out.startswith(f"usage: koenig-check {command}")


USAGE = {
    "misspelt formula": ["compare", "gimbal.xml", "--formulas", "alyushin_pole:paper:eulerxyz"],
    "unknown formula": ["compare", "gimbal.xml", "--formulas", "koenig"],
    "misspelt option": ["compare", "gimbal.xml", "--floting"],
    "zero poses": ["dynamics", "gimbal.xml", "--poses", "0"],
    "export into a missing directory": ["export", "gimbal.xml", "--to", "urdf", "--out", "DEEP/none/gimbal.urdf"],
}


@pytest.mark.parametrize("argv", USAGE.values(), ids=USAGE.keys())
def test_usage_errors_are_two_short_lines(deep: Path, argv: list[str], capfd: pytest.CaptureFixture[str]) -> None:
    status, out, err = assert_fits(capfd, *[a.replace("DEEP", str(deep)) for a in argv])
    assert status == 2 and not out and len(err.strip().splitlines()) == 2, err


def test_the_closest_formula_is_named_and_where_all_are_listed(capfd: pytest.CaptureFixture[str]) -> None:
    from koenig_check.formulas import FORMULAS

    _, _, err = run(capfd, "compare", "gimbal.xml", "--formulas", "koenig")
    line = err.strip().splitlines()[1]
    assert "did you mean 'koenig_world'?" in line and "koenig-check compare --help" in line
    assert sum(name in line for name in FORMULAS) == 1  # the closest, not the whole list
    help_text = run(capfd, "compare", "--help")[1]
    assert all(name in help_text for name in FORMULAS)  # every valid name is where the error says


def _bad_input(deep: Path) -> dict[str, Path]:
    """Files a user gets wrong: missing, malformed, a missing mesh, a non-physical inertia."""
    missing_mesh = deep / "missing_mesh.xml"
    missing_mesh.write_text(
        '<mujoco><asset><mesh name="shell" file="nowhere/shell.stl"/></asset><worldbody><body name="arm">'
        '<joint name="hinge" axis="0 0 1"/><geom type="mesh" mesh="shell"/></body></worldbody></mujoco>'
    )
    malformed = deep / "malformed.xml"
    malformed.write_text("<mujoco><worldbody><body name='a'>")
    return {
        "missing file": deep / "nowhere" / "robot.urdf",
        "malformed XML": malformed,
        "missing mesh": missing_mesh,
        "non-physical inertia": deep / "models" / "tiebreak" / "unbalanced_inertia.urdf",
        "not positive definite": deep / "engines" / "models" / "repair_needed.urdf",
    }


@pytest.mark.parametrize(
    "case", ["missing file", "malformed XML", "missing mesh", "non-physical inertia", "not positive definite"]
)
@pytest.mark.parametrize("command", ["compare", "parity", "dynamics", "export"])
def test_bad_input_is_one_short_line_naming_the_file(deep: Path, case: str, command: str, capfd) -> None:
    path = _bad_input(deep)[case]
    argv = [command, str(path), "--poses", "2"] if command in ("compare", "dynamics") else [command, str(path)]
    if command == "export":
        argv += ["--to", "mjcf", "--out", str(deep / "out" / f"bad_{path.stem}.xml")]
    status, _, err = assert_fits(capfd, *argv)
    assert status == 1
    lines = err.strip().splitlines()
    if command == "export" and not lines:  # export prints its refusal on stdout
        return
    assert_one_message(err)  # one message: its first line names the file, the rest is indented
    assert path.name in lines[0], err


def test_a_path_longer_than_a_line_is_the_only_exception(tmp_path: Path, capfd: pytest.CaptureFixture[str]) -> None:
    """A path over 200 characters the user typed is printed whole, alone on its line; errors name its file."""
    deeper = _long_directory(tmp_path, 220)
    model = deeper / "class_mass.xml"
    shutil.copy(TESTS / "models" / "causes" / "class_mass.xml", model)
    status, out, _ = assert_fits(capfd, "parity", str(model), given=(str(model),))
    assert status == 1 and str(model) in [line.strip() for line in out.splitlines()]  # whole, alone on its line
    broken = deeper / "broken.urdf"
    broken.write_text("<robot><link name='a'>")
    status, _, err = assert_fits(capfd, "parity", str(broken))
    assert status == 1 and "broken.urdf" in err.strip().splitlines()[0]
    assert_one_message(err)


def test_a_fresh_process_prints_no_long_warning(deep: Path) -> None:
    """As a user runs it: MuJoCo's compiler warnings are findings, not Python warnings printed with a path."""
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "parity", str(deep / "models" / "tiebreak" / "all_differ.xml")],
        capture_output=True,
        text=True,
        check=False,
        timeout=300,
    )
    assert proc.returncode == 1
    assert not over_width(proc.stdout) and not over_width(proc.stderr), proc.stderr
    assert "Warning" not in proc.stderr


PLUGIN_TEST = """
from koenig_check.testing import assert_energy_parity


def test_all_differ():
    assert_energy_parity("models/all_differ.xml")
"""


def test_pytest_failure_text_fits(pytester: pytest.Pytester) -> None:
    """The plugin's failures and assert_energy_parity's, as pytest prints them (``E       `` before each line)."""
    models = pytester.path / "models"
    models.mkdir()
    for rel in ("models/tiebreak/all_differ.xml", "models/causes/class_mass.xml", "engines/models/repair_needed.urdf"):
        shutil.copy(TESTS / rel, models / Path(rel).name)
    pytester.makepyprojecttoml(
        '[tool.koenig-check]\nmodels = ["models/all_differ.xml", "models/class_mass.xml", "models/repair_needed.urdf"]'
    )
    pytester.makepyfile(test_parity=PLUGIN_TEST)
    result = pytester.runpytest_subprocess("--koenig-check", "-p", "no:cacheprovider")
    text = result.stdout.str()
    failures = text[text.index("= FAILURES =") : text.index("short test summary")]
    assert "root cause:" in failures and "repair_needed.urdf: failed" in failures
    assert failures.count("AssertionError") >= 1
    assert not over_width(failures)


LOAD_FAILURE_TEST = """
from koenig_check.testing import assert_energy_parity


def test_refused():
    assert_energy_parity({path!r})
"""


@pytest.mark.parametrize("rel", ["suite/finger.xml"])
def test_pytest_load_failure_fits(pytester: pytest.Pytester, rel: str) -> None:
    """A model an engine refuses (finger: Pinocchio reads only its first root body): folded as energy failures are."""
    path = _dm_control(rel)
    pytester.makepyfile(test_refused=LOAD_FAILURE_TEST.format(path=path))
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    text = result.stdout.str()
    failures = text[text.index("= FAILURES =") : text.index("short test summary")]
    assert "AssertionError" in failures and "finger.xml" in failures and "root cause" in failures
    assert not over_width(failures), [line for line in failures.splitlines() if len(line) > LINE_LIMIT]
