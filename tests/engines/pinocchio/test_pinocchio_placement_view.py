"""Pinocchio's placements read whole through ``placement_view`` equal the bindings' per-joint ``homogeneous``."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from koenig_check.engines import load_model
from koenig_check.engines.pinocchio.placements import placement_view
from koenig_check.run.poses import random_poses

FREE_BALL_HINGE = Path(__file__).resolve().parents[2] / "data" / "free_ball_hinge.xml"
MODELS = Path(__file__).resolve().parents[3] / "models"
CASES = [FREE_BALL_HINGE, MODELS / "serial7.urdf", MODELS / "armature_chain.xml", "ur5", "a1"]  # a1: joints reordered


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_view_follows_every_joint_placement(model) -> None:
    pm = load_model(model).pinocchio.model
    data = pm.createData()
    view = placement_view(pm, data)
    assert view is not None, "the layout check refused Pinocchio's own storage: the sweep reads joints one by one"
    assert view.shape == (pm.njoints, 12)
    rng = np.random.default_rng(7)
    for _ in range(5):
        q = pin.integrate(pm, pin.neutral(pm), rng.uniform(-2.0, 2.0, pm.nv))
        pin.forwardKinematics(pm, data, q)
        for i, M in enumerate(data.oMi.tolist()):
            H = M.homogeneous
            np.testing.assert_array_equal(view[i, :9].reshape(3, 3).T, H[:3, :3], err_msg=f"joint {i} rotation")
            np.testing.assert_array_equal(view[i, 9:], H[:3, 3], err_msg=f"joint {i} translation")


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_sweep_placements_equal_forward_kinematics_joint_by_joint(model) -> None:
    pair = load_model(model)
    eng = pair.pinocchio
    poses = random_poses(pair.mujoco.model, 30, seed=5)
    states, _, _, _ = eng.sweep(poses.qpos, poses.qvel)
    q, _ = pair.state_map.to_pinocchio(poses.qpos, poses.qvel)
    H, _ = eng._sweep(q, None)  # forwardKinematics, then each joint's homogeneous placement
    np.testing.assert_array_equal(states.rotation, H[..., :3, :3])
    np.testing.assert_array_equal(states.pole, H[..., :3, 3])


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_sweep_without_the_view_gives_the_same_states(model) -> None:
    pair = load_model(model)
    eng = pair.pinocchio
    poses = random_poses(pair.mujoco.model, 30, seed=6)
    fast = eng.sweep(poses.qpos, poses.qvel)
    fast_public = eng.segment_states(poses.qpos, poses.qvel)
    eng._placement_views = (None, None)  # the route of a Pinocchio whose layout the check refuses
    slow = eng.sweep(poses.qpos, poses.qvel)
    slow_public = eng.segment_states(poses.qpos, poses.qvel)
    for name in ("com", "v_com", "rotation", "omega", "pole", "v_pole"):
        np.testing.assert_array_equal(getattr(fast[0], name), getattr(slow[0], name), err_msg=name)
        np.testing.assert_array_equal(getattr(fast_public, name), getattr(slow_public, name), err_msg=name)
    np.testing.assert_array_equal(fast[2], slow[2])


@pytest.mark.parametrize("how", ["pickle", "deepcopy"])
def test_a_copied_engine_reads_its_own_placements(how: str) -> None:
    import copy
    import pickle

    pair = load_model(FREE_BALL_HINGE)
    eng = pair.pinocchio
    clone = pickle.loads(pickle.dumps(eng)) if how == "pickle" else copy.deepcopy(eng)
    poses = random_poses(pair.mujoco.model, 20, seed=8)
    q, _ = pair.state_map.to_pinocchio(poses.qpos, poses.qvel)
    H, _ = eng._sweep(q, None)  # forwardKinematics, then each joint's homogeneous placement
    for engine in (clone, eng):
        states, _, _, _ = engine.sweep(poses.qpos, poses.qvel)
        np.testing.assert_array_equal(states.rotation, H[..., :3, :3])
        np.testing.assert_array_equal(states.pole, H[..., :3, 3])
        np.testing.assert_array_equal(engine.segment_states(poses.qpos, poses.qvel).rotation, H[..., :3, :3])


@pytest.mark.parametrize("checked_before", [False, True], ids=["fresh data", "data checked before"])
def test_a_view_that_does_not_follow_the_data_is_refused(checked_before: bool, monkeypatch) -> None:
    """A snapshot of the placements (bindings handing out copies) must not pass for a view of the data.

    With ``checked_before`` the data already holds the check's first configuration (as an engine's data
    does after its own check, and after pickling): a snapshot then matches one configuration.
    """
    pm = load_model(MODELS / "serial7.urdf").pinocchio.model
    data = pm.createData()
    if checked_before:
        assert placement_view(pm, data) is not None
    strided = np.lib.stride_tricks.as_strided
    monkeypatch.setattr(np.lib.stride_tricks, "as_strided", lambda *a, **k: strided(*a, **k).copy())
    assert placement_view(pm, data) is None
