"""Shared models and states of the dynamics tests (imported by conftest and the tests)."""

from __future__ import annotations

import numpy as np

from koenig_check.engines import LoadedModel, random_states

# Free root, a ball joint, a body with three joints (hinge with ref, slide, hinge on a tilted axis
# with an offset anchor: a Pinocchio composite), armature on several dofs, a welded child body,
# non-diagonal inertias everywhere; springs, dampers, friction loss and a limit that inverse dynamics must leave out.
MIXED_JOINTS_MJCF = """
<mujoco model="mixed_joints">
  <compiler angle="radian"/>
  <worldbody>
    <body name="torso" pos="0 0 1">
      <freejoint name="root"/>
      <inertial pos="0.05 0.02 -0.03" mass="3" fullinertia="0.06 0.08 0.05 0.004 -0.002 0.003"/>
      <body name="upper" pos="0.2 0 0" quat="0.95 0.1 0.2 0.2">
        <joint name="shoulder" type="ball" armature="0.03" damping="0.4" frictionloss="0.2"/>
        <inertial pos="0 0.12 0.02" mass="1.2" fullinertia="0.02 0.01 0.025 0.002 0.001 -0.003"/>
        <body name="lower" pos="0 0.25 0">
          <joint name="elbow_x" type="hinge" axis="1 0 0" ref="0.2" armature="0.01" stiffness="5" springref="0.5"
                 damping="0.3" frictionloss="0.1" limited="true" range="-0.5 1.5"/>
          <joint name="elbow_slide" type="slide" axis="0 1 0"/>
          <joint name="elbow_tilt" type="hinge" axis="0 0.6 0.8" pos="0 0.03 0"/>
          <inertial pos="0.01 0.1 -0.02" mass="0.8" fullinertia="0.01 0.004 0.011 0.001 -0.0005 0.0008"/>
          <body name="hand" pos="0 0.22 0" euler="0.3 0.1 -0.2">
            <inertial pos="0 0.03 0" mass="0.3" diaginertia="0.001 0.0008 0.0012"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

SEED = 20261121


def states_with_accelerations(pair: LoadedModel, n: int, seed: int = SEED) -> tuple[np.ndarray, ...]:
    """Seeded random canonical states and accelerations."""
    qpos, qvel = random_states(pair.mujoco.model, n, seed=seed)
    qacc = np.random.default_rng(seed + 1).normal(size=qvel.shape)
    return qpos, qvel, qacc
