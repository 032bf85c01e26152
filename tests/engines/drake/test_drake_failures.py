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


#: A massless link with a non-zero inertia on a fixed joint (as example-robot-data's bolt's feet): Drake's URDF
#: parser warns with a failed C++ check, whose message names Drake's build tree.
MASSLESS_FOOT = """<robot name="foot">
  <link name="base"/>
  <link name="leg"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
  </inertial></link>
  <link name="foot"><inertial><origin xyz="0 0 -0.2"/><mass value="0"/>
    <inertia ixx="5.3e-07" iyy="5.7e-07" izz="8.4e-07" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hip" type="revolute"><parent link="base"/><child link="leg"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="ankle" type="fixed"><parent link="leg"/><child link="foot"/><origin xyz="0 0 -0.3"/></joint>
</robot>"""


def test_parser_warnings_have_no_build_path(tmp_path) -> None:
    path = tmp_path / "foot.urdf"
    path.write_text(MASSLESS_FOOT)
    check = koenig_check.compare(path, n_poses=2, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"])
    (comparison,) = check.comparisons
    warned = [f for f in comparison.findings if f.engine == "drake" and f.summary.startswith("parser warns")]
    assert warned, [f.message() for f in comparison.findings]
    for f in warned:
        assert "bazel-out" not in f.message() and "Failure at" not in f.message(), f.message()
    assert any("SetFromRotationalInertia(): condition 'mass > 0' failed" in f.summary for f in warned)
