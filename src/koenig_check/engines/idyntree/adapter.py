"""iDynTree adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Callers pass canonical (MuJoCo-layout) states; :class:`~koenig_check.engines.idyntree.state_map.IDynTreeStateMap`
converts them to iDynTree's free-floating ``(world_H_base, s, ν)``, and its mass matrices and forces back.

Segments
--------
A segment is a link moved by a (non-fixed) joint, or the floating base, with every link fixed to it, keyed by the
joint's canonical name as for MuJoCo and Pinocchio.  Its mass and central inertia are lumped from iDynTree's own
per-link ``SpatialInertia`` (mass, COM and rotational inertia about the COM in the link's frame) at the reference
pose, in the head link's frame; its states come from ``getWorldTransform`` and ``getFrameVel`` of each link (its
origin's velocity and the angular velocity, world frame, in the mixed representation).  The pole is the head
link's origin, where a URDF joint's axis passes.

Energy
------
``KinDynComputations`` has no kinetic-energy function: the energy here is ``Σ ½ m v_C² + ½ ω·I_C ω`` over
iDynTree's links, from its link velocities and inertias (the self-consistency check compares it with ``½ q̇ᵀ M q̇``
of its ``getFreeFloatingMassMatrix``).  A URDF has no armature: the armature parts are zero.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.base import Engine, as_batches
from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.idyntree.state_map import IDynTreeStateMap, joint_kind
from koenig_check.engines.joint_pairs import dofs_by_kind
from koenig_check.engines.link_groups import group_links
from koenig_check.findings import Finding
from koenig_check.segments import SegmentStates


class IDynTreeEngine(Engine):
    """A URDF loaded in iDynTree.

    Parameters
    ----------
    model : idyntree.swig.Model
    kin_dyn : idyntree.swig.KinDynComputations
        On ``model``, base set, mixed velocity representation.
    state_map : IDynTreeStateMap
    path : Path
    qpos0 : ndarray, shape (nq,)
        The canonical reference configuration.
    findings : list of Finding, optional
    """

    engine = "idyntree"

    def __init__(
        self,
        model: Any,
        kin_dyn: Any,
        state_map: IDynTreeStateMap,
        path: Path,
        qpos0: np.ndarray,
        findings: list[Finding] | None = None,
    ) -> None:
        import idyntree.swig as idt

        self.model, self.kin_dyn, self.state_map = model, kin_dyn, state_map
        self.path = Path(path)
        self.findings = list(findings or [])
        self.nq, self.nv = state_map.nq, state_map.nv
        L = model.getNrOfLinks()
        inertia = [model.getLink(k).getInertia() for k in range(L)]
        self._link_mass = np.array([i.getMass() for i in inertia], dtype=float)
        self._link_com = np.array([i.getCenterOfMass().toNumPy() for i in inertia], dtype=float).reshape(-1, 3)
        self._link_inertia = np.array(
            [i.getRotationalInertiaWrtCenterOfMass().toNumPy() for i in inertia], dtype=float
        ).reshape(-1, 3, 3)
        self._wrenches = idt.LinkWrenches(model)
        self._torques = idt.FreeFloatingGeneralizedTorques(model)
        self._build_segments(np.asarray(qpos0, dtype=float), idt)

    # -------------------------------------------------------------- segments
    def _build_segments(self, qpos0: np.ndarray, idt: Any) -> None:
        model = self.model
        base = model.getLinkIndex(self.kin_dyn.getFloatingBase())
        traversal = idt.Traversal()
        model.computeFullTreeTraversal(traversal, base)
        name_of = {p.link: p.name for p in self.state_map.pairs}

        def carrier(head: int) -> int:  # the head link of the segment a link moves with (-1: the fixed base)
            while head not in name_of:
                joint = traversal.getParentJointFromLinkIndex(head)
                if joint is None or joint_kind(joint) != "fixed":  # the fixed base, or a joint MuJoCo lacks
                    return -1
                head = traversal.getParentLinkFromLinkIndex(head).getIndex()
            return head

        weighs = (self._link_mass > 0) | self._link_inertia.any(axis=(1, 2))
        order = [p.name for p in self.state_map.pairs]
        groups = group_links([carrier(k) for k in range(model.getNrOfLinks())], weighs, self._link_mass, name_of, order)
        self.findings.extend(groups.findings(self.engine))
        self.segment_names, self._groups = groups.names, groups
        self._heads, self._members = groups.heads, groups.members
        ref = self._read(qpos0[None], np.zeros((1, self.nv)))
        R = ref["R"][0]
        inertia = R @ self._link_inertia @ np.swapaxes(R, 1, 2)
        self._mass, self._inertia = groups.lumped(self._link_mass, ref["com"][0], inertia, R)
        self._ref = self._segments(ref)

    # -------------------------------------------------------------- reading iDynTree
    def _set(self, H: np.ndarray, s: np.ndarray, nu: np.ndarray) -> None:
        self.kin_dyn.setRobotState(H, s, nu[:6], nu[6:], np.zeros(3))

    def _read(self, qpos: np.ndarray, qvel: np.ndarray) -> dict[str, np.ndarray]:
        """Every link's frame, COM, COM velocity and angular velocity (world), per pose."""
        sm, kd = self.state_map, self.kin_dyn
        H, s = sm.base_pose(qpos), sm.joint_positions(qpos)
        nu = np.einsum("pij,pj->pi", sm.velocity_matrix(qpos), qvel)
        P, L = qpos.shape[0], len(self._link_mass)
        R, o, v, w = np.zeros((P, L, 3, 3)), np.zeros((P, L, 3)), np.zeros((P, L, 3)), np.zeros((P, L, 3))
        for p in range(P):
            self._set(H[p], s[p], nu[p])
            for link in range(L):
                X = kd.getWorldTransform(link)
                R[p, link], o[p, link] = X.getRotation().toNumPy(), X.getPosition().toNumPy()
                twist = kd.getFrameVel(link).toNumPy()
                v[p, link], w[p, link] = twist[:3], twist[3:]
        arm = np.einsum("plij,lj->pli", R, self._link_com)
        return {"R": R, "origin": o, "com": o + arm, "v": v + np.cross(w, arm), "omega": w, "v_origin": v}

    def _segments(self, links: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """Segment COM, COM velocity, rotation, angular velocity, pole and its velocity, per pose."""
        m, h = self._link_mass, self._heads
        return {
            "com": self._groups.mass_average(m, links["com"]),
            "v_com": self._groups.mass_average(m, links["v"]),
            "R": links["R"][:, h],
            "omega": links["omega"][:, h],
            "pole": links["origin"][:, h],
            "v_pole": links["v_origin"][:, h],
        }

    # -------------------------------------------------------------- the interface
    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return iDynTree's segment states, from its link transforms and velocities."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        s, ref = self._segments(self._read(qpos, qvel)), self._ref
        return self.states_from(s, ref)

    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return ``Σ ½ m v_C² + ½ ω·I_C ω`` over iDynTree's links (no armature in a URDF)."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        links = self._read(qpos, qvel)
        w_link = np.einsum("plji,plj->pli", links["R"], links["omega"])  # ω in each link's frame
        rigid = 0.5 * (
            np.einsum("l,pli,pli->p", self._link_mass, links["v"], links["v"])
            + np.einsum("pli,lij,plj->p", w_link, self._link_inertia, w_link)
        )
        return EnergyParts(rigid=rigid, armature=np.zeros_like(rigid), reported=rigid.copy())

    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return ``getFreeFloatingMassMatrix`` in canonical velocity coordinates (a fixed base: its joint block)."""
        import idyntree.swig as idt

        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        sm = self.state_map
        H, s = sm.base_pose(qpos), sm.joint_positions(qpos)
        n = 6 + sm.n_dofs
        M, buffer = np.empty((qpos.shape[0], n, n)), idt.MatrixDynSize(n, n)
        for p in range(qpos.shape[0]):
            self._set(H[p], s[p], np.zeros(n))
            self.kin_dyn.getFreeFloatingMassMatrix(buffer)
            M[p] = buffer.toNumPy()
        return sm.matrix_to_canonical(qpos, M)

    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return ``inverseDynamics`` (gravity and external wrenches zero) in canonical coordinates."""
        import idyntree.swig as idt

        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        sm = self.state_map
        T = sm.velocity_matrix(qpos)
        nu = np.einsum("pij,pj->pi", T, qvel)
        nu_dot = np.einsum("pij,pj->pi", T, qacc) + sm.acceleration_bias(qpos, qvel)
        H, s = sm.base_pose(qpos), sm.joint_positions(qpos)
        tau = np.empty_like(nu)
        for p in range(qpos.shape[0]):
            self._set(H[p], s[p], nu[p])
            self._wrenches.zero()
            self.kin_dyn.inverseDynamics(
                idt.Vector6.FromPython(nu_dot[p, :6].tolist()),
                idt.VectorDynSize.FromPython(nu_dot[p, 6:].tolist()),
                self._wrenches,
                self._torques,
            )
            tau[p, :6] = self._torques.baseWrench().toNumPy()
            tau[p, 6:] = self._torques.jointTorques().toNumPy()
        return sm.force_to_canonical(qpos, tau)

    def segment_of_link(self) -> dict[int, str]:
        """Link index (iDynTree's) -> the segment it moves with (links fixed to the world, massless segments left out).

        Returns
        -------
        dict of int to str
        """
        return {int(k): self.segment_names[b] for b, links in enumerate(self._members) for k in links}

    def armature_per_dof(self) -> np.ndarray:
        """A URDF has no armature: zero on every canonical dof.

        Returns
        -------
        ndarray, shape (nv,)
        """
        return np.zeros(self.nv)

    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by iDynTree joint type (``floating base``, ``revolute``, ...)."""
        words = {"free": "floating base", "hinge": "revolute", "slide": "prismatic"}
        return dofs_by_kind(self.state_map.pairs, lambda p: words[p.kind])
