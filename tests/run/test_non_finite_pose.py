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
