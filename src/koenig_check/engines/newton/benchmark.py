"""Newton's bare loop for ``comparisons/benchmark.py``: what a Newton user runs to get the same numbers, batched.

The robot is replicated into :data:`~koenig_check.engines.newton.adapter.BATCH` worlds; per batch, one
``eval_fk`` (body poses and twists) and one ``eval_mass_matrix`` (M, from which the kinetic energy ``½ q̇ᵀ M q̇``).
No state map, no segments: the floor the adapter's cost is measured against.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def bare_loop(engine: Any, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """Newton's kinetic energy of every pose by its own batched calls, after the poses are in Newton's coordinates.

    Parameters
    ----------
    engine : NewtonEngine
        A loaded adapter (its Newton models are reused: loading is not what is measured).
    qpos, qvel : ndarray, shape (P, nq) and (P, nv)
        Canonical states.

    Returns
    -------
    ndarray, shape (P,)
    """
    import newton
    import warp as wp

    from koenig_check.engines.newton.adapter import BATCH

    q, qd, _, _ = engine.state_map.to_newton(qpos, qvel)
    out = np.empty(q.shape[0])
    for a in range(0, q.shape[0], BATCH):
        b = min(a + BATCH, q.shape[0])
        model = engine._world_model(b - a)
        state = model.state()
        jq = wp.array(q[a:b].reshape(-1).astype(np.float32), dtype=wp.float32, device="cpu")  # type: ignore[var-annotated]  # Warp's array types
        jqd = wp.array(qd[a:b].reshape(-1).astype(np.float32), dtype=wp.float32, device="cpu")  # type: ignore[var-annotated]  # Warp's array types
        newton.eval_fk(model, jq, jqd, state)
        H = engine._assemble(newton.eval_mass_matrix(model, state).numpy(), b - a)  # type: ignore[union-attr]  # Warp's array types
        out[a:b] = 0.5 * np.einsum("pi,pij,pj->p", qd[a:b], H, qd[a:b])
    return out
