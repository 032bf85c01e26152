"""Fixtures of the engine tests: every case is loaded once, posed at seeded random states.

``case`` is a module-scoped parameter, so pytest runs a module's tests case by case, and ``pair`` holds the
one case's engines while they run: memory holds one model, not the whole corpus (about 2.7 GB when every
loaded pair was cached for the session).

Layout: tests of the shared modules (``base``, ``loading``, ``sampling``, ...) sit here; tests of one engine's
subpackage in ``mujoco/``, ``pinocchio/``, ``drake/``, named ``test_<engine>_*.py``.  These folders have no
``__init__.py``: pytest imports test modules by their base name (its default ``prepend`` mode), so base names
stay unique across folders; and an ``__init__.py`` would make ``tests/engines/mujoco`` a package named ``mujoco``
(or ``pinocchio``) in place of the engine.  Helper modules here (``engine_helpers``, ``urdf_builders``,
``all_joints``) are imported by name: this folder is on ``sys.path`` once this file is loaded.
"""

from __future__ import annotations

import numpy as np
import pytest
from engine_helpers import CASES, N_POSES, SEED, Case

from koenig_check.engines import LoadedModel, load_model, random_states


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    if "case" in metafunc.fixturenames:
        metafunc.parametrize("case", CASES, ids=[c.id for c in CASES], scope="module")


def _load(case: Case) -> LoadedModel:
    return load_model(
        case.model,
        floating=case.floating,
        pinocchio_source=case.pinocchio_source,
        balance_inertia=case.balance_inertia,
    )


@pytest.fixture(scope="session")
def load_pair():
    return _load


@pytest.fixture(scope="module")
def pair(case: Case, load_pair) -> LoadedModel:
    return load_pair(case)


@pytest.fixture
def pose_batch(pair: LoadedModel) -> tuple[np.ndarray, np.ndarray]:
    return random_states(pair.mujoco.model, N_POSES, seed=SEED)
