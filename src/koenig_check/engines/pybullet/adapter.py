"""PyBullet adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Callers pass canonical (MuJoCo-layout) states; :class:`~koenig_check.engines.pybullet.state_map.PyBulletStateMap`
converts them to PyBullet's, and its mass matrices and forces back.

Segments
--------
A segment is a link moved by a (non-fixed) joint, or the floating base, with every link fixed to it, keyed by the
joint's canonical name as for MuJoCo and Pinocchio.  Its mass and central inertia are lumped from PyBullet's own
per-link data (``getDynamicsInfo``: mass, principal moments, inertial frame) at the reference pose, in the head
link's frame; its states come from PyBullet's kinematics (``getLinkStates`` with velocities: each link's COM and
principal axes in the world, the COM's velocity and the angular velocity; the base's from ``getBase*``), the link
frames composed in numpy (``multiplyTransforms`` is single precision).  The pole is the head link's frame origin,
where a URDF joint's axis passes.

Energy
------
PyBullet has no kinetic-energy function: the energy here is ``Σ ½ m v_C² + ½ ω·I_C ω`` over PyBullet's links,
from its own link velocities and inertias (the self-consistency check compares it with ``½ q̇ᵀ M q̇`` of its
``calculateMassMatrix``).  A URDF has no armature: the armature parts are zero.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines.base import Engine, as_batches
from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.joint_pairs import dofs_by_kind
from koenig_check.engines.link_groups import group_links
from koenig_check.engines.pybullet.client import Client
from koenig_check.engines.pybullet.state_map import PyBulletStateMap
from koenig_check.engines.pybullet.tree import BodyTree, quat_matrix
from koenig_check.findings import Finding
from koenig_check.segments import SegmentStates


class PyBulletEngine(Engine):
    """A URDF loaded in PyBullet.

    Parameters
    ----------
    client : Client
        The DIRECT server holding the body (owned by the engine from now on).
    body : int
    tree : BodyTree
    state_map : PyBulletStateMap
    path : Path
    qpos0 : ndarray, shape (nq,)
        The canonical reference configuration.
    findings : list of Finding, optional
    """

    engine = "pybullet"

    def __init__(
        self,
        client: Client,
        body: int,
        tree: BodyTree,
        state_map: PyBulletStateMap,
        path: Path,
        qpos0: np.ndarray,
        findings: list[Finding] | None = None,
    ) -> None:
        self.client, self.body, self.tree, self.state_map = client, body, tree, state_map
        self.path = Path(path)
        self.findings = list(findings or [])
        self.nq, self.nv = state_map.nq, state_map.nv
        self._links = list(range(len(tree.link_names) - 1))
        self._joint_links = [p.link - 1 for p in sorted(state_map.pairs, key=lambda p: p.dof) if p.kind != "free"]
        self._inertia_local = tree.central_inertia()
        self._build_segments(np.asarray(qpos0, dtype=float))

    # -------------------------------------------------------------- segments
    def _carrier(self, row: int) -> int:
        """The row of the segment that carries a link (-1: static, fixed to the world)."""
        heads = {p.link for p in self.state_map.pairs}
        while row not in heads:
            if row == 0:
                return -1
            row = int(self.tree.parent[row])
        return row

    def _build_segments(self, qpos0: np.ndarray) -> None:
        tree = self.tree
        name_of = {p.link: p.name for p in self.state_map.pairs}
        weighs = (tree.mass > 0) | tree.principal.any(axis=1)  # a massless link's inertia counts
        order = [p.name for p in self.state_map.pairs]
        carriers = [self._carrier(row) for row in range(len(tree.link_names))]
        groups = group_links(carriers, weighs, tree.mass, name_of, order)
        self.findings.extend(groups.findings(self.engine))
        self.segment_names, self._groups = groups.names, groups
        self._heads, self._members = groups.heads, groups.members
        ref = self._read(qpos0[None], np.zeros((1, self.nv)))
        R_com = ref["R_com"][0]
        inertia = R_com @ (tree.principal[:, :, None] * np.swapaxes(R_com, 1, 2))
        self._mass, self._inertia = groups.lumped(tree.mass, ref["com"][0], inertia, ref["R_link"][0])
        self._ref = self._segments(ref)

    # -------------------------------------------------------------- reading PyBullet
    def _set(self, qpos: np.ndarray, qvel: np.ndarray, p: int, q: np.ndarray, v: np.ndarray) -> None:
        """Put PyBullet's body in pose ``p`` of a batch (joints, and the base when it floats)."""
        call, body = self.client.call, self.body
        if self._joint_links:
            call(
                "resetJointStatesMultiDof",
                body,
                self._joint_links,
                [[x] for x in q[p]],
                targetVelocities=[[x] for x in v[p]],
            )
        if self.state_map.base is not None:
            com, quat, v_com, omega = self.state_map.base_state(qpos[p : p + 1], qvel[p : p + 1])
            call("resetBasePositionAndOrientation", body, com[0].tolist(), quat[0].tolist())
            call("resetBaseVelocity", body, v_com[0].tolist(), omega[0].tolist())

    def _read(self, qpos: np.ndarray, qvel: np.ndarray) -> dict[str, np.ndarray]:
        """Every link's COM, principal axes, COM velocity and angular velocity (world), and its frame, per pose."""
        call, body = self.client.call, self.body
        q, v = self.state_map.joints(qpos, qvel)
        P, L = qpos.shape[0], len(self.tree.link_names)
        com, R_com = np.zeros((P, L, 3)), np.zeros((P, L, 3, 3))
        vel, omega = np.zeros((P, L, 3)), np.zeros((P, L, 3))
        for p in range(P):
            self._set(qpos, qvel, p, q, v)
            pos, orn = call("getBasePositionAndOrientation", body)
            com[p, 0], R_com[p, 0] = pos, quat_matrix(np.asarray(orn))
            lin, ang = call("getBaseVelocity", body)
            vel[p, 0], omega[p, 0] = lin, ang
            if self._links:
                states = call("getLinkStates", body, self._links, computeLinkVelocity=1, computeForwardKinematics=1)
                com[p, 1:] = [s[0] for s in states]
                R_com[p, 1:] = quat_matrix(np.array([s[1] for s in states], dtype=float))
                vel[p, 1:] = [s[6] for s in states]
                omega[p, 1:] = [s[7] for s in states]
        R_link = R_com @ np.swapaxes(self.tree.inertial_rot, 1, 2)
        origin = com - np.einsum("plij,lj->pli", R_link, self.tree.inertial_pos)
        return {"com": com, "R_com": R_com, "v": vel, "omega": omega, "R_link": R_link, "origin": origin}

    def _segments(self, links: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """Segment COM, COM velocity, rotation, angular velocity, pole and its velocity, per pose."""
        m, h = self.tree.mass, self._heads
        com, v = self._groups.mass_average(m, links["com"]), self._groups.mass_average(m, links["v"])
        omega, pole = links["omega"][:, h], links["origin"][:, h]
        v_pole = links["v"][:, h] + np.cross(omega, pole - links["com"][:, h])
        return {"com": com, "v_com": v, "R": links["R_link"][:, h], "omega": omega, "pole": pole, "v_pole": v_pole}

    # -------------------------------------------------------------- the interface
    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return PyBullet's segment states, from its link states."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        s, ref = self._segments(self._read(qpos, qvel)), self._ref
        return self.states_from(s, ref)

    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return ``Σ ½ m v_C² + ½ ω·I_C ω`` over PyBullet's links (no armature in a URDF)."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        links = self._read(qpos, qvel)
        m, D = self.tree.mass, self.tree.principal
        w_axes = np.einsum("plji,plj->pli", links["R_com"], links["omega"])  # ω in each link's principal axes
        rigid = 0.5 * (
            np.einsum("l,pli,pli->p", m, links["v"], links["v"]) + np.einsum("li,pli,pli->p", D, w_axes, w_axes)
        )
        return EnergyParts(rigid=rigid, armature=np.zeros_like(rigid), reported=rigid.copy())

    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``calculateMassMatrix`` in canonical velocity coordinates."""
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        q, _ = self.state_map.joints(qpos, np.zeros((qpos.shape[0], self.nv)))
        M = np.empty((qpos.shape[0], self.nv, self.nv))
        for p in range(qpos.shape[0]):
            M[p] = np.asarray(self.client.call("calculateMassMatrix", self.body, q[p].tolist()), dtype=float)
        return self.state_map.matrix_to_canonical(qpos, M)

    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return ``calculateInverseDynamics`` (gravity zero) in canonical coordinates."""
        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        sm = self.state_map
        T = sm.velocity_matrix(qpos)
        nu = np.einsum("pij,pj->pi", T, qvel)
        nu_dot = np.einsum("pij,pj->pi", T, qacc) + sm.acceleration_bias(qpos, qvel)
        q, _ = sm.joints(qpos, qvel)
        base = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0] if sm.base is not None else []
        tau = np.empty_like(nu)
        for p in range(qpos.shape[0]):
            out = self.client.call(
                "calculateInverseDynamics", self.body, base + q[p].tolist(), nu[p].tolist(), nu_dot[p].tolist()
            )
            tau[p] = out
        if sm.base is not None:  # PyBullet returns the base's force first, its torque second: ν has ω first
            tau[:, 0:6] = np.concatenate([tau[:, 3:6], tau[:, 0:3]], axis=1)
        return sm.force_to_canonical(qpos, tau)

    def armature_per_dof(self) -> np.ndarray:
        """A URDF has no armature: zero on every canonical dof.

        Returns
        -------
        ndarray, shape (nv,)
        """
        return np.zeros(self.nv)

    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by PyBullet joint type (``floating base``, ``revolute``, ...)."""
        types = self.tree.joint_types
        return dofs_by_kind(self.state_map.pairs, lambda p: "floating base" if p.kind == "free" else types[p.link])
