"""The one-line reasons on real files (example-robot-data, dm_control): one complete sentence naming the root causes.

Each expectation comes from the file itself or from MuJoCo's own refusal (read here with ElementTree, numpy and
``mujoco.MjModel``), never from the reason code: the link MuJoCo refuses, the root bodies that carry joints, the
links whose inertia breaks the triangle inequality, the massless feet with an inertia, a compiler option.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np
import pytest

import koenig_check
from koenig_check.causes import cause as catalogued
from koenig_check.cli import main
from koenig_check.diagnosis.reason import REASON_WIDTH
from koenig_check.engines import load_model
from koenig_check.exceptions import KoenigCheckError
from koenig_check.report.terminal import WIDTH, terminal_table
from koenig_check.testing import assert_energy_parity

dm_control = pytest.importorskip("dm_control")
SUITE = Path(dm_control.__file__).parent / "suite"
KINOVA = Path(dm_control.__file__).parent / "third_party" / "kinova"
ONE = dict(n_poses=2, formulas=["exact"])


def _open_brackets(text: str) -> bool:
    depth = 0
    for ch in text:
        depth += {"(": 1, "[": 1, ")": -1, "]": -1}.get(ch, 0)
    return depth != 0


def _one_sentence(line: str) -> None:
    """At most 200 characters with ``koenig-check: ``, nothing cut, no bracket left open, no Python repr."""
    assert len(line) <= REASON_WIDTH and "\n" not in line, line
    assert "…" not in line and not _open_brackets(line), line
    assert not re.search(r"[\[(]'[^']*',|\[\]|\(\)", line), line  # no list or tuple of names as Python prints it


def _file_of(check: koenig_check.CrossCheck) -> str:
    """The resolved file a refusal names in its whole message."""
    return re.search(r"(/\S+\.(?:urdf|xml))", check.failures[0][1]).group(1)


def _mujoco_refuses(path: str) -> str:
    """The element MuJoCo itself names when it refuses the file."""
    with pytest.raises(ValueError) as info:
        mujoco.MjModel.from_xml_path(path)
    return re.search(r"Element name '([^']+)'", str(info.value)).group(1)


def _first_lines(err: str) -> list[str]:
    """The first line of each message on stderr (the lines after it, indented, give the rest: issue 28)."""
    return [line for line in err.strip().splitlines() if line.startswith("koenig-check: ")]


# ----------------------------------------------------------------------------------------- 1: whole parts
@pytest.mark.parametrize("name", ["anymal_b_simple/anymal", "anymal_c_simple/anymal", "go1"])
def test_a_model_named_by_name_gives_the_link_and_what_loads_it_not_its_resolved_path(
    name: str, capsys: pytest.CaptureFixture[str]
) -> None:
    check = koenig_check.compare(name, **ONE)
    path = _file_of(check)
    (line,) = check.reasons()
    assert line.startswith(f"{name}: link '{_mujoco_refuses(path)}': MuJoCo rejects its inertia"), line
    assert path not in line and "site-packages" not in line  # the label names the model
    assert line.endswith("--repair-inertia loads it with the smallest change MuJoCo accepts"), line
    _one_sentence(line)
    assert main(["compare", name, "--poses", "2", "--formulas", "exact"]) == 1
    assert _first_lines(capsys.readouterr().err)[-1] == f"koenig-check: {line}"


def test_an_engines_verbatim_detail_goes_whole_and_the_hint_stays() -> None:
    check = koenig_check.compare("romeo", **ONE)
    root = ET.parse(_file_of(check)).getroot()
    moving = {j.find("child").get("link") for j in root.iter("joint") if j.get("type") != "fixed"}
    masses = {
        link.get("name"): float(link.find("inertial/mass").get("value"))
        if link.find("inertial/mass") is not None
        else 0
        for link in root.iter("link")
    }
    massless = {name for name in moving if masses.get(name, 0.0) <= 1e-15}
    (line,) = check.reasons()
    named = re.match(r"romeo: link '([^']+)': MuJoCo rejects a moving body without mass or inertia; ", line)
    assert named and named.group(1) in massless, line
    assert "Element name" not in line and "--repair-inertia loads it" in line  # MuJoCo's detail whole out, hint in
    _one_sentence(line)


def _root_bodies(path: Path) -> tuple[list[str], dict[str, list[str]]]:
    """The root bodies under <worldbody> after the first, and the joints under each (the file read as written)."""
    world = ET.parse(path).getroot().find("worldbody")
    bodies = world.findall("body")
    joints = {b.get("name"): [j.get("name") for j in b.iter("joint")] for b in bodies[1:]}
    return [b.get("name") for b in bodies[1:]], joints


@pytest.mark.parametrize("name", ["finger.xml", "manipulator.xml", "stacker.xml"])
def test_root_bodies_pinocchio_does_not_read_are_one_cause_naming_the_bodies_with_joints(
    name: str, capsys: pytest.CaptureFixture[str]
) -> None:
    path = SUITE / name
    roots, joints = _root_bodies(path)
    moving = [b for b in roots if joints[b]]
    still = [b for b in roots if not joints[b]]  # welded to the world: they cannot cause a joint mismatch
    check = koenig_check.compare(path, **ONE)
    (line,) = check.reasons()
    _one_sentence(line)
    with pytest.raises(KoenigCheckError) as refused:
        load_model(path)
    named = {c.element.removeprefix("body ") for c in refused.value.causes if c.cause == "pinocchio.mjcf.root-bodies"}
    assert named == set(roots), named  # one finding of the cause per root body after the first
    tag = "body" if len(moving) == 1 else "bodies"
    shown = ", ".join(moving[:4]) + (f" (+{len(moving) - 4} more)" if len(moving) > 4 else "")
    cause = f"root cause: {tag} {shown}: {catalogued('pinocchio.mjcf.root-bodies').brief}"
    assert cause in line and line.count("root cause") == 1 and "more root cause" not in line, line
    assert not any(re.search(rf"\b{b}\b", line) for b in still), line
    lost = [j for b in moving for j in joints[b]]
    if len(lost) <= 6:  # the joints it loses are named (in the message or the cause)
        assert all(j in line for j in lost), line
    main(["compare", str(path), "--poses", "2", "--formulas", "exact"])
    err = _first_lines(capsys.readouterr().err)[-1]
    assert err == f"koenig-check: {line}" and len(err) <= 200


def test_a_known_limitation_keeps_what_to_do() -> None:
    check = koenig_check.compare(SUITE / "quadruped.xml", **ONE)
    (line,) = check.reasons()
    assert "hfields are not supported yet" in line and "--pinocchio-model" in line, line
    _one_sentence(line)


@pytest.mark.parametrize("suffix", [".urdf", ".xml"])
def test_a_model_without_a_joint_says_so_once_with_the_option(tmp_path: Path, suffix: str) -> None:
    path = tmp_path / f"nojoint{suffix}"
    body = '<body name="a"><geom size="0.1"/></body>'
    text = (
        '<robot name="r"><link name="a"/></robot>'
        if suffix == ".urdf"
        else f"<mujoco><worldbody>{body}</worldbody></mujoco>"
    )
    path.write_text(text)
    check = koenig_check.compare(path, **ONE)
    (line,) = check.reasons()
    assert line.count("nothing moves") == 1 and line.count("no joint") == 1, line
    assert "--floating" in line and line.startswith(f"{path.name}: nothing moves"), line
    _one_sentence(line)


# --------------------------------------------------------------------------------- 2: counted root causes
def _unbalanced_links(path: str) -> list[str]:
    """Links whose principal moments break A + B >= C, in file order (numpy on the file's inertia)."""
    out = []
    for link in ET.parse(path).getroot().iter("link"):
        i = link.find("inertial/inertia")
        if i is None:
            continue
        v = {k: float(i.get(k, 0)) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
        tensor = np.array(
            [[v["ixx"], v["ixy"], v["ixz"]], [v["ixy"], v["iyy"], v["iyz"]], [v["ixz"], v["iyz"], v["izz"]]]
        )
        a, b, c = np.linalg.eigvalsh(tensor)
        if a + b < c:
            out.append(link.get("name"))
    return out


def _more(line: str) -> int:
    found = re.search(r"\band (\d+) more (?:root )?causes?\b", line)  # root causes or other causes
    return int(found.group(1)) if found else 0


def test_a_repair_of_several_links_is_one_root_cause_naming_them() -> None:
    refused = koenig_check.compare("allegro_right_hand", **ONE)
    links = _unbalanced_links(_file_of(refused))
    assert len(links) == 4
    check = koenig_check.compare("allegro_right_hand", repair_inertia=True, **ONE)
    (line,) = check.reasons()
    assert f"root cause: links {', '.join(links)}: inertia changed so that MuJoCo accepts it" in line, line
    engines = {"drake"} & {f.engine for f in check.comparisons[0].findings}
    assert _more(line) <= len(engines) and " and 7 more" not in line, line  # a third engine's parser at most
    _one_sentence(line)
    with pytest.raises(AssertionError) as info:
        assert_energy_parity("allegro_right_hand", repair_inertia=True, n_poses=3)
    text = str(info.value)
    causes = [text[m.start() :] for m in re.finditer("root cause:", text)]  # wherever its line starts
    assert causes and not any(c.startswith("root cause: and") for c in causes) and "finding(s)" not in text
    repairs = [c for c in causes if "inertia changed so that MuJoCo accepts it" in c]
    assert len(repairs) == 1 and all(link in repairs[0] for link in links), text  # said once, naming every link


def test_a_file_with_one_cause_counts_no_more() -> None:
    path = SUITE / "cheetah.xml"
    total = ET.parse(path).getroot().find("compiler").get("settotalmass")
    assert total is not None
    check = koenig_check.compare(path, **ONE)
    line = check.reason()
    found = [f for f in check.comparisons[0].findings if f.cause == "pinocchio.mjcf.settotalmass"]
    # the id's engine, which ignores the option; Drake's, which ignores it too, is its own
    (option,) = [f for f in found if f.engine == "pinocchio"]
    assert option.values["mujoco"] == pytest.approx(float(total), rel=1e-12)  # MuJoCo's total mass: the file's
    assert f"root cause: compiler settotalmass: {catalogued('pinocchio.mjcf.settotalmass').brief}" in line, line
    assert "more" not in line and not line.endswith(" and 2 more"), line
    _one_sentence(line)


def test_two_massless_feet_are_one_cause() -> None:
    from koenig_check.sources.catalogue import resolve_model

    refused = koenig_check.compare("bolt", **ONE)
    root = ET.parse(resolve_model("bolt").path).getroot()  # the file as written
    feet = []
    for link in root.iter("link"):
        mass, inertia = link.find("inertial/mass"), link.find("inertial/inertia")
        if mass is not None and float(mass.get("value")) == 0 and inertia is not None:
            if any(float(inertia.get(k, 0)) for k in ("ixx", "iyy", "izz")):
                feet.append(link.get("name"))
    assert len(feet) == 2
    line = refused.reason()
    assert f"root cause: links {', '.join(feet)}: {catalogued('mujoco.any.fusestatic-massless-inertia').brief}" in line
    assert {
        f.element for f in refused.comparisons[0].findings if f.cause == "mujoco.any.fusestatic-massless-inertia"
    } == {f"link {foot}" for foot in feet}
    engines = {"drake"} & {f.engine for f in refused.comparisons[0].findings}
    assert _more(line) <= len(engines) and " and 5 more" not in line, line
    _one_sentence(line)


# ------------------------------------------------------------------------------------ 4: no Python reprs
def test_values_are_listed_not_printed_as_python_sequences() -> None:
    check = koenig_check.compare(SUITE / "manipulator.xml", **ONE)
    whole = check.failures[0][1]
    _, joints = _root_bodies(SUITE / "manipulator.xml")
    assert f"(joints {', '.join(joints['ball'])}, mujoco loaded, pinocchio not read)" in whole, whole
    assert not re.search(r"[\[(]'[^']*',|\[\]|\(\)", whole), whole
    jaco = koenig_check.compare(KINOVA / "jaco_arm.xml", **ONE)
    includes = [f.message() for f in jaco.comparisons[0].findings if f.element.startswith("include ")]
    assert includes and not any("()" in m or "bodies ," in m for m in includes), includes
    assert "did you mean ur5" in koenig_check.compare("ur6", **ONE).reason()


# -------------------------------------------------------------- 5: FAILED (DISAGREE) rows fit the table
def test_a_failed_row_gives_the_short_failure_line_with_the_path_as_given() -> None:
    check = koenig_check.compare([SUITE / "manipulator.xml", SUITE / "finger.xml"], **ONE)
    table = terminal_table(check)
    rows = [line for line in table.splitlines() if "DISAGREE" in line]  # joints Pinocchio lacks: a disagreement
    assert len(rows) == 2 and all(len(r) <= WIDTH for r in rows), rows
    assert str(SUITE) not in table
    for label, short in check.failure_lines.items():
        assert " ".join(short.removeprefix(f"{label}: ").split()) in " ".join(table.split())
    block = table.split("manipulator.xml  DISAGREE", 1)[1].split("finger.xml", 1)[0]
    assert len(block.splitlines()) <= 4, block  # not the 26 lines of the whole message


# ------------------------------------------------------------------------------ 6: the option as spelt
def test_the_cli_and_the_api_name_the_tolerance_each_their_way() -> None:
    from koenig_check.diagnosis.reason import rounding_hint

    # the bound a 6-digit file holds at every pose (1e-05), never a smaller one the poses drawn happen to meet
    assert rounding_hint(3e-7, 1e-9).endswith("rtol=1e-05 accepts it")
    assert rounding_hint(3e-7, 1e-9, cli=True).endswith("--rtol 1e-05 accepts it")
    assert rounding_hint(4e-6, 1e-9).endswith("rtol=1e-05 accepts it")


@pytest.mark.parametrize(
    ("bodies", "advice"),
    [
        (1, "--floating, floating=True, gives the root body a free joint"),
        (3, "3 top-level bodies (a0, a1, a2): --floating frees one only; give each that moves a joint"),
    ],
)
def test_without_a_joint_the_advice_fits_the_file(tmp_path: Path, bodies: int, advice: str) -> None:
    """--floating frees one top-level body: a file with several gets other advice."""
    path = tmp_path / "still.xml"
    text = "".join(f'<body name="a{i}" pos="{i} 0 0"><geom size="0.1"/></body>' for i in range(bodies))
    path.write_text(f"<mujoco><worldbody>{text}</worldbody></mujoco>")
    assert len(ET.parse(path).getroot().find("worldbody")) == bodies  # the file's own top-level bodies
    check = koenig_check.compare(path, **ONE)
    assert f"({advice})" in check.failures[0][1]
    from koenig_check.engines import load_model
    from koenig_check.exceptions import NoMovingSegmentError

    with pytest.raises(NoMovingSegmentError) as info:
        load_model(path)
    assert [c.hint for c in info.value.causes] == [advice]  # the cause the reports show says the same
