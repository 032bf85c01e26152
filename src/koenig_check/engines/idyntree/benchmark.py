"""iDynTree's bare loop for ``comparisons/benchmark.py``: what an iDynTree user runs to get the same numbers.

Per pose, ``KinDynComputations`` as its users call it: ``setRobotState`` (base pose, joint positions, base twist,
joint velocities), then each link's ``getWorldTransform`` and ``getFrameVel`` (its pose and twist, world frame),
and ``getFreeFloatingMassMatrix``, from which the kinetic energy ``½ νᵀ M ν`` (``KinDynComputations`` has no
kinetic-energy function).  No segments: the floor the adapter's sweep is measured against; the states are put in
iDynTree's ``(world_H_base, s, ν)`` by the state map first, as Newton's are put in its coordinates.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def bare_loop(engine: Any, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """Return iDynTree's kinetic energy of every pose by its own calls, one pose at a time.

    Parameters
    ----------
    engine : IDynTreeEngine
        A loaded adapter (its ``KinDynComputations`` is reused: loading is not what is measured).
    qpos, qvel : ndarray, shape (P, nq) and (P, nv)
        Canonical states.

    Returns
    -------
    ndarray, shape (P,)
    """
    import idyntree.swig as idt

    sm, kin_dyn = engine.state_map, engine.kin_dyn
    H, s = sm.base_pose(qpos), sm.joint_positions(qpos)
    nu = np.einsum("pij,pj->pi", sm.velocity_matrix(qpos), qvel)
    n, L = nu.shape[1], engine.model.getNrOfLinks()
    M, gravity = idt.MatrixDynSize(n, n), np.zeros(3)
    out = np.empty(qpos.shape[0])
    for k in range(qpos.shape[0]):
        kin_dyn.setRobotState(H[k], s[k], nu[k, :6], nu[k, 6:], gravity)
        for link in range(L):  # the poses and twists the check reads
            kin_dyn.getWorldTransform(link).getRotation().toNumPy()
            kin_dyn.getFrameVel(link).toNumPy()
        kin_dyn.getFreeFloatingMassMatrix(M)
        out[k] = 0.5 * nu[k] @ M.toNumPy() @ nu[k]
    return out
