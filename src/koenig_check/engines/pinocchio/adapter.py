"""Pinocchio adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Callers pass canonical (MuJoCo-layout) states; the :class:`~koenig_check.engines.pinocchio.state_map.StateMap`
converts them to Pinocchio's ``(q, v)`` and converts the mass matrix and generalized forces back.

Segments are Pinocchio joints with non-zero mass: ``model.inertias[i]`` already lumps the links
fixed to the joint (URDF fixed joints, jointless MJCF bodies) and is expressed in the joint frame.
Segment states come from ``forwardKinematics(model, data, q, v)``: ``data.oMi`` (world <- joint) and
``data.v`` (the joint frame's spatial velocity in its own axes), rotated to the world; the public
:meth:`PinocchioEngine.point_velocities` applies ``data.v`` to the points in the joint's axes instead
(the other order of operations).  The pole is the joint frame origin.

Dynamics (energy, mass matrix, inverse dynamics) are
:class:`~koenig_check.engines.pinocchio.dynamics.PinocchioDynamics`; the placements and velocities are read
whole through :func:`~koenig_check.engines.pinocchio.placements.placement_view` and
:func:`~koenig_check.engines.pinocchio.placements.motion_view`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin

from koenig_check.engines.base import Engine, as_batches, check_points, states_point_velocities, symmetrize
from koenig_check.engines.pinocchio.dynamics import PinocchioDynamics
from koenig_check.engines.pinocchio.gravity import PinocchioGravity
from koenig_check.engines.pinocchio.placements import motion_view, placement_view
from koenig_check.engines.pinocchio.state_map import StateMap
from koenig_check.engines.planes import (
    byte_view,
    cross_planes,
    entry_index,
    gather_planes,
    matrices,
    rotate_constant,
    rotate_planes,
    vectors,
)
from koenig_check.findings import Finding, Kind
from koenig_check.segments import SegmentStates

__all__ = ["PinocchioEngine", "motion_view", "placement_view"]


class PinocchioEngine(PinocchioGravity, PinocchioDynamics, Engine):
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
        # Where each segment's entries sit in a pose's flat placements (12 per joint: the rotation column by
        # column, then the translation) and velocities (6 per joint: linear, angular).
        self._index = {
            "rotation": entry_index(self._joints, 12, [3 * j + i for i in range(3) for j in range(3)]),  # row-major
            "origin": entry_index(self._joints, 12, range(9, 12)),
            "velocity": entry_index(self._joints, 6, range(6)),
        }
        self._placement_views = self._views()
        self._motion_views = self._velocity_views()
        H, _ = self._sweep(pin.neutral(model)[None], None)
        R0, origin0 = H[0][:, :3, :3], H[0][:, :3, 3]
        # The reference configuration, once per model.
        self._ref = {"rotation": R0, "com": origin0 + np.einsum("bij,bj->bi", R0, self._lever), "pole": origin0}

    def _views(self) -> tuple[np.ndarray | None, np.ndarray | None]:
        """The :func:`placement_view` of the armature-free copy's data and of the model's data."""
        return placement_view(self._m_rigid, self._d_rigid), placement_view(self.model, self._data)

    def _velocity_views(self) -> tuple[np.ndarray | None, np.ndarray | None]:
        """The :func:`motion_view` of the armature-free copy's data and of the model's data."""
        return motion_view(self._m_rigid, self._d_rigid), motion_view(self.model, self._data)

    def __getstate__(self) -> dict:
        # A view reads the memory of this engine's own data: a copy (pickle, deepcopy) builds its own.
        state = self.__dict__.copy()
        del state["_placement_views"], state["_motion_views"]
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._placement_views = self._views()
        self._motion_views = self._velocity_views()

    def _sweep(self, q: np.ndarray, v: np.ndarray | None) -> tuple[np.ndarray, np.ndarray | None]:
        """Run forward kinematics once per pose; return oMi (P, B, 4, 4) and data.v (P, B, 6).

        The route of the public :meth:`point_velocities` (and of the reference configuration).
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

    def _sweep_motion(self, q: np.ndarray, v: np.ndarray, energies: bool = False) -> dict[str, np.ndarray]:
        """Run ``forwardKinematics(q, v)`` once per pose; return the segments' placements and velocities as planes.

        Per pose: one kinematic pass, ``data.oMi`` and ``data.v`` copied whole through
        :func:`placement_view` and :func:`motion_view` (joint by joint, through the bindings, where a
        view is not available); the segments' entries of every pose are then gathered at once into
        (k, P, B) planes: ``rotation`` (9, row-major), ``origin`` (3), ``velocity`` (6: the joint
        frame's linear then angular velocity, in its own axes).  With ``energies``, the pass runs on
        the armature-free copy (the same kinematic tree, so the same placements and velocities, bit
        for bit) as ``computeKineticEnergy(q, v)``, which runs ``forwardKinematics(q, v)`` itself and
        then sums the energy: ``rigid`` of :meth:`kinetic_energy`, with one engine call per pose.
        """
        P, nj = q.shape[0], self.model.njoints
        m, d = (self._m_rigid, self._d_rigid) if energies else (self.model, self._data)
        which = 0 if energies else 1
        place_view, motion = self._placement_views[which], self._motion_views[which]
        kinematics, kinetic = pin.forwardKinematics, pin.computeKineticEnergy
        placements, velocities = np.empty((P, nj, 12)), np.empty((P, nj, 6))
        rigid = np.empty(P)
        placements_live, motions_live = d.oMi, d.v  # follow every pose: taken once, outside the loop
        # The per-pose copies of the views are slice assignments between byte views (see planes.byte_view); the
        # views follow Pinocchio's storage, so a view that is not one run of bytes is copied by numpy instead.
        place_in = byte_view(place_view) if place_view is not None and place_view.flags.c_contiguous else None
        motion_in = byte_view(motion) if motion is not None and motion.flags.c_contiguous else None
        place_out, motion_out = byte_view(placements), byte_view(velocities)
        n_place, n_motion = nj * 12 * 8, nj * 6 * 8
        for p, (q_p, v_p) in enumerate(zip(q, v, strict=True)):
            if energies:  # computeKineticEnergy(q, v) runs the kinematic pass itself: one call per pose
                rigid[p] = kinetic(m, d, q_p, v_p)
            else:
                kinematics(m, d, q_p, v_p)
            if place_in is not None:
                place_out[p * n_place : (p + 1) * n_place] = place_in
            elif place_view is not None:
                placements[p] = place_view
            else:
                H = np.array([M.homogeneous for M in placements_live.tolist()])
                placements[p, :, :9] = np.swapaxes(H[:, :3, :3], -1, -2).reshape(nj, 9)  # column by column
                placements[p, :, 9:] = H[:, :3, 3]
            if motion_in is not None:
                motion_out[p * n_motion : (p + 1) * n_motion] = motion_in
            elif motion is not None:
                velocities[p] = motion
            else:
                velocities[p] = [x.vector for x in motions_live.tolist()]
        flat_placements, flat_velocities = placements.reshape(P, nj * 12), velocities.reshape(P, nj * 6)
        raws = {"rotation": flat_placements, "origin": flat_placements, "velocity": flat_velocities}
        out = {name: gather_planes(raws[name], index) for name, index in self._index.items()}
        if energies:
            out["rigid"] = rigid
        return out

    def _states(self, s: dict[str, np.ndarray], trusted: bool = False) -> SegmentStates:
        R, V = s["rotation"], s["velocity"]
        lever = rotate_constant(R, self._lever)  # C − O, world axes
        com = np.add(s["origin"], lever)
        omega, v_pole = rotate_planes(R, V[3:]), rotate_planes(R, V[:3])
        v_com = cross_planes(omega, lever)
        v_com += v_pole
        ref = self._ref
        return (SegmentStates.trusted if trusted else SegmentStates)(
            names=self.segment_names,
            mass=self._mass,
            inertia_body=self._inertia,
            com=vectors(com),
            v_com=vectors(v_com),
            rotation=matrices(R),
            omega=vectors(omega),
            pole=vectors(s["origin"]),
            v_pole=vectors(v_pole),
            rotation_ref=ref["rotation"],
            com_ref=ref["com"],
            pole_ref=ref["pole"],
        )

    def sweep(
        self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray | None = None
    ) -> tuple[SegmentStates, np.ndarray | None, np.ndarray, np.ndarray]:
        """Segment states, point velocities and energy from one pass of the engine per pose.

        The internal path of the comparison: the states are not validated again, and the
        point velocities come from the states' world velocities (``v_C + ω × R r``).
        """
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        s = self._sweep_motion(q, v, energies=True)
        states = self._states(s, trusted=True)
        pv = states_point_velocities(states, points)
        armature = 0.5 * (v**2) @ np.asarray(self.model.armature)
        return states, pv, s["rigid"], armature

    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return Pinocchio's segment states for a batch of canonical states."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        q, v = self.state_map.to_pinocchio(qpos, qvel)
        return self._states(self._sweep_motion(q, v))

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
