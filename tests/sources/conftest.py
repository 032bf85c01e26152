"""Fixtures of the model-source tests: offline Menagerie trees, a xacro package, a stub robot_descriptions."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from source_trees import descriptions_modules, install_stub_descriptions, write_arm_package


@pytest.fixture(autouse=True)
def _xacro_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Expanded xacro files go to the test's own directory."""
    monkeypatch.setenv("KOENIG_CHECK_CACHE", str(tmp_path / "koenig-check-cache"))
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)


@pytest.fixture
def arm_xacro(tmp_path: Path) -> Path:
    """The arm's xacro file inside its ROS package (``ws/arm_pkg``)."""
    return write_arm_package(tmp_path / "ws")


@pytest.fixture
def stub_descriptions(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Callable[[dict[str, str]], Path]]:
    """Install a stub ``robot_descriptions`` (see :func:`install_stub_descriptions`); restore the real one after."""
    before = {name: sys.modules[name] for name in descriptions_modules()}

    def install(modules: dict[str, str]) -> Path:
        return install_stub_descriptions(tmp_path, monkeypatch, modules)

    yield install
    for name in descriptions_modules():
        del sys.modules[name]
    sys.modules.update(before)
