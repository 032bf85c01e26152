"""PyBullet's declared precision (1e-7: it diagonalizes every inertia) is part of every verdict: its round-off is
never called a departure, and a difference above it always is."""

from __future__ import annotations

import numpy as np
import pytest

import koenig_check
from koenig_check.diagnosis.three_way import _departing
from koenig_check.findings import Kind

pytest.importorskip("pybullet")


@pytest.mark.parametrize(("offset", "departs"), [(5e-8, False), (5e-7, True)])
def test_round_off_below_the_precision_is_agreement(offset: float, departs: bool) -> None:
    values = {e: np.array([2.0]) for e in ("mujoco", "pinocchio", "idyntree")}
    values["pybullet"] = np.array([2.0 * (1 + offset)])
    assert _departing(values, 1e-9) == (("pybullet",) if departs else None)


def test_an_engine_of_finer_precision_departs_by_the_same_round_off() -> None:
    values = {e: np.array([2.0]) for e in ("mujoco", "pinocchio", "pybullet")}
    values["idyntree"] = np.array([2.0 * (1 + 5e-8)])  # iDynTree declares 1e-12
    assert _departing(values, 1e-9) == ("idyntree",)


def test_pandas_diagonalized_inertias_are_no_departure() -> None:
    """panda's link1 inertia comes back from PyBullet's principal axes 1e-9 off (measured): within its precision."""
    check = koenig_check.compare("panda", n_poses=2, formulas=["exact"], engines=("mujoco", "pinocchio", "pybullet"))
    assert check.ok and not [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]
