"""Newton adapter against MuJoCo and Pinocchio: energy, mass matrix, inverse dynamics and segment states.

Newton computes in float32, so the agreement is asserted within Newton's declared precision
(:data:`koenig_check.engines.newton.PRECISION`), relative to each quantity's largest entry; the same comparisons
against MuJoCo are at 1e-12 for Drake (tests/engines/drake).  The models are batched: one Newton load per case,
one batched call per quantity.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import LoadedModel, load_model, random_states

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

from koenig_check.engines.newton import PRECISION
from koenig_check.engines.newton.attach import load_newton_engine

#: The repository: the test models below are named from it (their ids), and found from this file, wherever pytest runs.
ROOT = Path(__file__).resolve().parents[3]
#: (model, floating): project models in both formats and example-robot-data robots, fixed and floating.
NEWTON_CASES = [
    ("gimbal.xml", False),
    ("gimbal.urdf", True),
    ("double_pendulum.urdf", False),
    ("serial7.xml", False),
    ("serial7.urdf", False),
    ("serial7.urdf", True),
    ("free_body.xml", False),
    ("free_body.urdf", True),
    ("armature_chain.xml", False),
    ("tests/engines/models/ball_armature.xml", False),
    ("tests/models/tiebreak/hinge_ref.xml", False),
    ("ur5", False),
    ("ur5", True),
    ("solo12", True),
]


@cache
def _load(model: str, floating: bool) -> tuple[LoadedModel, object]:
    pair = load_model(str(ROOT / model) if model.startswith("tests/") else model, floating=floating, check=False)
    return pair, load_newton_engine(pair.source, pair.mujoco.model, floating)


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    """Largest difference relative to the largest entry of the reference (per quantity, not per entry)."""
    return float(np.abs(np.asarray(a) - np.asarray(b)).max() / max(np.abs(b).max(), 1e-300))


@pytest.fixture(params=NEWTON_CASES, ids=[f"{m}{'-floating' if f else ''}" for m, f in NEWTON_CASES])
def loaded(request: pytest.FixtureRequest):
    pair, newton = _load(*request.param)
    qpos, qvel = random_states(pair.mujoco.model, 6, seed=3)
    return pair, newton, qpos, qvel


@pytest.mark.parametrize("other", ["mujoco", "pinocchio"])
def test_dynamics_agree_within_newton_precision(loaded, other: str) -> None:
    pair, newton, qpos, qvel = loaded
    engine = pair.engines[other]
    qacc = np.random.default_rng(5).normal(size=qvel.shape)
    mine, theirs = newton.kinetic_energy(qpos, qvel), engine.kinetic_energy(qpos, qvel)
    scale = np.abs(theirs.rigid).max() + np.abs(theirs.armature).max()
    assert np.abs(mine.rigid - theirs.rigid).max() <= PRECISION * scale
    assert np.abs(mine.armature - theirs.armature).max() <= PRECISION * scale
    assert _rel(newton.mass_matrix(qpos), engine.mass_matrix(qpos)) <= PRECISION
    assert _rel(newton.inverse_dynamics(qpos, qvel, qacc), engine.inverse_dynamics(qpos, qvel, qacc)) <= PRECISION
    assert _rel(newton.armature_matrix(qpos), engine.armature_matrix(qpos)) <= PRECISION or not np.any(
        engine.armature_matrix(qpos)
    )


def test_segment_states_agree_within_newton_precision(loaded) -> None:
    pair, newton, qpos, qvel = loaded
    mine, theirs = newton.segment_states(qpos, qvel), pair.mujoco.segment_states(qpos, qvel)
    assert mine.names == theirs.names
    size = max(float(np.abs(theirs.com).max()), 1.0)
    for field in ("com", "pole", "com_ref", "pole_ref"):
        assert np.abs(getattr(mine, field) - getattr(theirs, field)).max() <= PRECISION * size, field
    for field in ("mass", "inertia_body", "v_com", "omega", "rotation", "rotation_ref"):
        assert _rel(getattr(mine, field), getattr(theirs, field)) <= PRECISION, field


def test_poses_are_batched_not_one_call_per_pose(monkeypatch: pytest.MonkeyPatch) -> None:
    """130 poses: two eval_fk calls (100 + 30 worlds), each answering for every pose of its batch."""
    import newton as newton_module

    pair, engine = _load("serial7.urdf", False)
    calls = []
    fk = newton_module.eval_fk
    monkeypatch.setattr(
        newton_module, "eval_fk", lambda model, *a, **k: calls.append(model.world_count) or fk(model, *a, **k)
    )
    qpos, qvel = random_states(pair.mujoco.model, 130, seed=1)
    states = engine.segment_states(qpos, qvel)
    assert calls == [100, 30]
    np.testing.assert_allclose(states.com, pair.mujoco.segment_states(qpos, qvel).com, atol=PRECISION)
