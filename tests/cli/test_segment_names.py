"""Segments named as the user wrote them, the link (and the joint that moves it), in parity's table and verdict
and in the report's worst-segment column; the link read independently from the URDF's own joint element."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.engines import resolve_model

#: Robots whose engines disagree on some segments, with the options they need.
CASES = {"bolt": [], "allegro_right_hand": ["--repair-inertia"]}


def _child_links(robot: str) -> dict[str, str]:
    """Joint name → the link it moves, from the URDF file itself."""
    root = ET.parse(resolve_model(robot).path).getroot()
    return {j.get("name"): j.find("child").get("link") for j in root.iter("joint")}


@pytest.mark.parametrize("robot", list(CASES))
def test_parity_names_each_differing_segment_by_its_link_and_joint(
    robot: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["parity", robot, *CASES[robot]]) == 1
    out = capsys.readouterr().out
    verdict = out[out.index("\nverdict: ") :].split("\n\n")[0]
    links = _child_links(robot)
    named = re.findall(r"link (\S+) \(joint (\S+)\): ", verdict)
    assert named, verdict
    for link, joint in named:
        assert links[joint] == link
    assert not re.search(r"segment \S+: ", verdict)  # never a segment by its joint alone
    rows = [line for line in out.splitlines() if "DIFFERS" in line and "(joint " in line]
    assert {(m[0], m[1]) for r in rows for m in re.findall(r"^link (\S+) \(joint (\S+)\)", r)} >= set(named)


def test_the_reports_worst_segment_is_the_link_and_its_joint(tmp_path: Path) -> None:
    out = tmp_path / "report"
    assert main(["compare", "bolt", "--poses", "5", "--formulas", "exact", "koenig_world", "--out", str(out)]) == 1
    links = _child_links("bolt")
    row = next(x for x in (out / "summary.md").read_text().splitlines() if x.startswith("| `koenig_world`"))
    (link, joint) = re.search(r"\| link (\S+) \(joint (\S+)\) at random-\d+ \|$", row).groups()
    assert links[joint] == link
    assert f"link {link} (joint {joint}) at random-" in (out / "report.html").read_text()
