"""menagerie:NAME[:ENTRY], offline: a checkout through MENAGERIE_ROOT and a prepared MENAGERIE_CACHE_DIR."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from source_trees import (
    MENAGERIE_MODEL_FILE,
    MENAGERIE_ROBOT,
    MENAGERIE_SCENE_FILE,
    menagerie_cache,
    menagerie_root,
    no_network,
)

from koenig_check import compare
from koenig_check.cli import main
from koenig_check.engines import load_model
from koenig_check.sources import ModelSourceError
from koenig_check.sources.catalogue import resolve_model

TREES = {"MENAGERIE_ROOT": menagerie_root, "MENAGERIE_CACHE_DIR": menagerie_cache}
NAMES = {
    f"menagerie:{MENAGERIE_ROBOT}": MENAGERIE_MODEL_FILE,  # the default model: the robot alone
    f"menagerie:{MENAGERIE_ROBOT}:scene": MENAGERIE_SCENE_FILE,
    f"menagerie:{MENAGERIE_ROBOT}:piper": MENAGERIE_MODEL_FILE,
}


@pytest.mark.parametrize("tree", sorted(TREES))
@pytest.mark.parametrize("name", sorted(NAMES))
def test_name_resolves_to_the_entry_file(tree, name, tmp_path, monkeypatch):
    robot_dir = TREES[tree](tmp_path, monkeypatch)
    source = resolve_model(name)
    assert source.path.resolve() == (robot_dir / NAMES[name]).resolve()
    assert (source.name, source.origin, source.format) == (name, "menagerie", "mjcf")


@pytest.mark.parametrize("tree", sorted(TREES))
def test_robot_loads_and_compares_under_its_label(tree, tmp_path, monkeypatch):
    robot_dir = TREES[tree](tmp_path, monkeypatch)
    name = f"menagerie:{MENAGERIE_ROBOT}"
    pair, direct = load_model(name), load_model(robot_dir / MENAGERIE_MODEL_FILE)
    q = np.array([[0.3, -0.7]])
    for a, b in zip(pair.engines.values(), direct.engines.values(), strict=True):  # the same robot as the file itself
        np.testing.assert_allclose(a.mass_matrix(q), b.mass_matrix(q), rtol=1e-14, atol=0)
    check = compare(name, n_poses=5)
    assert check.ok, check.reason()
    assert [c.model for c in check.comparisons] == [name]  # reports say where the model came from


def test_scene_entry_reaches_pinocchio_include_cause(tmp_path, monkeypatch):
    """A scene pulls the robot in through <include>: the known root cause, not a crash."""
    menagerie_root(tmp_path, monkeypatch)
    check = compare(f"menagerie:{MENAGERIE_ROBOT}:scene", n_poses=3)
    assert not check.ok
    assert "include" in check.reason()


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        (f"menagerie:{MENAGERIE_ROBOT[:-1]}", f"did you mean menagerie:{MENAGERIE_ROBOT}"),
        ("menagerie:piper", f"did you mean menagerie:{MENAGERIE_ROBOT}"),
        (f"menagerie:{MENAGERIE_ROBOT}:scen", f"did you mean menagerie:{MENAGERIE_ROBOT}:scene"),
    ],
)
def test_unknown_name_suggests_the_closest(name, expected, tmp_path, monkeypatch):
    menagerie_root(tmp_path, monkeypatch)
    with pytest.raises(ModelSourceError) as info:
        resolve_model(name)
    assert expected in str(info.value)
    assert "\n" not in str(info.value)


def test_download_that_cannot_happen_says_which_variable_to_set(tmp_path, monkeypatch):
    no_network(tmp_path, monkeypatch)
    with pytest.raises(ModelSourceError) as info:
        resolve_model(f"menagerie:{MENAGERIE_ROBOT}")
    text = str(info.value)
    assert "\n" not in text
    assert text.startswith(f"menagerie:{MENAGERIE_ROBOT}: ")
    for variable in ("MENAGERIE_ROOT", "MENAGERIE_CACHE_DIR", "MENAGERIE_BASE_URL"):
        assert variable in text


def test_root_without_the_robot_is_refused(tmp_path, monkeypatch):
    menagerie_root(tmp_path, monkeypatch)
    with pytest.raises(ModelSourceError, match="MENAGERIE_ROOT"):
        resolve_model("menagerie:unitree_g1")


def test_batch_refused_before_any_model_is_loaded(tmp_path, monkeypatch):
    no_network(tmp_path, monkeypatch)
    started = []
    with pytest.raises(ModelSourceError):
        compare(["gimbal", f"menagerie:{MENAGERIE_ROBOT}"], n_poses=2, progress=started.append)
    assert started == []


def test_cli_exits_2_before_any_work(tmp_path, monkeypatch, capsys):
    no_network(tmp_path, monkeypatch)
    out = tmp_path / "report"
    with pytest.raises(SystemExit) as info:
        main(["compare", "gimbal", f"menagerie:{MENAGERIE_ROBOT}", "--out", str(out)])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert "MENAGERIE_CACHE_DIR" in err
    assert not out.exists()


def test_cli_exit_status_and_label(tmp_path, monkeypatch, capsys):
    menagerie_root(tmp_path, monkeypatch)
    assert main(["compare", f"menagerie:{MENAGERIE_ROBOT}", "--poses", "3"]) == 0
    assert f"menagerie:{MENAGERIE_ROBOT}  agree" in capsys.readouterr().out


@pytest.mark.parametrize("tree", sorted(TREES))
def test_models_menagerie_lists_robots_with_categories(tree, tmp_path, monkeypatch, capsys):
    import mujoco_menagerie as mm

    TREES[tree](tmp_path, monkeypatch)
    assert main(["models", "--menagerie"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert max(len(line) for line in lines) <= 100
    rows = {line.split()[0]: line.split()[1:] for line in lines if line.split() and line.split()[0] in mm.names()}
    assert set(rows) == set(mm.names())
    for robot in mm.robots():
        category, model, local = rows[robot.name][:3]
        assert (category, model) == (robot.category, robot.default_model)
        assert local == ("yes" if robot.name == MENAGERIE_ROBOT else "no")


def test_paths_flag_shows_the_local_file(tmp_path, monkeypatch, capsys):
    robot_dir = menagerie_root(tmp_path, monkeypatch)
    assert main(["models", "--menagerie", "--paths"]) == 0
    assert str(Path(robot_dir) / MENAGERIE_MODEL_FILE) in capsys.readouterr().out


def test_a_cache_that_cannot_be_written_is_one_line_saying_which_variable_to_set(tmp_path, monkeypatch):
    """The operating system's refusal (here: the cache folder would be inside a regular file) is an OSError,
    not one of the package's errors: it is still one line naming the model and the variables to set."""
    no_network(tmp_path, monkeypatch)
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    monkeypatch.setenv("MENAGERIE_CACHE_DIR", str(blocker / "cache"))
    with pytest.raises(ModelSourceError) as info:
        resolve_model(f"menagerie:{MENAGERIE_ROBOT}")
    text = str(info.value)
    assert "\n" not in text and text.startswith(f"menagerie:{MENAGERIE_ROBOT}: ")
    assert "MENAGERIE_CACHE_DIR" in text and "MENAGERIE_BASE_URL" in text
