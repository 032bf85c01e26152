"""Drake's pole (the joint's anchor on the child body) and its velocity, for anchors off the body origin.

The paper's formulas about the pole use its velocity; Drake's adapter gets it from the body origin's velocity
and the angular velocity.  Expected values from MuJoCo's own kinematics, independently of every adapter: the
anchor ``xpos + xmat · jnt_pos`` (the joint's ``pos`` as a point of the child body) and its velocity
``mj_jac(point) · q̇``.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.engines import load_model, random_states

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed: its tests are skipped")

MODELS = Path(__file__).resolve().parents[1] / "models"
#: A model whose joints sit off their body origins (hinges, a ball, a slide), and two whose joints do not.
CASES = ["offset_anchors.xml", "hinge_armature_offset.xml", "serial7.xml"]


def _anchors(m: mujoco.MjModel, qpos: np.ndarray, qvel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each joint's anchor on its child body and the anchor's world velocity, by MuJoCo's own Jacobian."""
    d = mujoco.MjData(m)
    jacp, jacr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
    pole, v_pole = np.zeros((len(qpos), m.njnt, 3)), np.zeros((len(qpos), m.njnt, 3))
    for p in range(len(qpos)):
        d.qpos[:] = qpos[p]
        mujoco.mj_forward(m, d)
        for k in range(m.njnt):
            b = int(m.jnt_bodyid[k])
            pole[p, k] = d.xpos[b] + d.xmat[b].reshape(3, 3) @ m.jnt_pos[k]
            mujoco.mj_jac(m, d, jacp, jacr, pole[p, k], b)
            v_pole[p, k] = jacp @ qvel[p]
    return pole, v_pole


@pytest.mark.parametrize("name", CASES)
def test_pole_and_its_velocity_are_mujocos_anchor_and_its_jacobian_velocity(name: str) -> None:
    pair = load_model(MODELS / name if (MODELS / name).exists() else name)
    drake = pair.attach("drake")
    m = pair.mujoco.model
    assert m.njnt == len(drake.segment_names)  # one joint per body: a segment per joint, in joint order
    qpos, qvel = random_states(m, 5, seed=11)
    states = drake.segment_states(qpos, qvel)
    pole, v_pole = _anchors(m, qpos, qvel)
    length = max(float(np.abs(pole).max()), 1.0)
    speed = max(float(np.abs(v_pole).max()), 1.0)
    assert np.abs(states.pole - pole).max() <= 1e-12 * length
    assert np.abs(states.v_pole - v_pole).max() <= 1e-12 * speed


def test_the_offset_model_has_its_anchors_off_the_body_origins() -> None:
    """What the case list claims: every joint of offset_anchors.xml is off its body's origin."""
    m = load_model(MODELS / "offset_anchors.xml").mujoco.model
    assert np.all(np.linalg.norm(m.jnt_pos, axis=1) > 0.01)
    kinds = {mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_BALL, mujoco.mjtJoint.mjJNT_SLIDE}
    assert set(m.jnt_type.tolist()) == {int(k) for k in kinds}
