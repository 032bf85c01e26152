"""Drake's failed C++ checks (pydrake raises SystemExit): Drake's reason whole, no build path, no run ended."""

from __future__ import annotations

import numpy as np
import pytest

import koenig_check
from koenig_check.findings import Kind

plant_module = pytest.importorskip("pydrake.multibody.plant")

CONDITION = "SetPositions(): condition 'q.size() == num_positions()' failed."


def _fail_a_drake_check(*args: object, **kwargs: object) -> None:
    """Ask Drake for something it refuses with a failed C++ check (its own SystemExit)."""
    plant = plant_module.MultibodyPlant(0.0)
    plant.Finalize()
    plant.SetPositions(plant.CreateDefaultContext(), np.zeros(3))


def test_a_failed_check_at_run_time_is_a_runtime_error_with_drakes_reason() -> None:
    from koenig_check.engines.drake.failures import drake_failures_raised

    with pytest.raises(RuntimeError) as info:
        drake_failures_raised(_fail_a_drake_check)()
    assert str(info.value) == f"Drake: {CONDITION}"


def test_a_failed_check_at_load_time_is_drakes_reason_and_the_batch_goes_on(monkeypatch: pytest.MonkeyPatch) -> None:
    import koenig_check.engines.drake.building as building

    monkeypatch.setattr(building, "load_drake_engine", _fail_a_drake_check)
    check = koenig_check.compare(
        ["gimbal.xml", "double_pendulum.xml"], n_poses=2, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"]
    )
    assert [c.model for c in check.comparisons] == ["gimbal.xml", "double_pendulum.xml"] and not check.failures
    for comparison in check.comparisons:
        (unable,) = [f for f in comparison.findings if f.kind is Kind.ENGINE_UNABLE]
        assert unable.summary.endswith(f"Drake cannot load the model: {CONDITION}")
        assert "bazel-out" not in unable.message()
