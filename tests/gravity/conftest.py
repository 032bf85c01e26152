"""The gravity tests' fixture: a file written in the test's folder."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture
def write(tmp_path: Path):
    """Write an MJCF text to a file in the test's folder and return its path."""

    def _write(text: str, name: str = "arm.xml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path

    return _write
