"""The CLI end to end on the built-in models: exit codes, every promised file, valid figures."""

from __future__ import annotations

import csv
import json
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.formulas import FORMULAS
from koenig_check.run.records import RECORD_FIELDS

MODELS = Path(__file__).resolve().parents[1] / "models"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _png_size(path: Path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, f"{path} is not a PNG"
    assert data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


@pytest.fixture(scope="module")
def demo_report(tmp_path_factory: pytest.TempPathFactory) -> tuple[int, Path, str]:
    out = tmp_path_factory.mktemp("demo") / "report"
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "demo", "--out", str(out), "--poses", "8"],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    return proc.returncode, out, proc.stdout + proc.stderr


def test_demo_exits_zero_and_prints_the_verdict(demo_report: tuple[int, Path, str]) -> None:
    code, _, output = demo_report
    assert code == 0, output
    assert "Models: do MuJoCo and Pinocchio agree? (tolerance 1e-09" in output
    for model in ["gimbal.xml", "serial7.urdf", "free_body.urdf", "double_pendulum.xml", "armature_chain.xml"]:
        assert model in output
    for name in FORMULAS:
        assert name in output
    assert "Traceback" not in output


def test_demo_writes_every_promised_file(demo_report: tuple[int, Path, str]) -> None:
    _, out, _ = demo_report
    summary = (out / "summary.md").read_text()
    assert summary.startswith("# koenig-check report") and "| formula | verdict | max rel. error |" in summary
    with open(out / "records.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert rows and tuple(rows[0]) == RECORD_FIELDS
    doc = json.loads((out / "records.json").read_text())
    assert doc["record_fields"] == list(RECORD_FIELDS) and len(doc["records"]) == len(rows)
    assert doc["parity"] and all(p["agrees"] for p in doc["parity"])
    for name in ["error_distribution.png", "error_map.png", "trajectory_energy.png"]:
        width, height = _png_size(out / name)
        assert width >= 400 and height >= 300 and (out / name).stat().st_size > 20_000


def test_compare_several_models_with_options(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        [
            "compare",
            str(MODELS / "gimbal.xml"),
            str(MODELS / "double_pendulum.urdf"),
            "--poses",
            "5",
            "--seed",
            "3",
            "--formulas",
            "exact",
            "koenig_world",
            "planar",
            "--out",
            str(tmp_path / "r"),
        ]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert "gimbal.xml" in out and "double_pendulum.urdf" in out and "alyushin_current" not in out
    rows = list(csv.DictReader(open(tmp_path / "r" / "records.csv", newline="")))
    assert {r["formula"] for r in rows} == {"exact", "koenig_world", "planar"}
    assert {r["model"] for r in rows} == {"gimbal.xml", "double_pendulum.urdf"}


def test_compare_exits_one_with_a_reason_when_a_model_fails(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "missing.urdf"
    code = main(["compare", str(MODELS / "gimbal.urdf"), str(missing), "--poses", "3"])
    captured = capsys.readouterr()
    assert code == 1
    assert "gimbal.urdf" in captured.out and "agree" in captured.out  # the good model still reports
    assert "missing.urdf" in captured.out and "FAILED" in captured.out
    err_lines = [line for line in captured.err.splitlines() if line.startswith("koenig-check:")]
    assert len(err_lines) == 1 and "missing.urdf" in err_lines[0]


def test_parity_and_models_commands(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["parity", str(MODELS / "serial7.urdf")]) == 0
    out = capsys.readouterr().out
    assert "verdict: no import difference" in out and "j3" in out
    assert main(["models"]) == 0
    listing = capsys.readouterr().out
    assert "urdf" in listing and "mjcf" in listing and len(listing.splitlines()) > 20


@pytest.mark.parametrize("command", ["demo", "compare", "parity", "models", "selfcheck"])
def test_every_command_has_help_with_an_example(command: str) -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", command, "--help"], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 0 and f"example:\n  koenig-check {command}" in proc.stdout


def test_bad_usage_is_the_usage_line_then_one_error_line_and_status_two() -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "compare"], capture_output=True, text=True, check=False
    )
    lines = proc.stderr.strip().splitlines()
    assert proc.returncode == 2 and len(lines) == 2 and "Traceback" not in proc.stderr
    assert lines[0] == "usage: koenig-check compare [options] MODEL [MODEL ...]" and "error:" in lines[1]


def test_python_api_has_the_reach_of_the_cli() -> None:
    import koenig_check

    check = koenig_check.compare([MODELS / "gimbal.xml", MODELS / "nope.xml"], n_poses=4, seed=1)
    assert not check.ok and check.failures[0][0] == "nope.xml" and "gimbal.xml" in [c.model for c in check.comparisons]
    totals = check.records.where(scope="total", formula="exact")
    assert len(totals) == 4 * 2 * 2  # poses × state sources × reference engines
    assert (totals["rel_error"] < 1e-12).all()
    assert {s.formula for s in check.summaries} >= {"koenig_world", "alyushin_paper:rotvec"}


def test_compare_grid_and_trajectory_write_their_figures(tmp_path: Path) -> None:
    gimbal = str(MODELS / "gimbal.xml")
    assert (
        main(
            [
                "compare",
                gimbal,
                "--pose-kind",
                "grid",
                "--grid-joints",
                "outer_z",
                "inner_x",
                "--poses",
                "6",
                "--out",
                str(tmp_path / "g"),
            ]
        )
        == 0
    )
    assert _png_size(tmp_path / "g" / "error_map.png")[0] >= 400
    assert main(["compare", gimbal, "--pose-kind", "trajectory", "--poses", "50", "--out", str(tmp_path / "t")]) == 0
    assert _png_size(tmp_path / "t" / "trajectory_energy.png")[0] >= 400


@pytest.mark.parametrize("rtol", ["nan", "-1", "0", "inf", "abc"])
def test_bad_tolerance_is_a_usage_error(rtol: str) -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "compare", "gimbal.xml", "--rtol", rtol],
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 2 and "--rtol" in proc.stderr and len(proc.stderr.strip().splitlines()) == 2


@pytest.mark.parametrize("where", ["before", "after"])
def test_debug_flag_shows_the_traceback_wherever_it_is_given(tmp_path: Path, where: str) -> None:
    missing = str(tmp_path / "missing.urdf")
    args = ["--debug", "parity", missing] if where == "before" else ["parity", missing, "--debug"]
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", *args], capture_output=True, text=True, check=False
    )
    assert proc.returncode != 0 and "Traceback" in proc.stderr


def test_engine_disagreement_names_its_import_cause(tmp_path: Path) -> None:
    import re

    from koenig_check.api import compare_model
    from koenig_check.run.summaries import engine_agreement

    comp = compare_model(MODELS / "serial7.urdf", n_poses=4)
    assert engine_agreement(comp).agrees and not [f for f in comp.findings if f.affects_energy]
    text = (MODELS / "serial7.urdf").read_text()
    altered = re.sub(r'(<link name="link5">.*?<mass value=")1.2(")', r"\g<1>1.5\g<2>", text, count=1, flags=re.S)
    copy = tmp_path / "heavier.urdf"
    copy.write_text(altered)
    parity = engine_agreement(compare_model(MODELS / "serial7.urdf", n_poses=4, pinocchio_model=copy))
    assert not parity.agrees and "cause: both: link link5 (joint j5): mass differs between the engines" in parity.reason
    assert "(mujoco 1.2, pinocchio 1.5, relative difference 0.2)" in parity.reason
