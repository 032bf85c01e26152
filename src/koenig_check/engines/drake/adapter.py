"""Drake adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Callers pass canonical (MuJoCo-layout) states; :class:`~koenig_check.engines.drake.state_map.DrakeStateMap`
converts them to Drake's ``(q, v)`` and converts mass matrices and generalized forces back.

Segments
--------
Drake keeps every link as a body.  A segment is a body moved by a (non-weld) joint together with
every body welded to it, keyed by the joint's canonical name, exactly as for MuJoCo and Pinocchio;
bodies welded to the world are not segments.  The lumped mass, COM and central inertia come from each
body's own ``CalcSpatialInertiaInBodyFrame`` and the constant weld transforms, expressed in the segment
body's frame.  Segment states are read from Drake's kinematics: ``EvalBodyPoseInWorld`` and
``EvalBodySpatialVelocityInWorld`` (ω and the velocity of the body origin, world frame); point
velocities take another route, ``CalcJacobianTranslationalVelocity`` of the points times ``v``.  The
pole is the origin of the joint's frame on the child body.

Energy
------
``CalcKineticEnergy`` includes the reflected inertia of joint actuators (rotor inertia × gear ratio²,
Drake's analogue of MuJoCo's and Pinocchio's armature; verified).  The rigid-body part is
``CalcKineticEnergy`` on a context whose rotor inertias are zero; the reflected-inertia part is
``½ Σ I_refl v²``.  ``CalcMassMatrix`` and ``CalcInverseDynamics`` include it too.  Inverse dynamics
leaves gravity out (it counts only the forces passed, none here) and runs with joint damping zero (set on the
context); the plant keeps the gravity its parser read, for :class:`~koenig_check.engines.drake.gravity.DrakeGravity`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.base import Engine, as_batches, check_points, symmetrize
from koenig_check.engines.drake.failures import drake_failures_raised
from koenig_check.engines.drake.gravity import DrakeGravity
from koenig_check.engines.drake.state_map import DrakeStateMap
from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.joint_pairs import dofs_by_kind, per_dof
from koenig_check.findings import Finding, Kind
from koenig_check.segments import SegmentStates


class DrakeEngine(DrakeGravity, Engine):
    """A model loaded in Drake.

    Parameters
    ----------
    plant : pydrake.multibody.plant.MultibodyPlant
        Finalized, with the gravity its parser read.
    state_map : DrakeStateMap
    path : Path
        The model file.
    qpos0 : ndarray, shape (nq,)
        The canonical reference configuration (MuJoCo's ``qpos0``).
    findings : list of Finding, optional
        Load findings (extended here with segment findings).
    """

    engine = "drake"

    def __init__(
        self,
        plant: Any,
        state_map: DrakeStateMap,
        path: Path,
        qpos0: np.ndarray,
        findings: list[Finding] | None = None,
    ) -> None:
        from pydrake.multibody.tree import BodyIndex

        self.plant = plant
        self.model = plant
        self.state_map = state_map
        self.path = Path(path)
        self.findings = list(findings or [])
        self.nq, self.nv = state_map.nq, state_map.nv
        self._context = plant.CreateDefaultContext()
        self._rigid = plant.CreateDefaultContext()
        self._reflected = np.zeros(self.nv)  # in Drake's velocity order (1-dof joints: same as canonical)
        for a in plant.GetJointActuatorIndices():
            actuator = plant.get_joint_actuator(a)
            actuator.SetRotorInertia(self._rigid, 0.0)
            joint = actuator.joint()
            # Drake's mass matrix and energy count one reflected inertia per joint, the last actuator's (a
            # hinge driven by two motors: each has armature / gear², the matrix has the armature once).
            self._reflected[joint.velocity_start()] = actuator.calc_reflected_inertia(self._context)
        for j in plant.GetJointIndices():
            joint = plant.get_joint(j)
            if joint.num_velocities() > 0:
                for ctx in (self._context, self._rigid):
                    joint.SetDampingVector(ctx, np.zeros(joint.num_velocities()))
        self._build_segments(BodyIndex, np.asarray(qpos0, dtype=float))

    # -------------------------------------------------------------- segments
    def _build_segments(self, BodyIndex: Any, qpos0: np.ndarray) -> None:
        plant, ctx = self.plant, self._context
        inboard = {}
        for j in plant.GetJointIndices():
            joint = plant.get_joint(j)
            inboard[int(joint.child_body().index())] = joint
        names = {p.drake_name: p.name for p in self.state_map.pairs}
        world = int(plant.world_body().index())

        def carrier(b: int) -> int:
            while b != world:
                joint = inboard.get(b)
                if joint is None:
                    return world
                if joint.num_velocities() > 0:
                    return b
                b = int(joint.parent_body().index())
            return world

        plant.SetPositions(ctx, self.state_map.positions(qpos0[None])[0])
        heads: dict[int, list[int]] = {}
        for b in range(1, plant.num_bodies()):
            carrier_b = carrier(b)
            if carrier_b != world:
                heads.setdefault(carrier_b, []).append(b)
        order = {p.name: k for k, p in enumerate(self.state_map.pairs)}
        items = sorted(heads.items(), key=lambda kv: order[names[inboard[kv[0]].name()]])
        seg_names, bodies, mass, com, inertia, anchor, massless = [], [], [], [], [], [], []
        self._segment_of_body = {}
        for head, members in items:
            name = names[inboard[head].name()]
            X_WH = plant.EvalBodyPoseInWorld(ctx, plant.get_body(BodyIndex(head)))
            R_WH = X_WH.rotation().matrix()
            m_tot, first, parts = 0.0, np.zeros(3), []
            for b in members:
                body = plant.get_body(BodyIndex(b))
                M = body.CalcSpatialInertiaInBodyFrame(ctx)
                m = float(M.get_mass())
                if not m > 0:
                    continue
                c_B = np.asarray(M.get_com(), dtype=float)
                I_Bo = np.asarray(M.CalcRotationalInertia().CopyToFullMatrix3(), dtype=float)
                I_C = I_Bo - m * (c_B @ c_B * np.eye(3) - np.outer(c_B, c_B))
                X_WB = plant.EvalBodyPoseInWorld(ctx, body)
                R_HB = R_WH.T @ X_WB.rotation().matrix()
                c_H = R_WH.T @ (X_WB.translation() - X_WH.translation()) + R_HB @ c_B
                parts.append((m, c_H, R_HB @ I_C @ R_HB.T))
                m_tot += m
                first += m * c_H
            if m_tot <= 0:
                massless.append(name)
                continue
            c = first / m_tot
            I_tot = np.zeros((3, 3))
            for m, c_H, I_H in parts:
                d = c_H - c
                I_tot += I_H + m * (d @ d * np.eye(3) - np.outer(d, d))
            seg_names.append(name)
            self._segment_of_body.update({plant.get_body(BodyIndex(b)).name(): name for b in members})
            bodies.append(head)
            mass.append(m_tot)
            com.append(c)
            inertia.append(I_tot)
            anchor.append(_anchor_in_body(inboard[head]))
        if massless:
            self.findings.append(
                Finding(
                    Kind.SEGMENTS, "drake", "segments " + ", ".join(massless), "massless: left out (no kinetic energy)"
                )
            )
        self.segment_names = tuple(seg_names)
        self._bodies = [plant.get_body(BodyIndex(b)) for b in bodies]
        self._mass = np.array(mass, dtype=float)
        self._com_local = np.array(com, dtype=float).reshape(-1, 3)
        self._inertia = symmetrize(np.array(inertia, dtype=float).reshape(-1, 3, 3))
        self._anchor_local = np.array(anchor, dtype=float).reshape(-1, 3)
        self._ref = self._sweep(qpos0[None], np.zeros((1, self.nv)))

    def _set(self, context: Any, q: np.ndarray, v: np.ndarray) -> None:
        self.plant.SetPositions(context, q)
        self.plant.SetVelocities(context, v)

    def _sweep(self, qpos: np.ndarray, qvel: np.ndarray) -> dict[str, np.ndarray]:
        """Body poses and spatial velocities (world) of the segment bodies, pose by pose."""
        q, v = self.state_map.to_drake(qpos, qvel)
        P, B = q.shape[0], len(self._bodies)
        R, o = np.empty((P, B, 3, 3)), np.empty((P, B, 3))
        w, vo = np.empty((P, B, 3)), np.empty((P, B, 3))
        for p in range(P):
            self._set(self._context, q[p], v[p])
            for b, body in enumerate(self._bodies):
                X = self.plant.EvalBodyPoseInWorld(self._context, body)
                V = self.plant.EvalBodySpatialVelocityInWorld(self._context, body)
                R[p, b], o[p, b] = X.rotation().matrix(), X.translation()
                w[p, b], vo[p, b] = V.rotational(), V.translational()
        anchor = o + np.einsum("pbij,bj->pbi", R, self._anchor_local)
        return {"R": R, "origin": o, "omega": w, "v_origin": vo, "anchor": anchor}

    @drake_failures_raised
    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return Drake's segment states for a batch of canonical states."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        s = self._sweep(qpos, qvel)
        R, o, w, vo = s["R"], s["origin"], s["omega"], s["v_origin"]
        com = o + np.einsum("pbij,bj->pbi", R, self._com_local)
        ref = self._ref
        R0 = ref["R"][0]
        return SegmentStates(
            names=self.segment_names,
            mass=self._mass,
            inertia_body=self._inertia,
            com=com,
            v_com=vo + np.cross(w, com - o),
            rotation=R,
            omega=w,
            pole=s["anchor"],
            v_pole=vo + np.cross(w, s["anchor"] - o),
            rotation_ref=R0,
            com_ref=ref["origin"][0] + np.einsum("bij,bj->bi", R0, self._com_local),
            pole_ref=ref["anchor"][0],
        )

    @drake_failures_raised
    def point_velocities(self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Return the world velocity of points fixed in the segments, from Drake's translational Jacobians."""
        from pydrake.multibody.tree import JacobianWrtVariable

        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        pts = check_points(points, len(self.segment_names))
        local = self._com_local[:, None, :] + pts  # (B, K, 3) in the body frame
        q, v = self.state_map.to_drake(qpos, qvel)
        P, (B, K, _) = q.shape[0], pts.shape
        out = np.empty((P, B, K, 3))
        world = self.plant.world_frame()
        for p in range(P):
            self._set(self._context, q[p], v[p])
            for b, body in enumerate(self._bodies):
                J = self.plant.CalcJacobianTranslationalVelocity(
                    self._context, JacobianWrtVariable.kV, body.body_frame(), local[b].T, world, world
                )
                out[p, b] = (J @ v[p]).reshape(K, 3)
        return out

    # ------------------------------------------------------------- dynamics
    @drake_failures_raised
    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return ``CalcKineticEnergy``, the same with rotor inertias zero, and the reflected inertia as armature."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_drake(qpos, qvel)
        P = q.shape[0]
        reported, rigid = np.empty(P), np.empty(P)
        for p in range(P):
            self._set(self._context, q[p], v[p])
            self._set(self._rigid, q[p], v[p])
            reported[p] = self.plant.CalcKineticEnergy(self._context)
            rigid[p] = self.plant.CalcKineticEnergy(self._rigid)
        return EnergyParts(rigid=rigid, armature=0.5 * (v**2) @ self._reflected, reported=reported)

    @drake_failures_raised
    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``CalcMassMatrix`` (reflected inertia included) in canonical velocity coordinates."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q = self.state_map.positions(qpos)
        M = np.empty((q.shape[0], self.nv, self.nv))
        for p in range(q.shape[0]):
            self.plant.SetPositions(self._context, q[p])
            M[p] = self.plant.CalcMassMatrix(self._context)
        return self.state_map.matrix_to_canonical(qpos, M)

    @drake_failures_raised
    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return ``CalcInverseDynamics`` (gravity, damping and applied forces zero) in canonical coordinates."""
        from pydrake.multibody.tree import MultibodyForces

        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        q, v = self.state_map.to_drake(qpos, qvel)
        _, a = self.state_map.to_drake(qpos, qacc)
        forces = MultibodyForces(self.plant)
        tau = np.empty_like(v)
        for p in range(q.shape[0]):
            self._set(self._context, q[p], v[p])
            tau[p] = self.plant.CalcInverseDynamics(self._context, a[p], forces)
        return self.state_map.force_to_canonical(qpos, tau)

    def segment_of_body(self) -> dict[str, str]:
        """Body name -> the segment it belongs to (bodies welded to the world and massless segments left out).

        Returns
        -------
        dict of str to str
        """
        return dict(self._segment_of_body)

    def armature_per_dof(self) -> np.ndarray:
        """Drake's reflected inertia of each canonical dof (actuators act on one-dof joints only).

        Returns
        -------
        ndarray, shape (nv,)
        """
        return per_dof(self.state_map.pairs, self.nv, lambda p: self._reflected[p.dv])

    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by Drake joint type (``revolute``, ``quaternion_floating``, ...)."""
        kinds = {"free": "quaternion_floating", "ball": "ball_rpy", "hinge": "revolute", "slide": "prismatic"}
        return dofs_by_kind(self.state_map.pairs, lambda p: kinds[p.kind])


def _anchor_in_body(joint: Any) -> np.ndarray:
    """The joint's anchor as a point of the child body (MuJoCo's ``jnt_pos``), in the body frame.

    The origin of the joint's frame on the child, except for a prismatic joint with a reference position:
    Drake's MJCF parser puts that frame ``ref`` along the axis from the anchor (so that ``q = ref`` is the
    file's pose; verified), and the anchor is ``p_BM − ref · axis``.
    """
    X_BM = joint.frame_on_child().GetFixedPoseInBodyFrame()
    origin = np.asarray(X_BM.translation(), dtype=float)
    if joint.type_name() == "prismatic":
        axis_B = X_BM.rotation().matrix() @ np.asarray(joint.translation_axis(), dtype=float)
        origin = origin - float(joint.get_default_translation()) * axis_B
    return origin
