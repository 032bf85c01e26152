"""Fixtures of the dynamics tests: models loaded once per session, seeded states with accelerations."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest
from dynamics_helpers import MIXED_JOINTS_MJCF

from koenig_check.engines import LoadedModel, load_model


@pytest.fixture(scope="session")
def mixed_joints_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("models") / "mixed_joints.xml"
    path.write_text(MIXED_JOINTS_MJCF)
    return path


@cache
def _load(model: str, floating: bool) -> LoadedModel:
    return load_model(model, floating=floating)


@pytest.fixture(autouse=True, scope="package")
def _loads_end_with_the_package():
    """The models loaded once for these tests are let go when they end (not kept for the whole session)."""
    yield
    _load.cache_clear()


@pytest.fixture(scope="session")
def load_pair():
    """``load_pair(model, floating=False)``: one load per session."""

    def load(model: str | Path, floating: bool = False) -> LoadedModel:
        return _load(str(model), floating)

    return load
