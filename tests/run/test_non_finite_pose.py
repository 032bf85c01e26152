"""A non-finite energy names the pose it happens at, not the chunk's first pose."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import koenig_check


def test_the_pose_with_a_non_finite_energy_is_the_one_named(tmp_path: Path) -> None:
    """Rates of 1e160 overflow ½ m v² on the third row only (gimbal.xml: two hinges, qpos then qvel per row)."""
    path = tmp_path / "poses.csv"
    rows = np.array([[0.1, 0.2, 1.0, 2.0], [0.0, 0.3, 1.0, 2.0], [0.1, 0.2, 1e160, 1e160]])
    np.savetxt(path, rows, delimiter=",")
    with np.errstate(over="ignore", invalid="ignore"):
        check = koenig_check.compare(["gimbal.xml"], pose_file=path)
    assert not check.ok
    assert "non-finite rigid energy at pose file-2" in check.reason(), check.reason()


def _runs_of(model: str = "ur5", n: int = 12):
    from koenig_check.engines import load_model
    from koenig_check.run.engine_runs import run_engine
    from koenig_check.run.poses import random_pose_range

    pair = load_model(model)
    poses = random_pose_range(pair.mujoco.model, 0, n, 0, 1.0)
    return poses, {name: run_engine(e, poses) for name, e in pair.engines.items()}


def test_a_nan_in_one_state_array_names_its_field_and_pose() -> None:
    """The check sums each array first; a NaN there still leads to the field, the segment and the pose."""
    import pytest

    from koenig_check.run.pipeline import _check_finite

    poses, runs = _runs_of()
    _check_finite("ur5", runs, poses)  # finite: no error
    omega = runs["pinocchio"].states.omega
    omega[7, 2, 1] = np.nan
    with pytest.raises(ValueError, match="pinocchio gives a non-finite omega for segment") as err:
        _check_finite("ur5", runs, poses)
    assert str(err.value).endswith(f"at pose {poses.ids[7]}")


def test_finite_values_whose_sum_overflows_pass() -> None:
    from koenig_check.run.pipeline import _check_finite

    poses, runs = _runs_of()
    runs["mujoco"].rigid[:] = 1e308  # finite, but their sum is not
    _check_finite("ur5", runs, poses)
