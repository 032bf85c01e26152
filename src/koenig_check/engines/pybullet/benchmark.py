"""PyBullet's bare loop for ``comparisons/benchmark.py``: what a PyBullet user runs to get the same numbers.

Per pose, PyBullet's own calls as its users make them: ``resetJointStatesMultiDof`` (and ``resetBase*`` when the
base floats), then ``getBasePositionAndOrientation``, ``getBaseVelocity`` and one ``getLinkStates`` with
velocities for every link (each link's COM, principal axes, COM velocity and angular velocity, world frame).
PyBullet has no kinetic-energy function: its users sum ``½ m v_C² + ½ ω·I ω`` over the links with the masses and
principal moments ``getDynamicsInfo`` gives (read once, with the model).  No state map beyond PyBullet's own joint
order, no segments: the floor the adapter's sweep is measured against.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def bare_loop(engine: Any, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """PyBullet's kinetic energy of every pose by its own calls, one pose at a time.

    Parameters
    ----------
    engine : PyBulletEngine
        A loaded adapter (its PyBullet client and body are reused: loading is not what is measured).
    qpos, qvel : ndarray, shape (P, nq) and (P, nv)
        Canonical states.

    Returns
    -------
    ndarray, shape (P,)
    """
    from koenig_check.engines.pybullet.tree import quat_matrix

    p, client, body = engine.client.p, engine.client.id, engine.body
    sm, tree = engine.state_map, engine.tree
    q, v = sm.joints(qpos, qvel)
    base = sm.base_state(qpos, qvel) if sm.base is not None else None
    moving = [[k] for k in engine._joint_links]  # PyBullet's joint indices of the moving joints
    links = list(range(len(tree.link_names) - 1))
    P, L = qpos.shape[0], len(tree.link_names)
    quat, vel, omega = np.zeros((P, L, 4)), np.zeros((P, L, 3)), np.zeros((P, L, 3))
    for k in range(P):
        if moving:
            p.resetJointStatesMultiDof(
                body,
                engine._joint_links,
                [[x] for x in q[k]],
                targetVelocities=[[x] for x in v[k]],
                physicsClientId=client,
            )
        if base is not None:
            com, orientation, v_com, w = (x[k].tolist() for x in base)
            p.resetBasePositionAndOrientation(body, com, orientation, physicsClientId=client)
            p.resetBaseVelocity(body, v_com, w, physicsClientId=client)
        quat[k, 0] = p.getBasePositionAndOrientation(body, physicsClientId=client)[1]
        vel[k, 0], omega[k, 0] = p.getBaseVelocity(body, physicsClientId=client)
        if links:
            states = p.getLinkStates(
                body, links, computeLinkVelocity=1, computeForwardKinematics=1, physicsClientId=client
            )
            quat[k, 1:] = [s[1] for s in states]
            vel[k, 1:] = [s[6] for s in states]
            omega[k, 1:] = [s[7] for s in states]
    w_axes = np.einsum("plji,plj->pli", quat_matrix(quat), omega)  # ω in each link's principal axes
    return 0.5 * (
        np.einsum("l,pli,pli->p", tree.mass, vel, vel) + np.einsum("li,pli,pli->p", tree.principal, w_axes, w_axes)
    )
