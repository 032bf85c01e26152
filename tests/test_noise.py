"""Library noise: no MUJOCO_LOG.TXT left in the user's directory; no scipy gimbal-lock warning on grid runs."""

from __future__ import annotations

import subprocess
import sys
import warnings
from pathlib import Path

import koenig_check

NAN_MODEL = """<mujoco model="nan_mass">
  <worldbody>
    <body name="arm"><joint name="hinge" type="hinge"/><geom type="sphere" size="0.1" mass="nan"/></body>
  </worldbody>
</mujoco>
"""


def test_cli_leaves_no_mujoco_log_file_on_a_file_mujoco_warns_about(tmp_path: Path) -> None:
    model = tmp_path / "nan_mass.xml"
    model.write_text(NAN_MODEL, encoding="utf-8")
    proc = subprocess.run(
        [sys.executable, "-m", "koenig_check.cli", "compare", model.name],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )
    assert proc.returncode in (0, 1) and "nan_mass.xml" in proc.stdout + proc.stderr and "Traceback" not in proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["nan_mass.xml"]
    assert "XML contains a 'NaN'" not in proc.stderr  # routed to a logger, shown with --debug


def test_grid_run_over_the_gimbal_lock_emits_no_library_warning() -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check = koenig_check.compare(
            "gimbal.xml", pose_kind="grid", grid_joints=("outer_z", "inner_x"), n_poses=9, formulas=None
        )
    assert check.comparisons and not check.failures
    assert not [w for w in caught if "Gimbal lock" in str(w.message)]


def test_drake_ball_joint_at_pitch_90_degrees_is_silent_and_agrees(tmp_path: Path) -> None:
    """scipy warns 'Gimbal lock detected' there; the roll-pitch-yaw angles still give the same rotation."""
    import numpy as np
    import pytest
    from scipy.spatial.transform import Rotation

    pytest.importorskip("pydrake")
    qpos = np.array([[0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 0.4]], dtype=float)
    qpos[0, 7:11] = Rotation.from_euler("xyz", [0.3, np.pi / 2, 0.7]).as_quat(scalar_first=True)
    qvel = np.array([[0.1, -0.2, 0.3, 0.5, -0.4, 0.2, 1.0, -0.7, 0.4, 0.9]])
    poses = tmp_path / "gimbal_lock.npz"
    np.savez(poses, qpos=qpos, qvel=qvel)
    model = Path(__file__).parent / "data" / "free_ball_hinge.xml"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check = koenig_check.compare(model, pose_file=poses, engines="mujoco,pinocchio,drake")
    assert not [w for w in caught if "Gimbal lock" in str(w.message)]
    assert check.ok, check.reason()  # the three engines agree at the singular angles
