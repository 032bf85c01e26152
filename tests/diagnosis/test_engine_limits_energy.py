"""A construct an optional engine's parser skips makes it no voter only where it changes the robot it reads.

A ``<frame>`` that holds world geoms only (a table under the robot) is skipped by Drake's MJCF parser, as by
Pinocchio's, with nothing of the moving robot lost: Drake checks the same robot, so naming Drake
(``--engines mujoco,pinocchio,drake``) must not fail the model as a check Drake could not make.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.engines import load_model, random_states
from koenig_check.findings import Kind

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed")

MODEL = Path(__file__).resolve().parents[1] / "models" / "harmless" / "frame_static_geom.xml"
ALL = ("mujoco", "pinocchio", "drake")


def test_drake_reads_the_same_robot_as_mujoco() -> None:
    """Independent: Drake's CalcMassMatrix against MuJoCo's mj_fullM at random states."""
    pair = load_model(MODEL)
    drake = pair.attach("drake")
    m = pair.mujoco.model
    d = mujoco.MjData(m)
    qpos, _ = random_states(m, 4, seed=5)
    for q in qpos:
        d.qpos[:] = q
        mujoco.mj_forward(m, d)
        full = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, full)
        assert np.abs(drake.mass_matrix(q[None])[0] - full).max() <= 1e-12 * np.abs(full).max()
    skipped = [f for f in pair.optional_findings if f.kind is Kind.IGNORED_CONSTRUCT and f.engine == "drake"]
    assert skipped and not any(f.affects_energy for f in skipped)  # the frame is named, as changing nothing


def test_naming_drake_checks_the_model_and_passes(capsys: pytest.CaptureFixture[str]) -> None:
    check = koenig_check.compare(MODEL, n_poses=3, formulas=["exact"], engines=ALL)
    findings = check.comparisons[0].findings
    assert not [f.message() for f in findings if f.kind in (Kind.ENGINE_UNABLE, Kind.VERDICT)]
    assert check.ok, check.reasons()
    argv = ["parity", str(MODEL), "--engines", "mujoco,pinocchio,drake"]
    assert main(argv) == 0
    assert "cannot check" not in capsys.readouterr().out
