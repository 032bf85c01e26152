"""The one interface every engine adapter implements (:class:`Engine`), and helpers the adapters share."""

from __future__ import annotations

from abc import ABC, abstractmethod
from pathlib import Path

import numpy as np

from koenig_check.engines.energy import EnergyParts
from koenig_check.engines.potential import GravityTerms
from koenig_check.findings import Finding
from koenig_check.kernels import body_point_velocities
from koenig_check.segments import SegmentStates


class Engine(GravityTerms, ABC):
    """A model loaded in one engine, answering for batches of canonical states.

    Every engine adapter (MuJoCo, Pinocchio, Drake, and any engine added later) derives from this class and
    implements its abstract methods, and the gravity methods of :class:`~koenig_check.engines.potential.GravityTerms`
    where it can; the checker calls nothing else.  Every method takes canonical (MuJoCo-layout,
    :mod:`koenig_check.engines.canonical`) states: ``qpos`` (P, nq), ``qvel``/``qacc`` (P, nv).

    Attributes
    ----------
    engine : str
        The engine's name (one of :func:`koenig_check.engines.registry.names`).
    path : Path
        The file the engine read.
    findings : list of Finding
        What was learned while loading it.
    segment_names : tuple of str
        The segments (bodies moved by one joint, keyed by that joint) with mass, in the engine's order.
    nq, nv : int
        Canonical sizes.
    """

    engine: str
    path: Path
    findings: list[Finding]
    segment_names: tuple[str, ...]
    nq: int
    nv: int
    #: Per segment, in :attr:`segment_names` order: mass (B,) and central inertia in the segment's axes (B, 3, 3).
    _mass: np.ndarray
    _inertia: np.ndarray

    def mass_properties(self) -> tuple[np.ndarray, np.ndarray]:
        """Each segment's mass (B,) and central inertia in its own axes (B, 3, 3): constant over poses.

        Returns
        -------
        mass : ndarray, shape (B,)
        inertia : ndarray, shape (B, 3, 3)
        """
        return self._mass, self._inertia

    def sweep(
        self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray | None = None
    ) -> tuple[SegmentStates, np.ndarray | None, np.ndarray, np.ndarray]:
        """Segment states, point velocities and energy of a batch: what the comparison reads per pose.

        Engines that can read all three in one pass per pose override this; the default calls
        :meth:`segment_states`, :meth:`kinetic_energy` and :meth:`point_velocities`.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)
        points : ndarray, shape (B, K, 3), optional
            Offsets from each segment's COM, in the segment's axes.

        Returns
        -------
        states : SegmentStates
        point_velocities : ndarray, shape (P, B, K, 3), or None without ``points``
        rigid, armature : ndarray, shape (P,)
            ``rigid`` and ``armature`` of :meth:`kinetic_energy`.
        """
        states = self.segment_states(qpos, qvel)
        energy = self.kinetic_energy(qpos, qvel)
        pv = None if points is None else self.point_velocities(qpos, qvel, points)
        return states, pv, np.asarray(energy.rigid), np.asarray(energy.armature)

    # The contract of each method (parameters, shapes, returns) is documented here once; an adapter's
    # override says in one line only how its engine answers.
    @abstractmethod
    def segment_states(self, qpos: np.ndarray, qvel: np.ndarray) -> SegmentStates:
        """Return the engine's segment states (pose, velocity, mass properties of each segment) per pose.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        SegmentStates
        """

    def point_velocities(self, qpos: np.ndarray, qvel: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Return the world velocity of points fixed in the segments.

        By default from :meth:`segment_states` (each segment's COM velocity, ω and rotation); an engine with a
        faster route of its own overrides it.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)
        points : ndarray, shape (B, K, 3)
            Offsets from each segment's COM, in the segment's axes.

        Returns
        -------
        ndarray, shape (P, B, K, 3)
        """
        out = states_point_velocities(self.segment_states(qpos, qvel), points)
        assert out is not None  # points were given
        return out

    def states_from(self, current: dict[str, np.ndarray], ref: dict[str, np.ndarray]) -> SegmentStates:
        """Segment states from an adapter's arrays: ``com``, ``v_com``, ``R``, ``omega``, ``pole``, ``v_pole``.

        Parameters
        ----------
        current : dict of str to ndarray
            Each of shape (P, B, ...), at the poses asked for.
        ref : dict of str to ndarray
            The same at the reference configuration (P = 1).

        Returns
        -------
        SegmentStates
        """
        return SegmentStates(
            names=self.segment_names,
            mass=self._mass,
            inertia_body=self._inertia,
            com=current["com"],
            v_com=current["v_com"],
            rotation=current["R"],
            omega=current["omega"],
            pole=current["pole"],
            v_pole=current["v_pole"],
            rotation_ref=ref["R"][0],
            com_ref=ref["com"][0],
            pole_ref=ref["pole"][0],
        )

    @abstractmethod
    def kinetic_energy(self, qpos: np.ndarray, qvel: np.ndarray) -> EnergyParts:
        """Return the engine's kinetic energy, the rigid-body part and the armature part apart.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel : ndarray, shape (P, nv)

        Returns
        -------
        EnergyParts
        """

    @abstractmethod
    def mass_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return the mass matrix, armature included, in canonical velocity coordinates.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv, nv)
        """

    @abstractmethod
    def inverse_dynamics(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return the generalized forces (gravity, damping and applied forces zero), canonical coordinates.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel, qacc : ndarray, shape (P, nv)

        Returns
        -------
        ndarray, shape (P, nv)
        """

    def armature_per_dof(self) -> np.ndarray:
        """Return the armature (rotor inertia) of each canonical dof, for an engine whose armature is diagonal there.

        The defaults of :meth:`armature_matrix` and :meth:`armature_forces` are built on it.  An engine whose
        armature is diagonal in its own velocity coordinates but not in the canonical ones (Pinocchio's free
        and ball joints) overrides those two methods instead.

        Returns
        -------
        ndarray, shape (nv,)

        Raises
        ------
        NotImplementedError
            The engine overrides :meth:`armature_matrix` and :meth:`armature_forces` instead.
        """
        raise NotImplementedError(
            f"{type(self).__name__} has no armature per canonical dof: it overrides armature_matrix and armature_forces"
        )

    def armature_matrix(self, qpos: np.ndarray) -> np.ndarray:
        """Return the armature part of :meth:`mass_matrix`, canonical coordinates.

        The default: :meth:`armature_per_dof` on the diagonal, the same at every pose.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)

        Returns
        -------
        ndarray, shape (P, nv, nv)
            Read-only (one matrix broadcast over the poses).
        """
        (qpos,) = as_batches(qpos, self.nq, nv=self.nv)
        return np.broadcast_to(np.diag(self.armature_per_dof()), (qpos.shape[0], self.nv, self.nv))

    def armature_forces(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """Return the armature part of :meth:`inverse_dynamics`, canonical coordinates.

        The default: :meth:`armature_per_dof` times ``qacc``, dof by dof.

        Parameters
        ----------
        qpos : ndarray, shape (P, nq)
        qvel, qacc : ndarray, shape (P, nv)

        Returns
        -------
        ndarray, shape (P, nv)
        """
        qpos, qvel, qacc = as_batches(qpos, self.nq, (qvel, "qvel"), (qacc, "qacc"), nv=self.nv)
        return qacc * self.armature_per_dof()

    @abstractmethod
    def dofs_by_kind(self) -> dict[str, np.ndarray]:
        """Return canonical dof indices grouped by the engine's joint kind.

        Returns
        -------
        dict of str to ndarray of int
        """


def as_batch(x: np.ndarray, n: int, what: str) -> np.ndarray:
    """Return ``x`` as a float array of shape (P, n).

    Parameters
    ----------
    x : array_like, shape (P, n) or (n,)
    n : int
    what : str
        Name for the error message.

    Returns
    -------
    ndarray, shape (P, n)

    Raises
    ------
    ValueError
        On a wrong shape.
    """
    arr = np.atleast_2d(np.asarray(x, dtype=float))
    if arr.ndim != 2 or arr.shape[1] != n:
        raise ValueError(f"{what}: expected shape (P, {n}), got {np.shape(x)}")
    return arr


def as_batches(qpos: np.ndarray, nq: int, *vels: tuple[np.ndarray, str], nv: int) -> list[np.ndarray]:
    """Validate a position batch and velocity-like batches with the same number of poses.

    Parameters
    ----------
    qpos : array_like, shape (P, nq)
    nq : int
    *vels : (array_like, name)
        Velocity-like arrays of shape (P, nv).
    nv : int

    Returns
    -------
    list of ndarray
        ``[qpos, *vels]`` as 2-D float arrays.
    """
    q = as_batch(qpos, nq, "qpos")
    out = [q]
    for arr, what in vels:
        a = as_batch(arr, nv, what)
        if a.shape[0] != q.shape[0]:
            raise ValueError(f"{what} has {a.shape[0]} poses, qpos has {q.shape[0]}")
        out.append(a)
    return out


def check_points(points: np.ndarray, n_segments: int) -> np.ndarray:
    """Validate a (B, K, 3) array of points, one set per segment.

    Parameters
    ----------
    points : array_like, shape (B, K, 3)
    n_segments : int

    Returns
    -------
    ndarray, shape (B, K, 3)
    """
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 3 or pts.shape[0] != n_segments or pts.shape[2] != 3:
        raise ValueError(f"points: expected shape ({n_segments}, K, 3), got {pts.shape}")
    return pts


def states_point_velocities(states: SegmentStates, points: np.ndarray | None) -> np.ndarray | None:
    """The world velocities of points fixed in the segments, from the segments' states (None without points).

    Parameters
    ----------
    states : SegmentStates
    points : ndarray, shape (B, K, 3), optional
        Offsets from each segment's COM, in the segment's axes.

    Returns
    -------
    ndarray, shape (P, B, K, 3), or None
    """
    if points is None:
        return None
    pts = check_points(points, len(states.names))
    return body_point_velocities(states.v_com, states.omega, states.rotation, pts)


def symmetrize(inertia: np.ndarray) -> np.ndarray:
    """Return ``½ (I + Iᵀ)`` over the last two axes.

    Parameters
    ----------
    inertia : ndarray, shape (..., 3, 3)

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    return 0.5 * (inertia + np.swapaxes(inertia, -1, -2))


def rows(index: np.ndarray) -> slice | np.ndarray:
    """An index along an axis as a slice where it can be one (a view instead of a copy), else itself.

    Parameters
    ----------
    index : ndarray of int, shape (n,)

    Returns
    -------
    slice or ndarray
        ``slice(a, a + n)`` for consecutive indices ``a, a + 1, ...``; ``slice(a, a + 1)`` (one row,
        broadcast along the axis) when every index is ``a``; otherwise ``index``.
    """
    index = np.asarray(index)
    if index.size and np.array_equal(index, index[0] + np.arange(index.size)):
        return slice(int(index[0]), int(index[0]) + index.size)
    if index.size and (index == index[0]).all():
        return slice(int(index[0]), int(index[0]) + 1)
    return index
