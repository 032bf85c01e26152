"""The two-link arm of the gravity tests, written here, and its gravity terms by hand.

Both links lie along their body's x axis and turn about y: ``u(θ) = (cos θ, 0, -sin θ)`` is a link's direction
after a turn θ (MuJoCo's and Pinocchio's right-handed rotation about y), so the COMs are
``c1 = a1 u(q1)`` and ``c2 = L1 u(q1) + a2 u(q1 + q2)``.  With gravity ``G`` in the arm's mount frame,
``V = -Σ m G·c`` and ``g_i = ∂V/∂q_i = -Σ m G·∂c/∂q_i``.  On a free base (position ``p``, rotation ``R``) the
same formulas hold with ``R^T G``; the base rows are ``-M G`` (world force) and ``-R^T Σ (c - p) × m G``
(torque about the base origin in the base's axes, MuJoCo's free-joint convention).
"""

from __future__ import annotations

import numpy as np

from koenig_check.engines import load_model
from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.registry import installed

M1, A1, L1 = 2.0, 0.5, 1.0
M2, A2 = 1.0, 0.4
M0, C0 = 3.0, np.array([0.1, 0.0, -0.05])  # the free base's mass and COM in its own axes

ARM = """
    <body name="upper" pos="0 0 0">
      <joint name="shoulder" type="hinge" axis="0 1 0"{spring}/>
      <inertial pos="0.5 0 0" mass="2" diaginertia="0.01 0.2 0.2"/>
      <body name="fore" pos="1 0 0">
        <joint name="elbow" type="hinge" axis="0 1 0"{spring}/>
        <inertial pos="0.4 0 0" mass="1" diaginertia="0.005 0.06 0.06"/>
      </body>
    </body>"""


def arm_xml(option: str = "", free: bool = False, spring: str = "", extra: str = "") -> str:
    """The arm as MJCF: ``option`` inside ``<mujoco>``, on a free base when ``free``, ``spring`` on each joint."""
    arm = ARM.format(spring=spring)
    if free:
        arm = (
            '<body name="base" pos="0.3 -0.2 1.5"><freejoint name="root"/>'
            '<inertial pos="0.1 0 -0.05" mass="3" diaginertia="0.1 0.1 0.1"/>' + arm + "</body>"
        )
    return f'<mujoco model="arm"><compiler angle="radian"/>{option}<worldbody>{extra}{arm}</worldbody></mujoco>'


def _u(t: np.ndarray) -> np.ndarray:
    return np.stack([np.cos(t), np.zeros_like(t), -np.sin(t)], axis=-1)


def _du(t: np.ndarray) -> np.ndarray:
    return np.stack([-np.sin(t), np.zeros_like(t), -np.cos(t)], axis=-1)


def arm_points(q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """COMs (P, 2, 3) in the mount frame and their derivatives by q1 and q2 (each (P, 2, 3))."""
    q1, q12 = q[:, 0], q[:, 0] + q[:, 1]
    c = np.stack([A1 * _u(q1), L1 * _u(q1) + A2 * _u(q12)], axis=1)
    d1 = np.stack([A1 * _du(q1), L1 * _du(q1) + A2 * _du(q12)], axis=1)
    d2 = np.stack([np.zeros_like(d1[:, 0]), A2 * _du(q12)], axis=1)
    return c, d1, d2, np.array([M1, M2])


def fixed_gravity(q: np.ndarray, G: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``g(q)`` (P, 2) and ``V(q)`` (P,) of the fixed arm by hand."""
    c, d1, d2, m = arm_points(q)
    g = -np.stack([np.einsum("b,pbi,i->p", m, d, G) for d in (d1, d2)], axis=1)
    return g, -np.einsum("b,pbi,i->p", m, c, G)


def _rotation(quat: np.ndarray) -> np.ndarray:
    w, x, y, z = quat / np.linalg.norm(quat)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def free_gravity(qpos: np.ndarray, G: np.ndarray) -> np.ndarray:
    """``g(q)`` (P, 8) of the arm on a free base by hand, canonical (MuJoCo) free-joint coordinates."""
    out = np.empty((qpos.shape[0], 8))
    for p, row in enumerate(qpos):
        R = _rotation(row[3:7])
        local = R.T @ G
        g_arm, _ = fixed_gravity(row[None, 7:9], local)
        c, _, _, m = arm_points(row[None, 7:9])
        arms = np.vstack([C0, c[0]])  # base COM then link COMs, in the base's axes
        masses = np.concatenate([[M0], m])
        out[p, :3] = -masses.sum() * G
        out[p, 3:6] = -np.sum(np.cross(arms, masses[:, None] * local), axis=0)
        out[p, 6:] = g_arm[0]
    return out


def engines_of(path: object):
    """The model loaded in MuJoCo, Pinocchio and, where installed, Drake (a ``LoadedModel``)."""
    loaded = load_model(str(path), LoadOptions())
    if installed("drake"):
        loaded.attach("drake")
    return loaded
