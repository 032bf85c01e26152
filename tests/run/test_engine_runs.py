"""The equimomental points each chunk's sweep uses are kept per set of mass properties, never mixed up."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines import load_model
from koenig_check.formulas.point_masses import equimomental_points
from koenig_check.run.engine_runs import _points_for

MODELS = Path(__file__).resolve().parents[2] / "models"


def _direct(engine) -> np.ndarray:
    return equimomental_points(engine._mass, engine._inertia, engine.segment_names)[0]


def test_points_follow_the_engine_and_its_mass_properties() -> None:
    a = load_model(MODELS / "serial7.urdf")
    b = load_model(MODELS / "armature_chain.xml")
    engines = [a.mujoco, b.mujoco, a.pinocchio, b.pinocchio]
    for _ in range(2):  # the second round is served from the kept points
        for engine in engines:
            np.testing.assert_array_equal(_points_for(engine), _direct(engine))
    engine = b.pinocchio
    engine._inertia = engine._inertia * 2.0  # other mass properties, same engine object
    np.testing.assert_array_equal(_points_for(engine), _direct(engine))
    engine._mass = engine._mass * 3.0
    np.testing.assert_array_equal(_points_for(engine), _direct(engine))


def test_a_non_physical_inertia_has_no_points() -> None:
    engine = load_model(MODELS / "serial7.urdf").mujoco
    engine._inertia = engine._inertia.copy()
    engine._inertia[0] = np.diag([1.0, 1.0, 5.0])  # violates A + B >= C
    assert _points_for(engine) is None
    assert _points_for(engine) is None
