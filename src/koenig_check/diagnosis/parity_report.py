"""The import parity of one model as data: per segment, per dof, and the root causes that explain them.

What :func:`koenig_check.diagnosis.import_parity.import_parity` measures, and how a report is read: whether it
is clean, which symptoms a root cause explains, its findings and its one-line headline.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from koenig_check.engines.registry import label as engine_label
from koenig_check.engines.specs import parity_pair
from koenig_check.findings import Finding, Kind

#: Default relative tolerance of parity comparisons.
PARITY_RTOL = 1e-9
#: Per-segment symptoms that a root cause of each kind explains (other kinds explain every symptom).
_ALL_SYMPTOMS = frozenset({"mass", "com", "inertia", "anchor", "axis", "armature", "missing"})
_EXPLAINS = {
    Kind.MASS: frozenset({"mass", "com", "inertia"}),
    Kind.COMPILER: frozenset({"mass", "com", "inertia"}),
    Kind.COM: frozenset({"com", "inertia"}),
    Kind.ANCHOR: frozenset({"anchor", "com", "axis"}),
}


#: Parity cause -> finding kind.
_PARITY_KINDS = {
    "mass": Kind.MASS,
    "com": Kind.COM,
    "inertia": Kind.INERTIA,
    "anchor": Kind.ANCHOR,
    "axis": Kind.AXIS,
    "armature": Kind.ARMATURE,
}


@dataclass(frozen=True)
class SegmentParity:
    """Engine A (MuJoCo) versus engine B (Pinocchio) for one segment.

    Attributes
    ----------
    name : str
    mass : tuple of float
        (MuJoCo, Pinocchio) mass in kg.
    com_distance : float
        Distance between the two centres of mass at the reference pose (m).
    inertia_frobenius : float
        Frobenius norm of the difference of the world-axis central inertias (kg m²).
    principal_moments : tuple of ndarray
        (MuJoCo, Pinocchio) principal central moments, ascending.
    pole_distance : float
        Distance between the two joint anchors (m).
    causes : tuple of str
        Which quantities differ beyond tolerance (``mass``, ``com``, ``inertia``, ``anchor``).
    relative : dict of str to float
        Per quantity, its difference relative to its scale (what the tolerance is compared with): the mass
        to the larger mass, lengths to the model's size, inertias to the inertia about the anchor
        (largest central principal moment + m |com - pole|², :meth:`SegmentStates.inertia_about_anchor`).
    """

    name: str
    mass: tuple[float, float]
    com_distance: float
    inertia_frobenius: float
    principal_moments: tuple[np.ndarray, np.ndarray]
    pole_distance: float
    causes: tuple[str, ...]
    relative: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class DofParity:
    """Engine A versus engine B for one degree of freedom.

    Attributes
    ----------
    dof : int
        Canonical (MuJoCo) dof index.
    joint : str
    armature : tuple of float
        (MuJoCo, Pinocchio) rotor inertia on this dof.
    jacobian_difference : float
        Largest difference of the angular velocity (rad/s) and pole velocity (m/s) of the dof's
        own segment under a unit rate of this dof: a different joint axis (NaN when that segment
        exists in one engine only).
    causes : tuple of str
        ``axis`` and/or ``armature`` when they differ.
    relative : dict of str to float
        Per quantity, its difference relative to its scale (see :class:`SegmentParity`).
    missing : str
        Why the Jacobians were not compared, when the dof's segment exists in one engine only (``"segment j2
        massless in Pinocchio"``); empty when they were.
    """

    dof: int
    joint: str
    armature: tuple[float, float]
    jacobian_difference: float
    causes: tuple[str, ...]
    relative: dict[str, float] = field(default_factory=dict)
    missing: str = ""


@dataclass
class ParityReport:
    """Import parity of one model.

    Attributes
    ----------
    model : str
    segments : list of SegmentParity
    dofs : list of DofParity
    only_in_mujoco, only_in_pinocchio : list of str
        Segments one engine has and the other does not (fused or dropped bodies); a segment the
        other engine has but gives no mass is in ``massless_in_*`` instead.
    massless_in_pinocchio, massless_in_mujoco : list of str
        Segments with mass in one engine and none in the other.
    total_mass : tuple of float
        The moving mass (the segments': bodies welded to the world are not counted), MuJoCo and Pinocchio.
    model_mass : float
        The mass of every body, static ones included (Pinocchio's, which keeps the links welded to the world).
    findings : list of str
        Model-level findings (compiler options, inertia from geometry, load notes).
    causes : list of Finding
        Root causes (typed records), those that change the energy first.
    mass_matrix_max_rel : float
        Largest relative difference of the two mass matrices over the checked poses.
    rtol : float
    frame_offset : FrameOffset or None
        ``world_mujoco <- world_pinocchio`` when Pinocchio dropped a jointless root body's pose (computed once,
        with the causes: :func:`koenig_check.diagnosis.root_frame.root_frame_offset`).
    """

    model: str
    segments: list[SegmentParity] = field(default_factory=list)
    dofs: list[DofParity] = field(default_factory=list)
    only_in_mujoco: list[str] = field(default_factory=list)
    only_in_pinocchio: list[str] = field(default_factory=list)
    total_mass: tuple[float, float] = (0.0, 0.0)
    model_mass: float = 0.0
    findings: list[str] = field(default_factory=list)
    mass_matrix_max_rel: float = 0.0
    rtol: float = PARITY_RTOL
    causes: list[Finding] = field(default_factory=list)
    massless_in_pinocchio: list[str] = field(default_factory=list)
    massless_in_mujoco: list[str] = field(default_factory=list)
    segment_labels: dict[str, str] = field(default_factory=dict)
    frame_offset: Any = field(default=None, repr=False, compare=False)

    def label(self, segment: str) -> str:
        """A segment as the user wrote it: its link or body, and the joint that keys it.

        Parameters
        ----------
        segment : str

        Returns
        -------
        str
        """
        return self.segment_labels.get(segment, f"segment {segment}")

    @property
    def differing_segments(self) -> list[SegmentParity]:
        """Segments with at least one cause."""
        return [s for s in self.segments if s.causes]

    @property
    def differing_dofs(self) -> list[DofParity]:
        """Dofs with at least one cause."""
        return [d for d in self.dofs if d.causes]

    @property
    def clean(self) -> bool:
        """True when no import difference that changes the energy was found."""
        return not (
            self.differing_segments
            or self.differing_dofs
            or self.only_in_mujoco
            or self.only_in_pinocchio
            or self.massless_in_mujoco
            or self.massless_in_pinocchio
            or any(c.affects_energy for c in self.causes)
        )

    def explained(self, name: str) -> set[str]:
        """The symptoms of a segment or dof that root causes explain (``mass``, ``com``, ``anchor``...).

        Parameters
        ----------
        name : str
            Segment or joint name.

        Returns
        -------
        set of str
        """
        out: set[str] = set()
        for c in self.causes:
            if c.affects_energy and (name in c.segments or name in c.values.get("joints", ())):
                out |= _EXPLAINS.get(c.kind, _ALL_SYMPTOMS)
        return out

    def largest_relative(self) -> float:
        """The largest relative difference of any differing quantity (segments, dofs), or inf when one has none.

        A difference without a measured size (a segment one engine lacks, a root cause) counts as infinite: only
        differences all of a known small size can be a written file's rounding.

        Returns
        -------
        float
        """
        if self.only_in_mujoco or self.only_in_pinocchio or self.massless_in_mujoco or self.massless_in_pinocchio:
            return float("inf")
        if any(c.affects_energy for c in self.causes):
            return float("inf")
        sizes = [self.mass_matrix_max_rel]
        for item in self.differing_segments:
            sizes += [item.relative.get(c, float("inf")) for c in item.causes]
        for dof in self.differing_dofs:
            sizes += [dof.relative.get(c, float("inf")) for c in dof.causes]
        return max(sizes)

    def causes_for(self, segment: str, above: float = 0.0) -> tuple[str, ...]:
        """The causes found for one segment (empty when it matches).

        Parameters
        ----------
        segment : str
        above : float
            Only the quantities whose relative difference is above this (e.g. above a written file's rounding).

        Returns
        -------
        tuple of str
        """
        for s in self.segments:
            if s.name == segment:
                return tuple(c for c in s.causes if s.relative.get(c, float("inf")) > above)
        return ()

    def as_findings(self) -> list[Finding]:
        """The import differences of a parity report as findings (one per segment or dof and quantity).

        Returns
        -------
        list of Finding
            The root causes come first, then the typed findings the report already carries, then one
            finding per differing segment and quantity that no root cause explains (values: MuJoCo's
            and Pinocchio's mass where the mass differs), per differing dof and quantity, and per
            segment that one engine lacks.
        """
        out = list(self.causes) + [f for f in self.findings if isinstance(f, Finding)]
        first, second = parity_pair()  # each pair of values below is (MuJoCo's, Pinocchio's)
        for seg in self.differing_segments:
            for cause in seg.causes:
                if cause in self.explained(seg.name):
                    continue
                values: dict[str, float] = {first: seg.mass[0], second: seg.mass[1]} if cause == "mass" else {}
                values["relative difference"] = seg.relative.get(cause, float("nan"))
                out.append(
                    Finding(
                        _PARITY_KINDS.get(cause, Kind.INERTIA),
                        "both",
                        self.label(seg.name),
                        f"{cause} differs between the engines",
                        values,
                        affects_energy=True,
                        segments=(seg.name,),
                    )
                )
        for dof in self.differing_dofs:
            for cause in dof.causes:
                if cause in self.explained(dof.joint):
                    continue
                values = {first: dof.armature[0], second: dof.armature[1]} if cause == "armature" else {}
                values["relative difference"] = dof.relative.get(cause, float("nan"))
                out.append(
                    Finding(
                        _PARITY_KINDS.get(cause, Kind.AXIS),
                        "both",
                        f"dof {dof.joint}",
                        f"{cause} differs between the engines",
                        values,
                        affects_energy=True,
                    )
                )
        for engine, names in ((first, self.only_in_mujoco), (second, self.only_in_pinocchio)):
            if names:
                out.append(
                    Finding(
                        Kind.SEGMENTS,
                        engine,
                        "segments " + ", ".join(names),
                        f"segments only in {engine_label(engine)}",
                        affects_energy=True,
                        segments=tuple(names),
                    )
                )
        return out

    def headline(self, brief: bool = False) -> str:
        """One line: root causes that change the energy first, then symptoms no root cause explains.

        A symptom is a differing segment or dof, or a segment one engine lacks or gives no mass.  ``brief``
        names each root cause in a few words (its element and brief form), for a view that lists them whole.
        """
        from koenig_check.diagnosis.reason import short_cause

        parts = [f"root cause: {short_cause(c) if brief else c.message()}" for c in self.causes if c.affects_energy]
        for label, items in (("segment", self.differing_segments), ("dof", self.differing_dofs)):
            for item in items:
                name = item.name if isinstance(item, SegmentParity) else item.joint
                rest = [c for c in item.causes if c not in self.explained(name)]
                if rest:
                    shown = self.label(name) if isinstance(item, SegmentParity) else f"{label} {name}"
                    parts.append(f"{shown}: {', '.join(rest)}")
        for label, names in (
            ("segments only in MuJoCo", self.only_in_mujoco),
            ("segments only in Pinocchio", self.only_in_pinocchio),
            ("segments massless in Pinocchio", self.massless_in_pinocchio),
            ("segments massless in MuJoCo", self.massless_in_mujoco),
        ):
            rest = [n for n in names if not self.explained(n)]
            if rest:
                parts.append(f"{label}: {rest}")
        return "; ".join(parts) or "no import difference"
