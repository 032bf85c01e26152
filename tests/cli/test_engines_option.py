"""``--engines`` on the command line: each new engine named, an engine that cannot read the format, and ``all``.

``all`` runs, per model, every installed engine whose parser reads its format: a batch of an MJCF and a URDF runs
in two sets, and the run says which engines each model ran in and which installed ones it left out, and why.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.cli import main
from koenig_check.engines.registry import installed, label, optional
from named_engines import NEW_ENGINES, URDF_ONLY, installed_reading, labels, named

NEW = [named(e) for e in NEW_ENGINES]


def _row(out: str, model: str) -> list[str]:
    return next(line for line in out.splitlines() if line.startswith(f"{model} ")).split()


@pytest.mark.parametrize("engine", NEW)
def test_compare_names_each_new_engine_on_a_urdf(engine: str, tmp_path: Path, capsys) -> None:
    argv = ["compare", "serial7.urdf", "--poses", "2", "--formulas", "exact"]
    assert main([*argv, "--engines", f"mujoco,pinocchio,{engine}", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert lines[0].startswith(f"Models: do MuJoCo, Pinocchio and {label(engine)} agree?")
    header = lines[2].split()
    assert [w for w in header[:-1] if header[header.index(w) + 1] == "gap"] == ["pinocchio", engine]  # its column
    _, _, said = " ".join(out.split()).partition("Also installed, not run (not named in --engines): ")
    others = [label(e) for e in optional() if e != engine and installed(e)]  # said once for the run, not per model
    assert said.split(";")[0].split(", ") == others
    assert "not asked for" not in (tmp_path / "summary.md").read_text()  # no note per model and engine


@pytest.mark.parametrize("engine", [named(e) for e in URDF_ONLY])
@pytest.mark.parametrize("command", [["compare", "--poses", "2", "--formulas", "exact"], ["parity"]])
def test_an_engine_that_cannot_read_mjcf_fails_with_its_reason(engine: str, command: list[str], capsys) -> None:
    argv = [command[0], "double_pendulum.xml", *command[1:], "--engines", f"mujoco,pinocchio,{engine}"]
    assert main(argv) == 1
    first, *rest = capsys.readouterr().err.splitlines()
    assert first.startswith(f"koenig-check: double_pendulum.xml: {label(engine)} asked for (--engines)")
    assert len(first) <= 200
    whole = " ".join(" ".join([first, *rest]).split())
    assert f"{label(engine)} reads URDF only" in whole  # the engine's own reason, whole


def test_all_runs_each_model_in_the_engines_that_read_its_format(tmp_path: Path, capsys) -> None:
    argv = ["compare", "serial7.xml", "serial7.urdf", "--poses", "2", "--formulas", "exact", "--engines", "all"]
    assert main([*argv, "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    text = " ".join(out.split())
    header = out.splitlines()[2].split()
    columns = [w for k, w in enumerate(header[:-1]) if header[k + 1] == "gap"]  # pinocchio, then the others
    assert columns == ["pinocchio", *(e for e in optional() if installed(e))]
    for model, fmt in (("serial7.xml", "mjcf"), ("serial7.urdf", "urdf")):
        cells = dict(zip(columns, _row(out, model)[2:], strict=False))  # after the model and its verdict
        assert {e for e, cell in cells.items() if cell != "—"} == set(installed_reading(fmt)) - {"mujoco"}, model
    mjcf, urdf = installed_reading("mjcf"), installed_reading("urdf")
    left = [e for e in urdf if e not in mjcf]
    assert mjcf != urdf and left  # the sets differ, and the run says so on the MJCF
    said = f"serial7.xml: engines {labels(mjcf)}; left out {labels(tuple(left))} (their parsers do not read MJCF)"
    assert said in text
    assert "serial7.urdf: engines" not in text  # nothing left out of the URDF's set
    assert "Also installed, not run" not in text  # every installed engine was asked for
    summary = (tmp_path / "summary.md").read_text()
    for engine in left:
        assert f"- {engine}: model: {label(engine)} not used: --engines all: its parser does not read" in summary


@pytest.mark.parametrize(
    "argv",
    [
        ["compare", "serial7.xml", "--engines", "all,drake"],
        ["compare", "serial7.xml", "--engines", "al"],
        ["parity", "serial7.xml", "--engines", "mujoco,all"],
        ["dynamics", "serial7.xml", "--engines", "drake,all"],
        ["export", "serial7.xml", "--to", "urdf", "--out", "x.urdf", "--engines", "all,newton"],
    ],
)
def test_a_misspelt_all_is_a_usage_error_before_any_work(argv: list[str], tmp_path: Path, capsys, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exit_:
        main(argv)
    assert exit_.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()[-1]
    assert "--engines" in err and "all" in err
    assert not list(tmp_path.iterdir())  # nothing written


def test_dynamics_all_gives_each_engine_that_reads_the_file_its_column(capsys) -> None:
    # each engine within its declared precision of the others (Newton's float32 round-off is no difference)
    assert main(["dynamics", "serial7.xml", "--poses", "2", "--formulas", "exact", "--engines", "all"]) == 0
    out = capsys.readouterr().out
    mjcf = installed_reading("mjcf")
    for engine in optional():
        assert (f"engines (mujoco vs {engine})" in out) == (engine in mjcf), engine
    for engine in (e for e in installed_reading("urdf") if e not in mjcf):
        assert f"{engine}: model: {label(engine)} not used: --engines all" in out


def test_export_all_proves_in_every_installed_engine_that_reads_both_files(tmp_path: Path, capsys) -> None:
    argv = ["export", "serial7.xml", "--to", "urdf", "--out", str(tmp_path / "s.urdf"), "--engines", "all"]
    assert main(argv) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert f"engines {', '.join(installed_reading('mjcf'))}" in out
    for engine in (e for e in installed_reading("urdf") if e not in installed_reading("mjcf")):
        assert f"{engine}: its parser does not read MJCF (--engines all)" in out


@pytest.mark.skipif(not installed("newton"), reason="Newton absent")
@pytest.mark.parametrize(
    "command", [["compare", "--poses", "2", "--formulas", "exact"], ["parity"], ["dynamics", "--poses", "2"]]
)
def test_all_asks_for_each_engine_so_a_refusal_fails_the_run_with_its_reason(command: list[str], capsys) -> None:
    """Newton reads MJCF, so ``all`` asks for it on an MJCF; it refuses ``solver="PGS"``: the check was not made."""
    from koenig_check.causes import cause, fixture_path

    path = fixture_path(cause("newton.mjcf.solver-pgs"))
    assert main([command[0], str(path), *command[1:], "--engines", "all"]) == 1
    out, err = capsys.readouterr()
    first = next(line for line in err.splitlines() if line.startswith("koenig-check: "))
    assert first.startswith("koenig-check: newton_solver_pgs.xml: ") and len(first) <= 200
    assert "Newton asked for (--engines) but it could not check the model" in first
    # Newton's own words: under the first line (compare, dynamics), or in the report above it (parity's table)
    assert "invalid literal for int() with base 10: 'pgs'" in (out if command[0] == "parity" else err)
