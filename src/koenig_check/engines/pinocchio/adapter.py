"""Pinocchio adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Callers pass canonical (MuJoCo-layout) states; the :class:`~koenig_check.engines.pinocchio.state_map.StateMap`
converts them to Pinocchio's ``(q, v)`` and converts the mass matrix and generalized forces back.

Segments are Pinocchio joints with non-zero mass: ``model.inertias[i]`` already lumps the links
fixed to the joint (URDF fixed joints, jointless MJCF bodies) and is expressed in the joint frame.
Segment states come from ``computeJointJacobians(model, data, q)``: ``data.oMi`` (world <- joint)
and the world-frame joint Jacobians, whose columns over a joint's supporting dofs give its twist;
point velocities take the other route, ``forwardKinematics(model, data, q, v)`` and ``data.v``
(spatial velocity in the joint frame).  The pole is the joint frame origin.

Dynamics (energy, mass matrix, inverse dynamics) are
:class:`~koenig_check.engines.pinocchio.dynamics.PinocchioDynamics`; the placements are read whole through
:func:`~koenig_check.engines.pinocchio.placements.placement_view`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin

from koenig_check.engines.base import Engine, as_batches, check_points, rows, states_point_velocities, symmetrize
from koenig_check.engines.pinocchio.dynamics import PinocchioDynamics
from koenig_check.engines.pinocchio.placements import placement_view, rotations_origins
from koenig_check.engines.pinocchio.state_map import StateMap
from koenig_check.findings import Finding, Kind
from koenig_check.kernels import cross, rotate
from koenig_check.segments import SegmentStates

__all__ = ["PinocchioEngine", "placement_view"]


class PinocchioEngine(PinocchioDynamics, Engine):
    """A model loaded in Pinocchio.

    Parameters
    ----------
    model : pinocchio.Model
    state_map : StateMap
        Canonical <-> Pinocchio conversion for this model.
    path : Path
        The model file.
    findings : list of Finding
        Load findings (extended here with segment findings).
    """

    engine = "pinocchio"

    def __init__(
        self, model: pin.Model, state_map: StateMap, path: Path, findings: list[Finding] | None = None
    ) -> None:
        self.model = model
        self.state_map = state_map
        self.path = Path(path)
        self.findings = list(findings or [])
        self.nq, self.nv = state_map.nq, state_map.nv
        self._data = model.createData()
        self._m_rigid = pin.Model(model)
        self._m_rigid.armature[:] = 0.0
        self._d_rigid = self._m_rigid.createData()
        self._m_dyn = pin.Model(model)
        self._m_dyn.gravity = pin.Motion.Zero()
        self._d_dyn = self._m_dyn.createData()
        order = {p.name: k for k, p in enumerate(state_map.pairs)}
        joints = sorted(range(1, model.njoints), key=lambda i: order[state_map.segment_names[i]])
        massless = [state_map.segment_names[i] for i in joints if model.inertias[i].mass <= 0]
        if massless:
            self.findings.append(
                Finding(
                    Kind.SEGMENTS,
                    "pinocchio",
                    "segments " + ", ".join(massless),
                    "massless: left out (no kinetic energy)",
                )
            )
        self._joints = np.array([i for i in joints if model.inertias[i].mass > 0], dtype=int)
        self.segment_names = tuple(state_map.segment_names[i] for i in self._joints)
        inertias = [model.inertias[int(i)] for i in self._joints]
        self._mass = np.array([Y.mass for Y in inertias], dtype=float)
        self._lever = np.array([Y.lever for Y in inertias], dtype=float).reshape(-1, 3)
        self._inertia = symmetrize(np.array([Y.inertia for Y in inertias], dtype=float).reshape(-1, 3, 3))
        self._support = np.zeros((model.nv, len(self._joints)))  # dof k moves segment b
        for b, i in enumerate(self._joints):
            for j in model.supports[int(i)]:
                if j > 0:
                    start = model.idx_vs[j]
                    self._support[start : start + model.nvs[j], b] = 1.0
        self._placement_views = self._views()
        H, _ = self._sweep(pin.neutral(model)[None], None)
        self._ref = H[0]

    def _views(self) -> tuple[np.ndarray | None, np.ndarray | None]:
        """The :func:`placement_view` of the armature-free copy's data and of the model's data."""
        return placement_view(self._m_rigid, self._d_rigid), placement_view(self.model, self._data)

    def __getstate__(self) -> dict:
        # A placement view reads the memory of this engine's own data: a copy (pickle, deepcopy) builds its own.
        state = self.__dict__.copy()
        del state["_placement_views"]
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._placement_views = self._views()

    def _sweep(self, q: np.ndarray, v: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
        """Run forward kinematics once per pose; return oMi (P, B, 4, 4) and data.v (P, B, 6).

        The route of the public :meth:`point_velocities`, independent of the world Jacobian.
        """
        m, d, idx = self.model, self._data, self._joints
        P = q.shape[0]
        H = np.empty((P, m.njoints, 4, 4))
        V = None if v is None else np.empty((P, m.njoints, 6))
        for p in range(P):
            if v is None:
                pin.forwardKinematics(m, d, q[p])
            else:
                pin.forwardKinematics(m, d, q[p], v[p])
                assert V is not None  # allocated above whenever v is given
                V[p] = [x.vector for x in d.v.tolist()]
            H[p] = [M.homogeneous for M in d.oMi.tolist()]
        return H[:, idx], None if V is None else V[:, idx]

    def _sweep_world(
        self, q: np.ndarray, v: np.ndarray, energies: bool = False
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]:
        """Run ``computeJointJacobians`` once per pose: rotations, origins and world twists of the segments.

        The twist of joint ``i`` is ``J_world[:, support(i)] v``: ``(v_O, ω)`` with ``v_O`` the
        velocity of the segment point at the world origin, so a point ``p`` moves with
        ``v_O + ω × p``.  Per pose: one engine call, the world Jacobian ``data.J`` copied whole
        and the placements ``data.oMi`` copied whole through :func:`placement_view` (per joint,
        through the bindings, where that view is not available); the sum over supports is
        vectorized.  With ``energies``, the same pass evaluates ``computeKineticEnergy`` on the
        armature-free copy (``rigid`` of :meth:`kinetic_energy`): ``forwardKinematics(q, v)`` once,
        then the energy and the Jacobians from that pass (the copy has the model's kinematic tree).
        """
        m = self.model
        P = q.shape[0]
        J = np.empty((P, 6, m.nv))
        rigid: np.ndarray | None = None
        jacobians, kinetic, kinematics = pin.computeJointJacobians, pin.computeKineticEnergy, pin.forwardKinematics
        m_rigid, d_rigid, d = self._m_rigid, self._d_rigid, self._data
        Jp = J if m.nv > 1 else J[..., 0]  # the bindings hand a 6 x 1 Jacobian out as a vector
        # data.J, data.oMi and the placement view follow every pose: taken once, outside the loop.
        data = d_rigid if energies else d
        J_live, placements = data.J, data.oMi
        view = self._placement_views[0 if energies else 1]
        raw = np.empty((P, m.njoints, 12)) if view is not None else np.empty((P, m.njoints, 4, 4))
        if energies:
            rigid = np.empty(P)
            # One kinematic pass on the armature-free copy (the same tree, so the same placements and
            # Jacobian, bit for bit): forwardKinematics with v, then the energy and the Jacobians from it.
            for p, (q_p, v_p) in enumerate(zip(q, v, strict=True)):
                kinematics(m_rigid, d_rigid, q_p, v_p)
                rigid[p] = kinetic(m_rigid, d_rigid)
                jacobians(m_rigid, d_rigid)
                Jp[p] = J_live
                raw[p] = view if view is not None else [M.homogeneous for M in placements.tolist()]
        else:
            for p, q_p in enumerate(q):
                jacobians(m, d, q_p)
                Jp[p] = J_live
                raw[p] = view if view is not None else [M.homogeneous for M in placements.tolist()]
        twists = np.swapaxes((J * v[:, None, :]) @ self._support, -1, -2)  # (P, B, 6): sum over supports
        R, origin = rotations_origins(raw, view is not None, rows(self._joints))
        return R, origin, twists, rigid

    def _states(self, R: np.ndarray, origin: np.ndarray, T: np.ndarray, trusted: bool = False) -> SegmentStates:
        v_origin, omega = T[..., :3], T[..., 3:]
        com = origin + rotate(R, self._lever)
        R0 = self._ref[..., :3, :3]
        return (SegmentStates.trusted if trusted else SegmentStates)(
            names=self.segment_names,
            mass=self._mass,
            inertia_body=self._inertia,
            com=com,
            v_com=v_origin + cross(omega, com),
            rotation=R,
            omega=omega,
            pole=origin,
            v_pole=v_origin + cross(omega, origin),
            rotation_ref=R0,
            com_ref=self._ref[..., :3, 3] + np.einsum("bij,bj->bi", R0, self._lever),
            pole_ref=self._ref[..., :3, 3],
        )

    def sweep(
        self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray | None = None
    ) -> tuple[SegmentStates, np.ndarray | None, np.ndarray, np.ndarray]:
        """Segment states, point velocities and energy from one pass of the engine per pose.

        The internal path of the comparison: the states are not validated again, and the
        point velocities come from the same world twists as the states (``v_O + ω × p``).
        """
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        R, origin, T, rigid = self._sweep_world(q, v, energies=True)
        assert rigid is not None  # energies=True always evaluates the energies
        states = self._states(R, origin, T, trusted=True)
        pv = states_point_velocities(states, points)
        armature = 0.5 * (v**2) @ np.asarray(self.model.armature)
        return states, pv, rigid, armature

    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return Pinocchio's segment states for a batch of canonical states."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        R, origin, T, _ = self._sweep_world(q, v)
        return self._states(R, origin, T)

    def point_velocities(self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Return the world velocity of points fixed in the segments, ``R (v + ω × r)`` from ``data.v``."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        pts = check_points(points, len(self.segment_names))
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        H, V = self._sweep(q, v)
        assert V is not None  # _sweep returns the twists whenever v is given
        r = self._lever[:, None, :] + pts  # (B, K, 3) from the joint origin, joint axes
        local = V[:, :, None, :3] + np.cross(V[:, :, None, 3:], r[None])
        return np.einsum("pbij,pbkj->pbki", H[..., :3, :3], local)

    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by Pinocchio joint model.

        Returns
        -------
        dict
            Keys are Pinocchio joint model names (``"JointModelRevoluteUnaligned"``...), with
            ``" in composite"`` appended for sub-joints of a composite joint.
        """
        width = {"free": 6, "ball": 3}
        groups: dict[str, list[int]] = {}
        for p in self.state_map.pairs:
            joint = self.model.joints[p.pin_joint]
            leaf = joint.extract().joints[p.pin_sub] if p.pin_sub >= 0 else joint
            key = leaf.shortname() + (" in composite" if p.pin_sub >= 0 else "")
            groups.setdefault(key, []).extend(range(p.vadr, p.vadr + width.get(p.kind, 1)))
        return {k: np.array(v, dtype=int) for k, v in groups.items()}
