"""Old import paths of moved modules give the moved module itself."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

import pytest

from koenig_check import _moved


def test_an_old_name_gives_the_new_module_object(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(_moved.MOVED, "koenig_check._old_name_for_test", "koenig_check.roundoff")
    old = importlib.import_module("koenig_check._old_name_for_test")
    assert old is importlib.import_module("koenig_check.roundoff")
    from koenig_check._old_name_for_test import ROUNDOFF  # type: ignore[import-not-found]

    assert ROUNDOFF == old.ROUNDOFF


@pytest.mark.parametrize("old", sorted(_moved.MOVED))
def test_every_moved_name_imports(old: str) -> None:
    assert importlib.import_module(old) is importlib.import_module(_moved.MOVED[old])


def test_an_unknown_name_is_still_an_import_error() -> None:
    with pytest.raises(ModuleNotFoundError):
        importlib.import_module("koenig_check._no_such_module")


def test_a_split_module_gives_each_name_from_its_new_home() -> None:
    from koenig_check.run import chunks, comparison, stats, summaries
    from koenig_check.run.chunks import evaluate_chunk
    from koenig_check.run.comparison import ModelComparison
    from koenig_check.run.stats import DEFAULT_RTOL
    from koenig_check.run.summaries import summarize  # type: ignore[attr-defined]

    assert (DEFAULT_RTOL, ModelComparison) == (stats.DEFAULT_RTOL, comparison.ModelComparison)
    assert (evaluate_chunk, summarize) == (chunks.evaluate_chunk, summaries.summarize)
    with pytest.raises(ImportError):
        from koenig_check.run.summaries import no_such_name  # type: ignore[attr-defined]  # noqa: F401


def test_the_moved_module_keeps_its_own_name_and_reloads(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "_moved_reload_target.py").write_text("VALUE = 1\n", encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setitem(_moved.MOVED, "koenig_check._old_name_for_reload", "_moved_reload_target")
    old = importlib.import_module("koenig_check._old_name_for_reload")
    new = importlib.import_module("_moved_reload_target")
    assert old is new and new.__spec__ is not None and new.__spec__.name == "_moved_reload_target"
    new.VALUE = 2
    importlib.reload(new)  # runs the module's file again: its own value is back
    assert new.VALUE == 1
    monkeypatch.delitem(sys.modules, "_moved_reload_target")
    monkeypatch.delitem(sys.modules, "koenig_check._old_name_for_reload")


#: (old module, name, new home): names a split moved out of a module that keeps its other names.
SPLIT_OUT = [
    ("koenig_check.parity", "ParityReport", "koenig_check.diagnosis.parity_report"),
    ("koenig_check.diagnosis.import_parity", "PARITY_RTOL", "koenig_check.diagnosis.parity_report"),
    ("koenig_check.diagnosis.import_parity", "SegmentParity", "koenig_check.diagnosis.parity_report"),
    ("koenig_check.diagnosis.import_parity", "DofParity", "koenig_check.diagnosis.parity_report"),
    ("koenig_check.engines.mujoco_loader", "BodyFinding", "koenig_check.engines.mujoco.mass_changes"),
    ("koenig_check.engines.mujoco.loader", "REPAIR_HINT", "koenig_check.engines.mujoco.compiling"),
    ("koenig_check.engines.mujoco.loader", "MAX_REPAIR_TRIES", "koenig_check.engines.mujoco.compiling"),
    ("koenig_check.engines.pinocchio_engine", "placement_view", "koenig_check.engines.pinocchio.placements"),
    ("koenig_check.api", "CrossCheck", "koenig_check.run.cross_check"),
    ("koenig_check.api", "make_poses", "koenig_check.run.pose_kinds"),
    ("koenig_check.api", "load_options_from", "koenig_check.engines.load_options"),
    *[
        ("koenig_check.pipeline", name, "koenig_check.run.chunk_tasks")
        for name in ("ChunkTask", "ModelSource", "RandomRange", "PROBE_POSES", "chunk_size", "plan", "probe_normals")
    ],
    ("koenig_check.engines.sources", "model_names", "koenig_check.sources.model_names"),
    ("koenig_check.engines.sources", "ModelName", "koenig_check.sources.model_names"),
    ("koenig_check.engines.sources", "resolve_uri", "koenig_check.sources.uris"),
    ("koenig_check.engines.sources", "resolve_model", "koenig_check.sources.catalogue"),
    ("koenig_check.sources.catalogue", "resolve_uri", "koenig_check.sources.uris"),
]


@pytest.mark.parametrize(("old", "name", "home"), SPLIT_OUT)
def test_a_name_split_out_of_a_module_still_imports_from_it(old: str, name: str, home: str) -> None:
    assert getattr(importlib.import_module(old), name) is getattr(importlib.import_module(home), name)


@pytest.mark.parametrize("name", ["add_export_arguments", "run_export", "print_proof", "refused_lines"])
def test_the_export_command_imports_from_its_old_home(name: str) -> None:
    """The export command's argparse part moved from export/ into cli/ (export must not import cli)."""
    old = importlib.import_module("koenig_check.export.cli_export")
    assert getattr(old, name) is getattr(importlib.import_module("koenig_check.cli.export"), name)
