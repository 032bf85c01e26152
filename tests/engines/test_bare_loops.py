"""Each new engine's bare loop (``engines/<name>/benchmark.py``, the benchmark's floor) computes the robot's kinetic
energy: MuJoCo's, on the same canonical states, within the engine's declared precision."""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.specs import spec
from koenig_check.run.poses import random_poses
from named_engines import NEW_ENGINES, named


@pytest.mark.parametrize(
    ("model", "floating"), [("serial7.urdf", False), ("serial7.urdf", True), ("gimbal.urdf", True)]
)
@pytest.mark.parametrize("engine", [named(e) for e in NEW_ENGINES])
def test_the_bare_loop_gives_mujocos_energy(engine: str, model: str, floating: bool) -> None:
    pair = load_model(model, LoadOptions(engines=("mujoco", "pinocchio", engine), floating=floating), check=False)
    poses = random_poses(pair.mujoco.model, 6, seed=3)
    bare_loop = importlib.import_module(f"koenig_check.engines.{engine}.benchmark").bare_loop
    energy = bare_loop(pair.engine(engine), poses.qpos, poses.qvel)
    reference = pair.mujoco.kinetic_energy(poses.qpos, poses.qvel).rigid
    assert energy.shape == reference.shape and np.all(reference > 0)
    assert np.max(np.abs(energy - reference) / reference) <= spec(engine).precision
