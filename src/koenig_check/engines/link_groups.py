"""Links grouped into segments: the links a joint moves together, and their lumped mass and central inertia.

An engine that reads a URDF link by link (PyBullet, iDynTree) keys a segment by the joint that moves its head link;
every link fixed to the head belongs to it.  A link welded to the world belongs to no segment, and a segment whose
links weigh nothing is left out (it has no kinetic energy) and named in one finding.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from koenig_check.engines.base import symmetrize
from koenig_check.findings import Finding, Kind


@dataclass(frozen=True)
class LinkGroups:
    """The segments of a model as groups of its links.

    Attributes
    ----------
    names : tuple of str
        The segments' canonical names, in the state map's joint order.
    heads : ndarray of int, shape (B,)
        Each segment's head link (the one its joint moves).
    members : list of ndarray of int
        Each segment's links (those with mass or inertia).
    massless : tuple of str
        The segments left out because their links weigh nothing, in the state map's order.
    """

    names: tuple[str, ...]
    heads: np.ndarray
    members: list[np.ndarray]
    massless: tuple[str, ...]

    def findings(self, engine: str) -> list[Finding]:
        """The one ``SEGMENTS`` finding naming the massless segments of ``engine`` (none when there are none).

        Parameters
        ----------
        engine : str

        Returns
        -------
        list of Finding
        """
        if not self.massless:
            return []
        names = "segments " + ", ".join(self.massless)
        return [Finding(Kind.SEGMENTS, engine, names, "massless: left out (no kinetic energy)")]

    def mass_average(self, mass: np.ndarray, values: np.ndarray) -> np.ndarray:
        """Each segment's mass-weighted mean of a per-link quantity (COM, COM velocity), per pose.

        Parameters
        ----------
        mass : ndarray, shape (L,)
        values : ndarray, shape (P, L, 3)

        Returns
        -------
        ndarray, shape (P, B, 3)
        """
        return np.stack([(mass[r, None] * values[:, r]).sum(1) / mass[r].sum() for r in self.members], axis=1)

    def lumped(
        self, mass: np.ndarray, com: np.ndarray, inertia: np.ndarray, rotation: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """Each segment's mass and central inertia in its head link's frame (parallel-axis theorem).

        Parameters
        ----------
        mass : ndarray, shape (L,)
        com : ndarray, shape (L, 3)
            Each link's COM, world frame, at one pose.
        inertia : ndarray, shape (L, 3, 3)
            Each link's central inertia in world axes, at the same pose.
        rotation : ndarray, shape (L, 3, 3)
            Each link's frame, world ← link, at the same pose.

        Returns
        -------
        mass : ndarray, shape (B,)
        inertia : ndarray, shape (B, 3, 3)
            Symmetric, about the segment's COM, in the head link's frame.
        """
        seg_mass, seg_inertia = [], []
        for h, rows in zip(self.heads, self.members, strict=True):
            m, c = mass[rows], com[rows]
            d = c - (m[:, None] * c).sum(0) / m.sum()
            shift = m[:, None, None] * (
                np.einsum("ki,ki->k", d, d)[:, None, None] * np.eye(3) - d[:, :, None] * d[:, None, :]
            )
            total = (inertia[rows] + shift).sum(0)
            seg_mass.append(m.sum())
            seg_inertia.append(rotation[h].T @ total @ rotation[h])
        return np.array(seg_mass, dtype=float), symmetrize(np.array(seg_inertia, dtype=float).reshape(-1, 3, 3))


def group_links(
    carrier: Sequence[int], weighs: np.ndarray, mass: np.ndarray, name_of: Mapping[int, str], order: Sequence[str]
) -> LinkGroups:
    """Group links into segments by the head link that carries each.

    Parameters
    ----------
    carrier : sequence of int
        Per link, the head link of the segment it moves with (-1: fixed to the world).
    weighs : ndarray of bool, shape (L,)
        The links that count (mass or inertia: a massless link's inertia counts).
    mass : ndarray, shape (L,)
    name_of : mapping of int to str
        Head link -> the canonical name of the joint that moves it, one per state-map pair.
    order : sequence of str
        The canonical joint names in the state map's order (the order of the segments).

    Returns
    -------
    LinkGroups
    """
    members: dict[int, list[int]] = {}
    for link, head in enumerate(carrier):
        if head >= 0 and weighs[link]:
            members.setdefault(head, []).append(link)
    members = {h: links for h, links in members.items() if mass[links].sum() > 0}
    rank = {name: k for k, name in enumerate(order)}
    heads = sorted(members, key=lambda h: rank[name_of[h]])
    return LinkGroups(
        names=tuple(name_of[h] for h in heads),
        heads=np.array(heads, dtype=int),
        members=[np.array(members[h], dtype=int) for h in heads],
        massless=tuple(name_of[h] for h in name_of if h not in members),
    )
