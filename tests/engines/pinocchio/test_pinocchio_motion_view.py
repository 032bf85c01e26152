"""Pinocchio's velocities read whole through ``motion_view``, and the states built from them.

The states' world velocities come from ``data.v`` rotated to the world; an independent route, the world
Jacobian of every joint summed over its supporting dofs (``computeJointJacobians``), gives the same twists
within round-off.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from koenig_check.engines import load_model
from koenig_check.engines.pinocchio.placements import motion_view
from koenig_check.run.poses import random_poses

FREE_BALL_HINGE = Path(__file__).resolve().parents[2] / "data" / "free_ball_hinge.xml"
MODELS = Path(__file__).resolve().parents[3] / "models"
CASES = [FREE_BALL_HINGE, MODELS / "serial7.urdf", MODELS / "armature_chain.xml", "ur5", "a1"]  # a1: joints reordered


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_view_follows_every_joint_velocity(model) -> None:
    pm = load_model(model).pinocchio.model
    data = pm.createData()
    view = motion_view(pm, data)
    assert view is not None, "the layout check refused Pinocchio's own storage: the sweep reads joints one by one"
    assert view.shape == (pm.njoints, 6)
    rng = np.random.default_rng(9)
    for _ in range(5):
        q = pin.integrate(pm, pin.neutral(pm), rng.uniform(-2.0, 2.0, pm.nv))
        pin.forwardKinematics(pm, data, q, rng.normal(size=pm.nv))
        for i, motion in enumerate(data.v.tolist()):
            np.testing.assert_array_equal(view[i], motion.vector, err_msg=f"joint {i}")


def test_a_view_that_does_not_follow_the_data_is_refused(monkeypatch) -> None:
    pm = load_model(MODELS / "serial7.urdf").pinocchio.model
    data = pm.createData()
    strided = np.lib.stride_tricks.as_strided
    monkeypatch.setattr(np.lib.stride_tricks, "as_strided", lambda *a, **k: strided(*a, **k).copy())
    assert motion_view(pm, data) is None


def _jacobian_twists(eng, q: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per pose and segment, (ω, velocity of the joint origin) from the world Jacobians, summed over supports."""
    m, d = eng.model, eng.model.createData()
    omega, v_pole = [], []
    for q_p, v_p in zip(q, v, strict=True):
        pin.computeJointJacobians(m, d, q_p)
        w_p, o_p = [], []
        for i in eng._joints:
            columns = np.zeros(m.nv, dtype=bool)
            for j in m.supports[int(i)]:
                if j > 0:
                    columns[m.idx_vs[j] : m.idx_vs[j] + m.nvs[j]] = True
            twist = np.asarray(d.J).reshape(6, m.nv)[:, columns] @ v_p[columns]  # (v_O, ω), world frame
            origin = d.oMi[int(i)].translation
            w_p.append(twist[3:])
            o_p.append(twist[:3] + np.cross(twist[3:], origin))
        omega.append(w_p)
        v_pole.append(o_p)
    return np.array(omega), np.array(v_pole)


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_velocities_from_data_v_equal_the_world_jacobians_within_round_off(model) -> None:
    pair = load_model(model)
    eng = pair.pinocchio
    poses = random_poses(pair.mujoco.model, 20, seed=11)
    states, _, _, _ = eng.sweep(poses.qpos, poses.qvel)
    q, v = pair.state_map.to_pinocchio(poses.qpos, poses.qvel)
    omega, v_pole = _jacobian_twists(eng, q, v)
    for name, expected in (("omega", omega), ("v_pole", v_pole)):
        scale = np.abs(expected).max()
        np.testing.assert_allclose(getattr(states, name), expected, rtol=0, atol=1e-13 * scale, err_msg=name)
    lever = states.com - states.pole
    np.testing.assert_allclose(
        states.v_com, v_pole + np.cross(omega, lever), rtol=0, atol=1e-13 * np.abs(v_pole).max(), err_msg="v_com"
    )


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_sweep_without_the_motion_view_gives_the_same_states(model) -> None:
    pair = load_model(model)
    eng = pair.pinocchio
    poses = random_poses(pair.mujoco.model, 30, seed=12)
    fast = eng.sweep(poses.qpos, poses.qvel)
    eng._motion_views = (None, None)  # the route of a Pinocchio whose layout the check refuses
    slow = eng.sweep(poses.qpos, poses.qvel)
    for name in ("com", "v_com", "rotation", "omega", "pole", "v_pole"):
        np.testing.assert_array_equal(getattr(fast[0], name), getattr(slow[0], name), err_msg=name)
    np.testing.assert_array_equal(fast[2], slow[2])
