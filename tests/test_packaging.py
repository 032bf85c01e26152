"""pyproject.toml installs every subpackage: a non-editable install (pip install .) has them all."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"


def test_every_subpackage_is_listed_for_setuptools() -> None:
    tomllib = pytest.importorskip("tomllib")  # Python >= 3.11
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["setuptools"]["packages"])
    found = {".".join(init.parent.relative_to(SRC).parts) for init in (SRC / "koenig_check").rglob("__init__.py")}
    assert found, SRC
    assert found - listed == set(), "subpackages a non-editable install would leave out"
