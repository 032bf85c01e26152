"""Shared fixtures: seeded random generators and synthetic segment states."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.analytic import random_states
from koenig_check.segments import SegmentStates


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261121)


@pytest.fixture
def random_batch(rng: np.random.Generator) -> SegmentStates:
    return random_states(rng, n_poses=64, n_segments=7)
