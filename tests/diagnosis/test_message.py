"""One message per failure (issue 28, items 1 and 6): a first line of at most 200 characters naming the model and
why, then indented lines with the rest, the engine's own words whole, and the hint; never cut with "…".

The engine's own words are read here from the engine itself (MuJoCo's, Pinocchio's, Drake's exception on the same
file), never from koenig-check, and looked for on the terminal of every refusal the suite provokes.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

from koenig_check.diagnosis.message import detail_lines, first_and_rest
from koenig_check.exceptions import ModelLoadError, quote_engine
from koenig_check.line_width import LINE_LIMIT

TESTS = Path(__file__).resolve().parents[1]
ENGINE_MODELS = TESTS / "engines" / "models"

#: A URDF whose base link breaks A + B >= C (fixed: welded to the world; --floating: it moves).
ABC = """<robot name="abc">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"""


def _cli(*argv: str) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "koenig_check.cli", *argv]
    return subprocess.run(command, capture_output=True, text=True, timeout=600)


def _mujoco_words(path: Path) -> list[str]:
    """MuJoCo's own refusal of the file, line by line (MuJoCo called directly)."""
    with pytest.raises(ValueError) as info:
        mujoco.MjModel.from_xml_path(str(path))
    return [line.strip() for line in str(info.value).splitlines() if line.strip()]


def _pinocchio_words(path: Path) -> list[str]:
    """Pinocchio's own refusal of the file, its reason lines (its C++ source location left out)."""
    build = pin.buildModelFromUrdf if path.suffix == ".urdf" else pin.buildModelFromMJCF
    with pytest.raises((ValueError, RuntimeError)) as info:  # Pinocchio raises either
        build(str(path))
    lines = [line.strip() for line in str(info.value).splitlines() if line.strip()]
    location = ("From file:", "in function:", "at line:", "message:")
    return [line.replace(str(path), path.name) for line in lines if not line.startswith(location)]


def assert_one_message(text: str, prefix: str = "koenig-check: ") -> tuple[str, list[str]]:
    """One message: a first line of at most 200 characters, then indented lines only, none of them cut."""
    first, *rest = text.strip("\n").splitlines()
    assert first.startswith(prefix) and len(first) <= LINE_LIMIT, text
    assert all(line.startswith("    ") for line in rest), text
    assert all(len(line) <= LINE_LIMIT or " " not in line.strip() for line in rest), text
    assert not any(line.rstrip().endswith("…") for line in [first, *rest]), text
    return first, rest


def _flat(text: str) -> str:
    return " ".join(text.split())


# ---------------------------------------------------------------------------------- the A + B >= C URDF


@pytest.mark.parametrize("floating", [False, True], ids=["fixed", "floating"])
@pytest.mark.parametrize("command", ["compare", "parity"])
def test_mujocos_words_with_and_without_floating(tmp_path: Path, command: str, floating: bool) -> None:
    """The same refusal says MuJoCo's words whole with a fixed base and with --floating (main: only without)."""
    path = tmp_path / "abc.urdf"
    path.write_text(ABC)
    words = _mujoco_words(path)
    assert words[0] == "Error: inertia must satisfy A + B >= C; use 'balanceinertia' to fix"  # MuJoCo 4.0's text
    argv = [command, str(path), *(["--poses", "1"] if command == "compare" else []), *(["--floating"] * floating)]
    proc = _cli(*argv)
    assert proc.returncode == 1
    first, rest = assert_one_message(proc.stderr)
    assert "abc.urdf" in first and "link 'base'" in first and "MuJoCo rejects its inertia" in first
    said = [line.strip() for line in rest]
    assert f"MuJoCo says: {words[0]}" in said and all(w in said for w in words[1:]), proc.stderr
    assert any(line.startswith("hint: --repair-inertia") for line in said)  # the paraphrase's hint kept


def test_assert_energy_parity_gives_mujocos_words(tmp_path: Path) -> None:
    from koenig_check.testing import assert_energy_parity

    path = tmp_path / "abc.urdf"
    path.write_text(ABC)
    for floating in (False, True):
        with pytest.raises(AssertionError) as info:
            assert_energy_parity(path, floating=floating)
        _, rest = assert_one_message(str(info.value), prefix=str(path))
        assert any(line.strip() == f"MuJoCo says: {_mujoco_words(path)[0]}" for line in rest)


# ------------------------------------------------------- every engine refusal the suite provokes, on the terminal

GEOM = (
    '<mujoco><worldbody><body name="arm"><joint name="hinge" type="hinge"/>'
    '<geom name="rod" type="sphere" size="0.1" mass="-1"/></body></worldbody></mujoco>'
)
BAD_JOINT = "<mujoco><worldbody><body name='b'><joint type='nonsense'/></body></worldbody></mujoco>"

