"""Fixtures of the diagnosis tests."""

from __future__ import annotations

import pytest

from koenig_check.engines import registry


@pytest.fixture
def drake_the_only_other_engine(monkeypatch: pytest.MonkeyPatch) -> None:
    """Make Drake the only optional engine installed, for the tests of a three-engine vote by the default policy.

    With every installed optional engine consulted as tie-breaker, PyBullet's or iDynTree's own reading of a file
    would cast the deciding vote these tests are not about.
    """
    installed = registry.installed
    monkeypatch.setattr(
        registry, "installed", lambda name: name in ("mujoco", "pinocchio", "drake") and installed(name)
    )
