"""Full-precision numbers and URDF roll-pitch-yaw angles round-trip."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.export.transforms import matrix_to_rpy, number, rpy_to_matrix


def test_numbers_round_trip_exactly() -> None:
    rng = np.random.default_rng(11)
    values = np.concatenate([rng.normal(size=500) * 10.0 ** rng.integers(-12, 12, size=500), [0.1, 1 / 3, -0.0]])
    assert all(float(number(v)) == v for v in values)


@pytest.mark.parametrize("pitch", [0.3, np.pi / 2, -np.pi / 2, np.pi / 2 - 1e-9])
def test_rpy_round_trip(pitch: float) -> None:
    rng = np.random.default_rng(2)
    for _ in range(20):
        roll, yaw = rng.uniform(-np.pi, np.pi, size=2)
        rot = rpy_to_matrix(np.array([roll, pitch, yaw]))
        assert np.abs(rpy_to_matrix(matrix_to_rpy(rot)) - rot).max() < 1e-12
