"""Shared fixtures: seeded random generators and synthetic segment states."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from koenig_check.formulas.analytic import random_states
from koenig_check.segments import SegmentStates
from process_memory import peak_memory, release_memory

#: ``pytester`` runs pytest on small projects (the ``--koenig-check`` plugin's tests, in subprocesses).
pytest_plugins = ["pytester"]

#: The comparison scripts live in ``comparisons/`` (scripts, not a package): their shared corpus
#: definitions (``common``) are importable from the tests.
COMPARISONS = Path(__file__).resolve().parents[1] / "comparisons"
if str(COMPARISONS) not in sys.path:
    sys.path.insert(0, str(COMPARISONS))


@pytest.fixture(autouse=True, scope="session")
def _no_mujoco_log_file() -> None:
    """MuJoCo's warnings go to a logger, not to MUJOCO_LOG.TXT in the directory the tests run from."""
    from koenig_check.noise import route_mujoco_warnings

    route_mujoco_warnings()


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261121)


@pytest.fixture
def random_batch(rng: np.random.Generator) -> SegmentStates:
    return random_states(rng, n_poses=64, n_segments=7)


@pytest.fixture(autouse=True, scope="module")
def _release_memory_after_each_module(request: pytest.FixtureRequest):
    yield
    for value in list(vars(request.module).values()):  # a module's cached loads (functools.cache) end with it
        if (
            callable(getattr(value, "cache_clear", None))
            and getattr(value, "__module__", "") == request.module.__name__
        ):
            value.cache_clear()
    release_memory()


#: The suite's peak memory in one process (the project's standard); the session fails above it.
PEAK_MEMORY_LIMIT = 2 * 2**30


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    """Fail a session whose process peaked above :data:`PEAK_MEMORY_LIMIT` (a test that holds memory again)."""
    peak = peak_memory()
    if peak > PEAK_MEMORY_LIMIT and exitstatus == pytest.ExitCode.OK:
        print(
            f"\nFAILED: the tests' process peaked at {peak / 2**30:.2f} GiB, above {PEAK_MEMORY_LIMIT / 2**30:g} GiB "
            "(find the test with /usr/bin/time -v per file)",
            file=sys.stderr,
        )
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
