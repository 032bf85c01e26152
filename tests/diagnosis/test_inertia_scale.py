"""A segment's inertia difference is measured against its inertia about the anchor that moves it.

Drake's ``examples/pendulum/Pendulum.urdf`` is two point masses on one line: no central moment of its own.
``--repair-inertia`` gives MuJoCo's link moments of 2e-15 kg m² (its bound); Pinocchio and Drake keep zero.
Against the link's own (zero) moments that is a 100 % difference and three engines said "MuJoCo departs"
while every energy agreed to 1e-14; against the link's inertia about its hinge, m l² = 0.25 kg m², it is 1e-14.
A real inertia difference on a lever still counts: the same model with one moment of 1e-3 kg m² in the file
that the engines read alike agrees, and dm_control's cartpole (a class mass Pinocchio does not apply) differs.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

import koenig_check
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.engines import load_model
from koenig_check.findings import Kind

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "engines" / "mujoco"))
from test_compiling import PENDULUM

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"


@pytest.fixture
def pendulum(tmp_path: Path) -> Path:
    path = tmp_path / "point_pendulum.urdf"
    path.write_text(PENDULUM, encoding="utf-8")
    return path


def test_a_repaired_point_mass_moment_is_not_an_import_difference(pendulum: Path) -> None:
    pair = load_model(pendulum, repair_inertia=True)
    report = import_parity(pair)
    (arm,) = report.segments  # the segment the hinge theta moves
    assert arm.inertia_frobenius > 0 and "inertia" not in arm.causes  # MuJoCo's 2e-15 moments, 1e-14 of m l²
    assert arm.relative["inertia"] <= 1e-13


def test_three_engines_agree_on_the_repaired_point_pendulum(pendulum: Path) -> None:
    pytest.importorskip("pydrake")
    check = koenig_check.compare(
        pendulum, repair_inertia=True, n_poses=4, formulas=["exact"], engines=("mujoco", "pinocchio", "drake")
    )
    verdicts = [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]
    assert check.ok and not verdicts, check.reason()


def test_a_real_inertia_difference_still_departs() -> None:
    pytest.importorskip("pydrake")
    check = koenig_check.compare(
        CAUSES / "class_mass.xml", n_poses=4, formulas=["exact"], engines=("mujoco", "pinocchio", "drake")
    )
    moments = [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT and "principal moments" in f.element]
    assert not check.ok and [f.engine for f in moments] == ["pinocchio"]
