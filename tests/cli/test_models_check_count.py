"""``koenig-check models --check`` counts the models that load in both engines: those :func:`load_model` loads."""

from __future__ import annotations

import re

import pytest

from koenig_check.cli import main
from koenig_check.engines import load_model

#: Two models that load in both engines and one MuJoCo refuses (an inertia it rejects).
NAMES = ["gimbal.xml", "double_pendulum.urdf", "ur3"]


def _loads(name: str) -> bool:
    try:
        load_model(name)
    except Exception:
        return False
    return True


def test_models_check_counts_the_models_that_load(monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    import koenig_check.sources.model_names as names

    every = names.model_names()
    chosen = [e for e in every if e.name in NAMES]
    assert sorted(e.name for e in chosen) == sorted(NAMES)
    monkeypatch.setattr(names, "model_names", lambda: chosen)
    expected = sum(_loads(name) for name in NAMES)
    assert expected == 2  # the test can tell a count of the loaded ones from a count of all
    assert main(["models", "--check"]) == 0
    summary = re.search(r"(\d+) of (\d+) load in both", capsys.readouterr().out)
    assert summary is not None
    assert (int(summary.group(1)), int(summary.group(2))) == (expected, len(NAMES))
