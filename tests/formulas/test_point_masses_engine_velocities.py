"""point_masses reads the point velocities the engine gives the comparison, not ones it recomputes.

The grid's point velocities of every segment are shifted by a known vector u; eq. (10) over the
six equimomental points (total mass m, centre of mass C) then moves by exactly
m u·v_C + ½ m |u|², with v_C the engine's own centre-of-mass velocity.
"""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.demo import builtin_models
from koenig_check.engines import load_model
from koenig_check.run import chunks, engine_runs
from koenig_check.run.poses import random_poses


def _segment_records(chunk: chunks.ChunkResult, engine: str) -> dict[tuple[str, str], float]:
    rows = chunk.records.to_pylist()
    return {
        (r["pose"], r["scope"]): r["value"]
        for r in rows
        if r["formula"] == "point_masses" and r["source"] == engine and r["reference"] == f"exact@{engine}"
    }


@pytest.mark.parametrize("model", ["gimbal.xml", "serial7.urdf"])
def test_point_masses_record_moves_by_the_shift_of_the_given_point_velocities(model: str) -> None:
    path = next(p for p in builtin_models() if p.name == model)
    pair = load_model(path)
    poses = random_poses(pair.mujoco.model, 4, seed=3)
    runs = {e.engine: engine_runs.run_engine(e, poses) for e in pair.engines.values()}
    base = chunks.evaluate_chunk(model, poses, runs, ["point_masses"], records="segments")
    rng = np.random.default_rng(11)
    for engine, run in runs.items():
        states = run.states
        u = rng.normal(size=(states.n_poses, states.n_segments, 3))
        shifted = dict(runs)
        shifted[engine] = engine_runs.EngineRun(
            run.engine, states, run.rigid, run.armature, run.point_velocities + u[:, :, None, :]
        )
        moved = chunks.evaluate_chunk(model, poses, shifted, ["point_masses"], records="segments")
        before, after = _segment_records(base, engine), _segment_records(moved, engine)
        assert len(before) == states.n_poses * states.n_segments
        for p, pose in enumerate(poses.ids):
            for b, seg in enumerate(states.names):
                m = states.mass[b]
                expected = m * u[p, b] @ states.v_com[p, b] + 0.5 * m * u[p, b] @ u[p, b]
                np.testing.assert_allclose(after[(pose, seg)] - before[(pose, seg)], expected, rtol=1e-9)
