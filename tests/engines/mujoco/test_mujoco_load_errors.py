"""MuJoCo's compile errors reach the user whole, on one line, naming the file.

(Pinocchio's parse errors: ``tests/engines/pinocchio/test_pinocchio_load_errors.py``.)
"""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.engines import ModelLoadError, load_model


def test_mujoco_compile_error_is_whole_on_one_line(tmp_path: Path) -> None:
    path = tmp_path / "bad.xml"
    path.write_text("<mujoco><worldbody><body name='b'><joint type='nonsense'/></body></worldbody></mujoco>")
    with pytest.raises(ModelLoadError) as info:
        load_model(path)
    msg = str(info.value)
    assert "\n" not in msg and str(path) in msg and "nonsense" in msg and "line" in msg
