"""No committed output of comparisons/ carries a path of the machine it was produced on."""

from __future__ import annotations

from pathlib import Path

import pytest
from common import display_name, dm_control_corpus, erd_corpus, project_corpus, scrub

from documents import DOCUMENTS  # the README and the site's pages

COMPARISONS = Path(__file__).resolve().parents[2] / "comparisons"
OUTPUTS = sorted(p for p in COMPARISONS.iterdir() if p.suffix in (".md", ".json"))
FORBIDDEN = ("/tmp/", "/home/", "/root/", "/work/", "site-packages/")


def test_outputs_are_found() -> None:
    names = {p.name for p in OUTPUTS}
    assert {"paper_claims.md", "engine_parity.md", "inertia_forces.md", "README.md"} <= names


@pytest.mark.parametrize("path", OUTPUTS + DOCUMENTS, ids=[p.name for p in OUTPUTS + DOCUMENTS])
def test_no_absolute_path_in_committed_output(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    found = [f for f in FORBIDDEN if f in text]
    assert not found, f"{path.name} contains {found}"


def test_models_are_named_relative_to_their_package() -> None:
    erd = next(p for p in erd_corpus() if p.name == "ur5_robot.urdf")
    assert display_name(erd) == "example-robot-data: ur_description/urdf/ur5_robot.urdf"
    gimbal = next(p for p in project_corpus() if p.name == "gimbal.xml")
    assert display_name(gimbal) == "koenig-check: gimbal.xml"
    corpus = dm_control_corpus()
    if corpus:
        cartpole = next(p for p in corpus if p.as_posix().endswith("suite/cartpole.xml"))
        assert display_name(cartpole) == "dm_control: suite/cartpole.xml"


def test_engine_messages_are_rewritten() -> None:
    erd = next(p for p in erd_corpus() if p.name == "ur5_robot.urdf")
    message = f"{erd}: link 'base' refused; copy at /tmp/xyz123/ur5_robot.urdf (line 3)"
    out = scrub(message)
    expected = "example-robot-data: ur_description/urdf/ur5_robot.urdf: link 'base' refused; copy at ur5_robot.urdf"
    assert out == expected + " (line 3)"
    assert not any(f in out for f in FORBIDDEN)


def test_a_web_address_in_an_engine_message_is_kept() -> None:
    """Drake ends its refusals with a troubleshooting link: not a path of the machine, kept whole."""
    message = (
        "only .obj meshes, /tmp/a/b/leg.stl was requested. See https://drake.mit.edu/troubleshooting.html for more"
    )
    assert (
        scrub(message)
        == "only .obj meshes, leg.stl was requested. See https://drake.mit.edu/troubleshooting.html for more"
    )
