"""Report directories: earlier own files cleaned, foreign files refused without --overwrite, listing == disk."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check import cli
from koenig_check.arguments import ArgumentValueError
from koenig_check.report.output_dir import MANIFEST, check_out_dir, clean_out_dir, finish_out_dir


def _listed(stdout: str) -> set[str]:
    block = stdout.split("\nreport: ", 1)[1].splitlines()[1:]
    return {line.split()[0] for line in block if line.startswith("  ")}


def _on_disk(out: Path) -> set[str]:
    return {p.name for p in out.iterdir() if p.name != MANIFEST}


def test_second_run_removes_the_first_runs_files_and_lists_what_is_on_disk(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "report"
    cli.main(["compare", "gimbal.xml", "--poses", "3", "--out", str(out)])
    first = _listed(capsys.readouterr().out)
    assert first == _on_disk(out)
    stale = out / "error_map.png"  # as an earlier grid run would have left it
    stale.write_bytes(b"old figure")
    finish_out_dir(out, [out / n for n in first] + [stale])
    cli.main(["compare", "gimbal.xml", "--poses", "3", "--out", str(out)])
    second = _listed(capsys.readouterr().out)
    assert second == _on_disk(out) == first and not stale.exists()


def test_foreign_files_refuse_the_directory_unless_overwrite(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "report"
    out.mkdir()
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    with pytest.raises(SystemExit) as exc:
        cli.main(["compare", "gimbal.xml", "--poses", "3", "--out", str(out)])
    assert exc.value.code == 2 and "notes.txt" in capsys.readouterr().err
    assert _on_disk(out) == {"notes.txt"}
    cli.main(["compare", "gimbal.xml", "--poses", "3", "--out", str(out), "--overwrite"])
    listed = _listed(capsys.readouterr().out)
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert listed == _on_disk(out) - {"notes.txt"} and "summary.md" in listed


def test_clean_removes_only_the_tools_files(tmp_path: Path) -> None:
    (tmp_path / "summary.md").write_text("old", encoding="utf-8")  # an older version's file, no manifest
    (tmp_path / "custom_figure.png").write_text("listed", encoding="utf-8")
    (tmp_path / "keep.txt").write_text("foreign", encoding="utf-8")
    (tmp_path / MANIFEST).write_text("custom_figure.png\n../escape\n", encoding="utf-8")
    removed = {p.name for p in clean_out_dir(tmp_path)}
    assert removed == {"summary.md", "custom_figure.png", MANIFEST}
    assert [p.name for p in tmp_path.iterdir()] == ["keep.txt"]


def test_check_accepts_missing_and_own_directories(tmp_path: Path) -> None:
    assert check_out_dir(tmp_path / "new") == tmp_path / "new"
    (tmp_path / "records.json").write_text("{}", encoding="utf-8")
    check_out_dir(tmp_path)
    (tmp_path / "data.bin").write_bytes(b"x")
    with pytest.raises(ArgumentValueError, match=r"data\.bin"):
        check_out_dir(tmp_path)
    check_out_dir(tmp_path, overwrite=True)
