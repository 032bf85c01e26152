"""What the dynamics check tells about an engine that departs: the norm-relative error and the worst entry by name.

One entry of Pinocchio's mass matrix (and its mirror) is moved by ``δ`` at one pose.  Expected values by hand
from MuJoCo's own ``mj_fullM``: the engines' mass matrices then differ by ``‖Δ‖_F / ‖M + Δ‖_F`` (Frobenius
norms, relative to Pinocchio's) at that pose and nothing at the others, and the worst entry is the one moved,
named by its two joints.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from koenig_check.engines.pinocchio.adapter import PinocchioEngine
from koenig_check.implied_dynamics.analysis import ENGINE_PARITY, dynamics

POSES, MOVED_POSE = 3, 1


@pytest.mark.parametrize(
    ("model", "entry"),
    [("serial7.xml", (1, 4)), ("serial7.xml", (6, 6)), ("gimbal.xml", (0, 1)), ("double_pendulum.xml", (1, 1))],
)
def test_the_engines_mass_matrices_differ_by_the_frobenius_norm_at_the_moved_entry(monkeypatch, model, entry):
    i, j = entry
    delta = 1e-4
    original = PinocchioEngine.mass_matrix

    def moved(self, qpos):
        M = np.array(original(self, qpos))
        M[MOVED_POSE, i, j] += delta
        if i != j:
            M[MOVED_POSE, j, i] += delta
        return M

    monkeypatch.setattr(PinocchioEngine, "mass_matrix", moved)
    result = dynamics(model, n_poses=POSES, formulas=["exact"])
    (parity,) = [
        e for e in result.errors if e.formula == ENGINE_PARITY and e.quantity == "M" and e.engine == "pinocchio"
    ]

    m = mujoco.MjModel.from_xml_path(str(result.model))
    d = mujoco.MjData(m)
    d.qpos[:] = result.qpos[MOVED_POSE]
    mujoco.mj_forward(m, d)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    full -= np.diag(m.dof_armature)  # the rigid mass matrix, as both engines' references are
    change = np.zeros_like(full)
    change[i, j] = change[j, i] = delta
    expected = np.linalg.norm(change) / np.linalg.norm(full + change)  # relative to Pinocchio's, the reference

    assert parity.rel_error[MOVED_POSE] == pytest.approx(expected, rel=1e-6)
    assert np.all(np.delete(parity.rel_error, MOVED_POSE) <= 1e-12)
    assert (parity.max_pose, parity.worst_pose, parity.worst_entry) == (MOVED_POSE, MOVED_POSE, (i, j))
    assert parity.worst_entry_error == pytest.approx(-delta, rel=1e-6)  # MuJoCo's minus Pinocchio's
    assert set(m.jnt_type.tolist()) == {int(mujoco.mjtJoint.mjJNT_HINGE)}  # hinge-only models: dof k is joint k
    names = (m.joint(i).name, m.joint(j).name)
    assert not result.ok
    assert f"worst entry {names[0]},{names[1]} " in result.reason()
