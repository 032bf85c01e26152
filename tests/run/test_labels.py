"""A run's model labels are unique: two files with one name never share records, rows or report sections."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.run.labels import unique_labels

HERE = Path(__file__).resolve().parents[1]
DISAGREES = HERE / "models" / "causes" / "class_mass.xml"  # Pinocchio ignores a default-class geom mass
AGREES = HERE.parent / "models" / "gimbal.xml"


@pytest.mark.parametrize(
    ("models", "labels"),
    [
        (["x/robot.xml"], ["robot.xml"]),
        (["a/robot.xml", "b/robot.xml"], ["a/robot.xml", "b/robot.xml"]),
        (["a/x/robot.xml", "b/x/robot.xml", "c/robot.xml"], ["a/x/robot.xml", "b/x/robot.xml", "c/robot.xml"]),
        (["ur5", "gimbal.xml"], ["ur5", "gimbal.xml"]),
        (["a/robot.xml", "a/robot.xml"], ["robot.xml", "robot.xml#2"]),
    ],
)
def test_labels_are_the_shortest_distinguishing_path_suffix(models: list[str], labels: list[str]) -> None:
    assert unique_labels(models) == labels
    assert unique_labels(models, floating=True) == [f"{label} (floating)" for label in labels]


@pytest.fixture
def same_name(tmp_path: Path) -> tuple[Path, Path]:
    """``a/robot.xml`` whose engines disagree and ``b/robot.xml`` whose engines agree."""
    a, b = tmp_path / "a" / "robot.xml", tmp_path / "b" / "robot.xml"
    for src, dst in ((DISAGREES, a), (AGREES, b)):
        dst.parent.mkdir()
        shutil.copy(src, dst)
    return a, b


def test_api_keeps_two_files_with_one_name_apart(same_name: tuple[Path, Path]) -> None:
    check = koenig_check.compare(list(same_name), n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio"))
    agrees = {p.model: p.agrees for p in check.agreements}
    assert agrees == {"a/robot.xml": False, "b/robot.xml": True}
    assert set(check.settings) == {"a/robot.xml", "b/robot.xml"}
    assert {s.model for s in check.summaries} == {"a/robot.xml", "b/robot.xml"}
    assert set(check.records.columns["model"].tolist()) == {"a/robot.xml", "b/robot.xml"}
    assert not check.ok  # no third engine here: the two engines' disagreement alone fails the run
    assert check.reason().startswith("a/robot.xml: ") and "b/robot.xml" not in check.reason()


def test_cli_keeps_two_files_with_one_name_apart(
    same_name: tuple[Path, Path], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "report"
    argv = ["compare", *map(str, same_name), "--poses", "2", "--formulas", "exact", "--out", str(out)]
    assert main([*argv, "--engines", "mujoco,pinocchio"]) == 1
    rows = {line.split()[0]: line.split()[1] for line in capsys.readouterr().out.splitlines() if "robot.xml  " in line}
    assert rows == {"a/robot.xml": "DISAGREE", "b/robot.xml": "agree"}
    summary = (out / "summary.md").read_text(encoding="utf-8")
    assert "- **a/robot.xml** (2 random poses): MuJoCo and Pinocchio DISAGREE" in summary
    assert "- **b/robot.xml** (2 random poses): MuJoCo and Pinocchio agree" in summary
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "a/robot.xml" in html and "b/robot.xml" in html and "DISAGREE" in html
    records = koenig_check.read_records(out / "records.parquet")
    assert sorted(set(records.columns["model"].tolist())) == ["a/robot.xml", "b/robot.xml"]


def test_models_given_with_their_labels_keep_them() -> None:
    """``compare({label: model})``: the label the caller chose (the pytest plugin's item id) names every result."""
    import koenig_check

    check = koenig_check.compare({"left/arm.xml": "gimbal.xml"}, n_poses=2, formulas=["exact"])
    assert [c.model for c in check.comparisons] == ["left/arm.xml"] and check["left/arm.xml"] is check.comparisons[0]
    assert {s.model for s in check.summaries} == {"left/arm.xml"} and list(check.settings) == ["left/arm.xml"]