#: (id, file or text to write, engine): the refusals of tests/test_bad_input.py, tests/engines/*/test_*_load_errors.py,
#: tests/cli/test_line_width.py's bad input and tests/engines/models.
REFUSALS = [
    ("mujoco-unbalanced-inertia", TESTS / "models" / "tiebreak" / "unbalanced_inertia.urdf", "mujoco"),
    ("mujoco-not-positive-definite", ENGINE_MODELS / "repair_needed.urdf", "mujoco"),
    ("mujoco-negative-geom-mass", GEOM, "mujoco"),
    ("mujoco-unknown-joint-type", BAD_JOINT, "mujoco"),
    ("pinocchio-hfield", ENGINE_MODELS / "hfield.xml", "pinocchio"),
    ("pinocchio-include-in-worldbody", ENGINE_MODELS / "include_worldbody.xml", "pinocchio"),
    ("pinocchio-spherical-joint", ENGINE_MODELS / "spherical_capsules.urdf", "pinocchio"),
]


@pytest.mark.parametrize(("path", "engine"), [r[1:] for r in REFUSALS], ids=[r[0] for r in REFUSALS])
@pytest.mark.parametrize("command", ["compare", "parity"])
def test_the_engines_own_words_are_on_the_terminal(tmp_path: Path, path: Path | str, engine: str, command: str) -> None:
    if isinstance(path, str):
        written = tmp_path / "refused.xml"
        written.write_text(path)
        path = written
    words = _mujoco_words(path) if engine == "mujoco" else _pinocchio_words(path)
    proc = _cli(command, str(path), *(["--poses", "1"] if command == "compare" else []))
    assert proc.returncode == 1
    first, rest = assert_one_message(proc.stderr)
    assert path.name in first
    label = {"mujoco": "MuJoCo", "pinocchio": "Pinocchio"}[engine]
    said = _flat(" ".join(rest)).replace(str(path), path.name)
    assert f"{label} says:" in said, proc.stderr
    assert all(_flat(w) in said for w in words), (words, proc.stderr)


def test_drakes_own_words_are_on_the_terminal() -> None:
    """Drake named with --engines on talos (a joint of 0 dof with a mimic): Drake's own text, whole, on stderr."""
    pytest.importorskip("pydrake")
    from koenig_check.engines import load_model
    from koenig_check.engines.drake.building import load_drake_engine
    from koenig_check.engines.drake.loader import DrakeLoadError

    pair = load_model("talos")
    with pytest.raises(DrakeLoadError) as info:
        load_drake_engine(pair.source, pair.mujoco.model)
    drake = info.value.__cause__  # the exception Drake itself raised
    assert isinstance(drake, RuntimeError)
    drake_words = _flat(str(drake)).split("error: ", 1)[-1]  # after the file and line Drake names
    assert "which has 0 DOF cannot mimic joint" in drake_words
    proc = _cli("compare", "talos", "--engines", "mujoco,pinocchio,drake", "--poses", "1", "--formulas", "exact")
    assert proc.returncode == 1
    first, _ = assert_one_message(proc.stderr)
    assert first.startswith("koenig-check: talos: ")
    assert drake_words in _flat(proc.stderr), (drake_words, proc.stderr)


# ------------------------------------------------------------------------------------------------ the parts


def test_detail_lines_give_the_engine_text_as_written_and_never_cut() -> None:
    long_words = "word " * 80
    err = ModelLoadError(f"model.xml: refused ({long_words.strip()}); what to do")
    try:
        raise err from ValueError(f"Error: first line\n  {long_words}\nElement name 'b', id 1")
    except ModelLoadError as raised:
        quote_engine(raised, "MuJoCo")
        lines = detail_lines(raised, first="model.xml: refused; what to do")
    text = "\n".join(lines)
    assert lines[0].startswith("    MuJoCo says: Error: first line")
    assert _flat(long_words) in _flat(text) and "Element name 'b', id 1" in text
    assert all(len(line) <= LINE_LIMIT for line in lines) and "…" not in text
    assert "details:" not in text  # what the engine says is not said twice


def test_a_quoted_error_keeps_its_own_quote() -> None:
    err = ModelLoadError("m.xml: refused")
    quote_engine(err, "Pinocchio", "its own words")
    quote_engine(err, "MuJoCo", "something else")
    assert err.engine_texts == (("Pinocchio", "its own words"),)
    plain = ModelLoadError("m.xml: ours")  # raised from no engine: nothing quoted
    quote_engine(plain, "MuJoCo")
    assert plain.engine_texts == ()


def test_first_and_rest_splits_at_whole_parts() -> None:
    parts = [f"part {k} " + "x" * 40 for k in range(8)]
    first, rest = first_and_rest("; ".join(parts), 120)
    assert first == "; ".join(parts[:2]) and len(first) <= 120
    assert _flat(" ".join(rest)) == _flat("details: " + "; ".join(parts[2:]))


def test_first_and_rest_splits_a_part_too_long_alone_at_a_clause() -> None:
    """dynamics on all_differ.xml: one part of 205 characters; the first line ends at a clause, the rest below."""
    text = "model.xml: exact disagrees by lagrange: M " + "y" * 90 + " off by 7.37 relative at pose 0, worst entry a,b"
    first, rest = first_and_rest(text, 170)
    assert first == text[: text.index(", worst")] and len(first) <= 170
    assert rest == ["    details: worst entry a,b"]
