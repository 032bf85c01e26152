"""``koenig-check export``: exit 0 equivalent, 1 naming what differs (a corrupted export names the link), 2 usage."""

from __future__ import annotations

import itertools
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from koenig_check.cli import main

#: The export tests' models (tests/export/models).
MODELS = Path(__file__).resolve().parents[1] / "export" / "models"


def test_export_prints_equivalent(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "slide.urdf"
    assert main(["export", str(MODELS / "slide.xml"), "--to", "urdf", "--out", str(out), "--poses", "3"]) == 0
    text = capsys.readouterr().out
    assert "equivalent: max relative difference" in text and "over 3 poses" in text
    assert out.is_file()


def _corrupt(path: Path, link: str, element: str, attribute: str, factor: float) -> Path:
    tree = ET.parse(path)
    node = tree.getroot().find(f"link[@name='{link}']/inertial/{element}")
    assert node is not None
    if attribute == "xyz":
        x, y, z = (float(v) for v in node.get("xyz", "0 0 0").split())
        node.set("xyz", f"{x + factor} {y} {z}")
    else:
        node.set(attribute, repr(float(node.get(attribute, "0")) * factor))
    corrupted = path.with_name("corrupted.urdf")
    tree.write(corrupted)
    return corrupted


@pytest.mark.parametrize(
    ("element", "attribute", "factor", "quantity"),
    [
        ("inertia", "ixx", 1.3, "principal moments"),
        ("mass", "value", 1.1, "mass"),
        ("origin", "xyz", 0.05, "COM distance"),
    ],
)
def test_corrupted_export_fails_naming_the_link(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], element: str, attribute: str, factor: float, quantity: str
) -> None:
    exported = tmp_path / "hinge_ref.urdf"
    assert main(["export", str(MODELS / "hinge_ref.xml"), "--to", "urdf", "--out", str(exported)]) == 0
    corrupted = _corrupt(exported, "b", element, attribute, factor)
    capsys.readouterr()
    assert main(["export", "--check-only", str(MODELS / "hinge_ref.xml"), str(corrupted)]) == 1
    text = capsys.readouterr().out
    assert "not equivalent" in text
    assert f"link b (joint twist): {quantity}" in text
    assert "link a " not in text


def test_corrupted_joint_axis_fails_on_the_mass_matrix(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A kinematic change (no link's mass properties touched) is caught by the mass matrices themselves."""
    exported = tmp_path / "hinge_ref.urdf"
    assert main(["export", str(MODELS / "hinge_ref.xml"), "--to", "urdf", "--out", str(exported)]) == 0
    tree = ET.parse(exported)
    axis = tree.getroot().find("joint[@name='twist']/axis")
    assert axis is not None
    axis.set("xyz", "0 0 1")
    corrupted = tmp_path / "corrupted.urdf"
    tree.write(corrupted)
    capsys.readouterr()
    assert main(["export", "--check-only", str(MODELS / "hinge_ref.xml"), str(corrupted)]) == 1
    text = capsys.readouterr().out
    for engine in ("mujoco", "pinocchio"):
        assert f"{engine}: mass matrix differs by" in text


@pytest.mark.parametrize(
    "argv",
    [
        ["export"],
        ["export", "MODEL_ONLY.xml", "--to", "urdf"],
        ["export", "{model}", "--to", "urdf", "--out", "{tmp}/wrong_suffix.xml"],
        ["export", "{model}", "--to", "mjcf", "--out", "{tmp}/wrong_suffix.urdf"],
        ["export", "{model}", "--to", "urdf", "--out", "{tmp}"],
        ["export", "{model}", "--to", "urdf", "--out", "{tmp}/missing/dir.urdf"],
        ["export", "{model}", "--to", "sdf", "--out", "{tmp}/x.sdf"],
        ["export", "--check-only", "{model}", "{tmp}/missing.urdf"],
        ["export", "--check-only", "{model}", "{model}", "--to", "urdf"],
        ["export", "{model}", "--to", "urdf", "--out", "{tmp}/x.urdf", "--poses", "0"],
        ["export", "{model}", "--to", "urdf", "--out", "{tmp}/x.urdf", "--pinocchio-model", "{model}"],
    ],
)
def test_usage_errors_exit_2_before_any_work(tmp_path: Path, argv: list[str]) -> None:
    argv = [a.format(model=MODELS / "slide.xml", tmp=tmp_path) for a in argv]
    with pytest.raises(SystemExit) as caught:
        main(argv)
    assert caught.value.code == 2
    assert list(tmp_path.iterdir()) == []


def test_refusal_exits_1_naming_the_joint(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["export", str(MODELS / "ball.xml"), "--to", "urdf", "--out", str(tmp_path / "b.urdf")]) == 1
    assert "ball joint (joints socket)" in capsys.readouterr().out


def test_check_only_names_the_frame_that_hides_joints_from_an_engine(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """An MJCF export that keeps a <frame>: the engines whose parser skips it are told why its joints are missing."""
    causes = Path(__file__).resolve().parents[1] / "models" / "causes"
    export = tmp_path / "export.xml"
    export.write_text((causes / "frame_body.xml").read_text())
    argv = ["export", "--check-only", str(causes / "frame_body.xml"), str(export), "--engines", "mujoco,pinocchio"]
    assert main(argv) == 1  # Pinocchio was named and could not compare: no proof
    lines = capsys.readouterr().out.splitlines()
    (start,) = [i for i, t in enumerate(lines) if t.startswith("  - Pinocchio asked for (--engines) but not compared:")]
    folded = itertools.takewhile(lambda t: t.startswith("      "), lines[start + 1 :])  # its continuation lines
    line = " ".join([lines[start], *(t.strip() for t in folded)])
    assert all(len(t) <= 200 for t in lines)
    assert "only in MuJoCo: j2" in line  # Pinocchio's own reason, whole
    assert line.endswith(
        "root cause: frame #1 in body base: <frame> not read by Pinocchio's MJCF parser: what it holds is missing "
        "(1 bodies, 1 joints) (joints j2)"
    )


def test_a_refusal_is_never_cut() -> None:
    """Constructs whose names do not fit one line even one each: the first line counts them, the list gives each
    whole (issue 28: never cut with '…')."""
    from koenig_check.cli.export import refused_lines
    from koenig_check.export.carried import ExportRefusedError, NotCarried

    kinds = [f"construct_{k}_" + "x" * 30 for k in range(6)]
    constructs = tuple(NotCarried(kind, f"joint {kind}_joint", f"{kind} cannot be written: why") for kind in kinds)
    lines = refused_lines(ExportRefusedError("refused", constructs), "urdf")
    assert lines[0] == "refused: URDF cannot hold 6 kinds of construct (6 elements)"
    assert all(len(line) <= 200 for line in lines) and "…" not in "\n".join(lines)
    flat = " ".join(" ".join(lines).split())
    assert all(f"joint {kind}_joint" in flat and f"{kind} cannot be written: why" in flat for kind in kinds)
