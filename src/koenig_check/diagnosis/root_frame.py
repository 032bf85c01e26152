"""A jointless root body's pose that Pinocchio's MJCF parser drops: a constant transform between the engines' worlds."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import mujoco
import numpy as np

from koenig_check.findings import Finding, Kind
from koenig_check.segments import SegmentStates


@dataclass(frozen=True)
class FrameOffset:
    """The constant transform ``world_mujoco <- world_pinocchio`` of a dropped root-body pose.

    Attributes
    ----------
    rotation : ndarray, shape (3, 3)
    translation : ndarray, shape (3,)
    """

    rotation: np.ndarray
    translation: np.ndarray

    def point(self, x: np.ndarray) -> np.ndarray:
        """Map points (..., 3) from Pinocchio's world to MuJoCo's."""
        return x @ self.rotation.T + self.translation

    def vector(self, v: np.ndarray) -> np.ndarray:
        """Map free vectors (..., 3) from Pinocchio's world to MuJoCo's."""
        return v @ self.rotation.T

    def frame(self, R: np.ndarray) -> np.ndarray:
        """Map rotations (..., 3, 3) world <- segment from Pinocchio's world to MuJoCo's."""
        return self.rotation @ R

    def segment_states(self, states: SegmentStates) -> SegmentStates:
        """Map segment states (every point, vector and rotation) from Pinocchio's world to MuJoCo's.

        Parameters
        ----------
        states : SegmentStates
            Pinocchio's.

        Returns
        -------
        SegmentStates
        """
        return replace(
            states,
            com=self.point(states.com),
            v_com=self.vector(states.v_com),
            rotation=self.frame(states.rotation),
            omega=self.vector(states.omega),
            pole=self.point(states.pole),
            v_pole=self.vector(states.v_pole),
            rotation_ref=self.frame(states.rotation_ref),
            com_ref=self.point(states.com_ref),
            pole_ref=self.point(states.pole_ref),
        )


def root_frame_offset(pair: Any, atol: float = 1e-9) -> tuple[FrameOffset | None, Finding | None]:
    """The dropped pose of a jointless root body: where MuJoCo and Pinocchio put the first root body.

    Parameters
    ----------
    pair : LoadedModel
    atol : float
        Under this (rotation entries, metres) the poses are the same.

    Returns
    -------
    offset : FrameOffset or None
    finding : Finding or None
        A FRAME note (``affects_energy=False``) naming the body and both poses.
    """
    import pinocchio as pin

    mj_model, pin_model = pair.mujoco.model, pair.pinocchio.model
    roots = [b for b in range(1, mj_model.nbody) if mj_model.body_parentid[b] == 0]
    if not roots:
        return None, None
    body = roots[0]
    name = mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_BODY, body) or ""
    if mj_model.body_jntnum[body] > 0 or not name or not pin_model.existFrame(name):
        return None, None
    data = mujoco.MjData(mj_model)
    data.qpos[:] = mj_model.qpos0
    mujoco.mj_kinematics(mj_model, data)
    R_mj, p_mj = data.xmat[body].reshape(3, 3).copy(), data.xpos[body].copy()
    pdata = pin_model.createData()
    q = pair.state_map.to_pinocchio(np.asarray(mj_model.qpos0, dtype=float))
    pin.framesForwardKinematics(pin_model, pdata, q)
    placement = pdata.oMf[pin_model.getFrameId(name)]
    R_pin, p_pin = np.array(placement.rotation), np.array(placement.translation)
    if np.abs(R_mj - R_pin).max() <= atol and np.abs(p_mj - p_pin).max() <= atol:
        return None, None
    R = R_mj @ R_pin.T
    offset = FrameOffset(R, p_mj - R @ p_pin)
    quat = _quat(R_mj)
    finding = Finding(
        Kind.FRAME,
        "pinocchio",
        f"body {name}",
        "pose of the jointless root body dropped by Pinocchio's MJCF parser: a constant world transform "
        "between the engines (segments compared in MuJoCo's world after removing it)",
        values={
            "mujoco pos": _vec(p_mj),
            "pinocchio pos": _vec(p_pin),
            "mujoco quat": _vec(quat),
            "pinocchio quat": _vec(_quat(R_pin)),
        },
        affects_energy=False,
        root_cause=True,
        segments=tuple(pair.pinocchio.segment_names),
        cause="pinocchio.mjcf.root-pose",
    )
    return offset, finding


def _vec(x: np.ndarray) -> tuple[float, ...]:
    """A vector as a tuple of floats rounded to 1e-12 (readable in messages, exact enough as data)."""
    return tuple(round(float(v), 12) + 0.0 for v in np.ravel(x))


def _quat(R: np.ndarray) -> np.ndarray:
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(R).ravel())
    return quat
