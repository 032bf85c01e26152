"""MuJoCo adapter: segment states, point velocities, energy, mass matrix, inverse dynamics.

Segments
--------
A segment is a body carrying at least one joint, together with every jointless descendant body
welded to it (MuJoCo keeps those as separate bodies unless ``fusestatic`` fused them); bodies
welded to the world are not segments.  The lumped mass, COM and central inertia (parallel-axis
theorem) are expressed in the segment body's frame (``xpos``/``xmat``), computed once from the
compiled ``body_mass``, ``xipos``, ``ximat`` and ``body_inertia`` at ``qpos0``.  The segment is named
after the body's last joint; its pole is that joint's anchor as a point of the segment,
``xpos + xmat · jnt_pos``.  That is MuJoCo's ``xanchor`` for hinge, ball and free joints; for a slide
joint ``xanchor`` stays on the parent (it is computed before the displacement) while the pole here
moves with the segment, like Pinocchio's joint origin.

Velocities come from ``cvel``: the body's spatial velocity ``(ω, v)`` in world orientation,
referred to the ``subtree_com`` of the body's root (verified against ``mj_objectVelocity`` in
MuJoCo 4.0), so a point ``p`` of the body moves with ``v + ω × (p - subtree_com[root])``.

Dynamics (energy, mass matrix, inverse dynamics) are :class:`~koenig_check.engines.mujoco.dynamics.MujocoDynamics`.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.base import Engine, as_batches, check_points, rows, states_point_velocities, symmetrize
from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.engines.mujoco.dynamics import MujocoDynamics
from koenig_check.engines.mujoco.gravity import MujocoGravity
from koenig_check.engines.planes import (
    byte_view,
    entry_index,
    gather_planes,
    matrices,
    moved_point_velocity,
    rotate_constant,
    vectors,
)
from koenig_check.findings import Finding, Kind
from koenig_check.kernels import cross, rotate_points
from koenig_check.segments import SegmentStates

_KIND = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}


class MujocoEngine(MujocoGravity, MujocoDynamics, Engine):
    """A model loaded in MuJoCo.

    Parameters
    ----------
    model : mujoco.MjModel
    path : Path
        The model file.
    findings : list of Finding
        Load findings (extended here with segment findings).
    body_findings : list of (str, Finding), optional
        ``(body, finding)`` from the loader: bodies whose mass properties MuJoCo changed; each
        finding is recorded with the segment the body belongs to.

    Attributes
    ----------
    findings : list of Finding
    """

    engine = "mujoco"

    def __init__(
        self,
        model: mujoco.MjModel,
        path: Path,
        findings: list[Finding] | None = None,
        body_findings: list[tuple[str, Finding]] | None = None,
    ) -> None:
        self.model = model
        self.path = Path(path)
        self.findings = list(findings or [])
        self.nq, self.nv = int(model.nq), int(model.nv)
        self.joint_names = tuple(mujoco_joint_names(model))
        self._data = mujoco.MjData(model)
        self._build_segments()
        for body, finding in body_findings or []:
            bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
            seg = self._segment_of[bid] if bid >= 0 else ""
            self.findings.append(replace(finding, segments=(seg,) if seg else ()))

    def segment_bodies(self) -> dict[str, str]:
        """Each segment's first body, as the file names it (the link or body its joint moves).

        Returns
        -------
        dict of str to str
            Segment name -> body name ("" for an unnamed body).
        """
        return {
            name: mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_BODY, int(b)) or ""
            for name, b in zip(self.segment_names, self._seg_body, strict=True)
        }

    def dof_segments(self) -> tuple[str, ...]:
        """Name of the segment each canonical degree of freedom moves (its body's segment).

        Returns
        -------
        tuple of str
            One name per dof, in canonical order.
        """
        return tuple(self._segment_of[int(b)] for b in self.model.dof_bodyid)

    # -------------------------------------------------------------- segments
    def _build_segments(self) -> None:
        m = self.model
        seg_of = np.full(m.nbody, -1, dtype=int)
        for b in range(1, m.nbody):  # parents come before children
            if m.body_jntnum[b] > 0:
                seg_of[b] = b
            else:
                seg_of[b] = seg_of[m.body_parentid[b]]
        heads = np.flatnonzero(m.body_jntnum > 0)
        last = m.body_jntadr + m.body_jntnum - 1
        self._segment_of = [self.joint_names[last[s]] if s > 0 else "" for s in seg_of]
        d = mujoco.MjData(m)
        d.qpos[:] = m.qpos0
        mujoco.mj_kinematics(m, d)
        members = np.flatnonzero(seg_of > 0)
        head_of = seg_of[members]
        R_s = d.xmat[head_of].reshape(-1, 3, 3)
        mass_b = m.body_mass[members]
        r_b = np.einsum("bji,bj->bi", R_s, d.xipos[members] - d.xpos[head_of])
        Ri = np.einsum("bji,bjk->bik", R_s, d.ximat[members].reshape(-1, 3, 3))  # segment <- inertial
        I_b = Ri @ (m.body_inertia[members][:, :, None] * np.swapaxes(Ri, -1, -2))
        slot = np.searchsorted(heads, head_of)
        mass = np.zeros(len(heads))
        np.add.at(mass, slot, mass_b)
        first = np.zeros((len(heads), 3))
        np.add.at(first, slot, mass_b[:, None] * r_b)
        com = first / np.where(mass > 0, mass, 1.0)[:, None]
        dvec = r_b - com[slot]
        shift = mass_b[:, None, None] * (
            np.einsum("bi,bi->b", dvec, dvec)[:, None, None] * np.eye(3) - dvec[:, :, None] * dvec[:, None, :]
        )
        inertia = np.zeros((len(heads), 3, 3))
        np.add.at(inertia, slot, I_b + shift)
        last_joint = m.body_jntadr[heads] + m.body_jntnum[heads] - 1
        names = [self.joint_names[j] for j in last_joint]
        keep = mass > 0
        if not keep.all():
            dropped = [n for n, k in zip(names, keep, strict=True) if not k]
            self.findings.append(
                Finding(
                    Kind.SEGMENTS, "mujoco", "segments " + ", ".join(dropped), "massless: left out (no kinetic energy)"
                )
            )
        self._seg_body = heads[keep]
        self._seg_root = m.body_rootid[self._seg_body]
        self._seg_joint = last_joint[keep]
        self._anchor_local = np.asarray(m.jnt_pos[self._seg_joint], dtype=float).reshape(-1, 3)
        self.segment_names = tuple(n for n, k in zip(names, keep, strict=True) if k)
        self._mass = mass[keep]
        self._com_local = com[keep]
        self._inertia = symmetrize(inertia[keep])
        roots = rows(self._seg_root)  # one root body for every segment: one row, broadcast
        root_rows = self._seg_root[:1] if isinstance(roots, slice) and roots.stop - roots.start == 1 else self._seg_root
        # Where each segment's entries sit in a pose's flat xpos (3), xmat (9), cvel (6) and subtree_com (3).
        self._index = {
            "xpos": entry_index(self._seg_body, 3, range(3)),
            "xmat": entry_index(self._seg_body, 9, range(9)),
            "cvel": entry_index(self._seg_body, 6, range(6)),
            "ref": entry_index(root_rows, 3, range(3)),
        }
        ref = self._sweep(m.qpos0[None], np.zeros((1, m.nv)))
        R0, x0 = matrices(ref["xmat"])[0].copy(), vectors(ref["xpos"])[0].copy()
        # The reference configuration, once per model.
        self._ref = {
            "rotation": R0,
            "com": x0 + np.einsum("bij,bj->bi", R0, self._com_local),
            "pole": vectors(ref["anchor"])[0].copy(),
        }

    def _sweep(self, qpos: np.ndarray, qvel: np.ndarray, energies: bool = False) -> dict[str, np.ndarray]:
        """Run the engine once per pose, copy its body arrays whole; return the segments' entries as planes.

        Per pose, ``xpos``, ``xmat``, ``cvel`` and ``subtree_com`` are copied whole (one copy each);
        the segments' entries of every pose are then gathered at once into (k, P, B) planes
        (:func:`~koenig_check.engines.planes.gather_planes`): ``xpos`` (3), ``xmat`` (9, row-major),
        ``cvel`` (6: ω then v), ``ref`` (3: each segment's root ``subtree_com``, (3, P, 1) when
        every segment hangs from one root body) and ``anchor`` (3).

        With ``energies``, the same pass also evaluates ``mj_makeM`` + ``mj_energyVel`` (``½ q̇ᵀ M q̇``,
        armature included) without running the kinematics again; ``rigid`` is that minus the
        armature term, as in :meth:`kinetic_energy` (a copy with ``dof_armature`` zeroed would keep
        the armature of the dofs whose diagonal MuJoCo precomputes at compile time).
        """
        m, d = self.model, self._data
        qpos, qvel = np.ascontiguousarray(qpos, dtype=float), np.ascontiguousarray(qvel, dtype=float)
        P, nb = qpos.shape[0], m.nbody
        xpos, xmat = np.empty((P, nb * 3)), np.empty((P, nb * 9))
        cvel, sub = np.empty((P, nb * 6)), np.empty((P, nb * 3))
        rigid = np.empty(P)
        kinematics, com_pos, com_vel = mujoco.mj_kinematics, mujoco.mj_comPos, mujoco.mj_comVel
        make_m, energy_vel = mujoco.mj_makeM, mujoco.mj_energyVel
        # Every per-pose copy is a slice assignment between byte views (see planes.byte_view), taken once here:
        # MjData's arrays are views of its own buffers, each attribute access would build a new one.
        q_in, v_in = byte_view(qpos), byte_view(qvel)
        q_d, v_d = byte_view(d.qpos), byte_view(d.qvel)
        x_in, r_in, c_in, s_in = (byte_view(a) for a in (d.xpos, d.xmat, d.cvel, d.subtree_com))
        x_out, r_out, c_out, s_out = (byte_view(a) for a in (xpos, xmat, cvel, sub))
        nq, nv, nx, nr, nc, ns = (len(v) for v in (q_d, v_d, x_in, r_in, c_in, s_in))
        e_in, e_out = byte_view(d.energy)[8:16], byte_view(rigid)  # energy[1]: the kinetic energy
        for p in range(P):
            q_d[:] = q_in[p * nq : (p + 1) * nq]
            v_d[:] = v_in[p * nv : (p + 1) * nv]
            kinematics(m, d)
            com_pos(m, d)
            com_vel(m, d)
            x_out[p * nx : (p + 1) * nx] = x_in
            r_out[p * nr : (p + 1) * nr] = r_in
            c_out[p * nc : (p + 1) * nc] = c_in
            s_out[p * ns : (p + 1) * ns] = s_in
            if energies:
                make_m(m, d)
                energy_vel(m, d)
                e_out[p * 8 : (p + 1) * 8] = e_in
        index = self._index
        out = {name: gather_planes(raw, index[name]) for name, raw in zip(index, (xpos, xmat, cvel, sub), strict=True)}
        out["anchor"] = rotate_constant(out["xmat"], self._anchor_local)
        out["anchor"] += out["xpos"]
        if energies:
            out["armature"] = 0.5 * (qvel**2) @ m.dof_armature
            out["rigid"] = rigid - out["armature"]
        return out

    def _states(self, s: dict[str, np.ndarray], trusted: bool = False) -> SegmentStates:
        R, V = s["xmat"], s["cvel"]
        com = rotate_constant(R, self._com_local)
        com += s["xpos"]
        omega, v_ref = V[:3], V[3:]
        ref = self._ref
        return (SegmentStates.trusted if trusted else SegmentStates)(
            names=self.segment_names,
            mass=self._mass,
            inertia_body=self._inertia,
            com=vectors(com),
            v_com=vectors(moved_point_velocity(v_ref, omega, com, s["ref"])),
            rotation=matrices(R),
            omega=vectors(omega),
            pole=vectors(s["anchor"]),
            v_pole=vectors(moved_point_velocity(v_ref, omega, s["anchor"], s["ref"])),
            rotation_ref=ref["rotation"],
            com_ref=ref["com"],
            pole_ref=ref["pole"],
        )

    def _points(self, s: dict[str, np.ndarray], points: np.ndarray) -> np.ndarray:
        local = self._com_local[:, None, :] + points
        xpos, xmat, ref = vectors(s["xpos"]), matrices(s["xmat"]), vectors(s["ref"])
        world = (xpos - ref)[:, :, None, :] + rotate_points(xmat, local)
        cvel = vectors(s["cvel"])
        omega, v_ref = cvel[:, :, None, :3], cvel[:, :, None, 3:]
        return v_ref + cross(omega, world)

    def sweep(
        self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray | None = None
    ) -> tuple[SegmentStates, np.ndarray | None, np.ndarray, np.ndarray]:
        """Segment states, point velocities and energy from one pass of the engine per pose.

        The internal path of the comparison: the states are not validated again (the
        model was checked at load), and every quantity is read once per pose.
        """
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        s = self._sweep(qpos, qvel, energies=True)
        states = self._states(s, trusted=True)
        pv = states_point_velocities(states, points)
        return states, pv, s["rigid"], s["armature"]

    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return MuJoCo's segment states for a batch of canonical states."""
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        return self._states(self._sweep(qpos, qvel))

    def point_velocities(
        self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray, method: str = "spatial"
    ) -> np.ndarray:
        """Return the world velocity of points fixed in the segments.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)
        points : ndarray, shape (B, K, 3)
            Offsets from each segment's COM, in the segment's axes.
        method : {"spatial", "jacobian"}
            ``"spatial"``: the body spatial velocity ``cvel`` applied to the points (vectorized);
            ``"jacobian"``: ``mj_jac`` of every point times ``qvel`` (one engine call per point).

        Returns
        -------
        ndarray, shape (P, B, K, 3)
        """
        qpos, qvel = as_batches(qpos, self.nq, (qvel, "qvel"), nv=self.nv)
        pts = check_points(points, len(self.segment_names))
        if method == "spatial":
            return self._points(self._sweep(qpos, qvel), pts)
        if method != "jacobian":
            raise ValueError(f"method must be 'spatial' or 'jacobian', got {method!r}")
        local = self._com_local[:, None, :] + pts
        m, d = self.model, self._data
        P, (B, K, _) = qpos.shape[0], pts.shape
        out = np.empty((P, B, K, 3))
        jacp = np.zeros((3, self.nv))
        for p in range(P):
            d.qpos[:] = qpos[p]
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            world = d.xpos[self._seg_body][:, None, :] + np.einsum(
                "bij,bkj->bki", d.xmat[self._seg_body].reshape(-1, 3, 3), local
            )
            for b, body in enumerate(self._seg_body):
                for k in range(K):
                    mujoco.mj_jac(m, d, jacp, None, world[b, k], int(body))
                    out[p, b, k] = jacp @ qvel[p]
        return out

    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by MuJoCo joint type.

        Returns
        -------
        dict
            ``{"hinge": array([...]), ...}``
        """
        m = self.model
        groups: dict[str, list[int]] = {}
        for j in range(m.njnt):
            n = {0: 6, 1: 3}.get(int(m.jnt_type[j]), 1)
            groups.setdefault(_KIND[int(m.jnt_type[j])], []).extend(range(m.jnt_dofadr[j], m.jnt_dofadr[j] + n))
        return {k: np.array(v, dtype=int) for k, v in groups.items()}
