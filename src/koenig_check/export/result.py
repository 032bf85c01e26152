"""The records an export and its proof return: frozen dataclasses, data rather than sentences."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from koenig_check.export.carried import NotCarried
from koenig_check.roundoff import side_by_side


@dataclass(frozen=True)
class EngineProof:
    """One engine's reading of the export against MuJoCo's reading of the original.

    Parameters
    ----------
    engine : str
        ``"mujoco"``, ``"pinocchio"`` or ``"drake"``.
    mass_matrix : float
        Max over poses of ``max|M_export - M_original| / max|M_original|``, armature removed (NaN when
        not compared); ``M_export`` from this engine, ``M_original`` from MuJoCo.
    energy : float
        Max over poses of ``|T_export - T_original| / |T_original|`` (rigid-body energy).
    poses : int
    equivalent : bool
        Both within the tolerance.
    reason : str
        Why the engine was not compared (it refused the export, joints unpaired), or empty.
    inverse_dynamics : float
        Max over poses of ``max|τ_export - τ_original| / max|τ_original|``: the inverse dynamics with gravity and
        passive forces off and the armature's forces removed, at q̈ = q̇.
    own_reading : float
        Max over poses of ``|T_engine - T_mujoco| / |T_mujoco|``, the rigid energies of this engine's and MuJoCo's
        readings of the original (the measure ``koenig-check compare`` gives the engines' gap); NaN when it
        cannot load the original.  Large while ``mass_matrix`` is small: the engine reads the original
        differently from MuJoCo, and reads the export as MuJoCo reads the original.
    """

    engine: str
    mass_matrix: float
    energy: float
    poses: int
    equivalent: bool
    reason: str = ""
    own_reading: float = float("nan")
    inverse_dynamics: float = float("nan")

    @property
    def compared(self) -> bool:
        """Whether the engine loaded both files and was compared."""
        return not self.reason


@dataclass(frozen=True)
class SegmentDifference:
    """A moving segment whose mass properties differ between the original and the export.

    Parameters
    ----------
    engine : str
    segment : str
        The segment's joint.
    link : str
        The body (link) carrying that joint in the export.
    quantity : str
        ``"mass"``, ``"COM distance from the joint"`` or ``"principal moments of inertia"``.
    relative : float
        Relative difference (mass: of the mass; COM: difference of distances over the model's extent;
        inertia: largest difference of the principal moments over the largest moment).
    original, export : float
        The mass, the distance, or the principal moment that differs the most, on each side.
    """

    engine: str
    segment: str
    link: str
    quantity: str
    relative: float
    original: float
    export: float

    def message(self) -> str:
        """One line for people.

        Returns
        -------
        str
        """
        original, export = side_by_side([self.original, self.export])  # digits enough to show the difference
        return (
            f"{self.engine}: link {self.link} (joint {self.segment}): {self.quantity} off by "
            f"{self.relative:.3g} relative (original {original}, export {export})"
        )


@dataclass(frozen=True)
class Proof:
    """Whether the export is the same robot as the original, engine by engine.

    Parameters
    ----------
    engines : tuple of EngineProof
    segments : tuple of SegmentDifference
        Segments whose mass, COM or inertia differ beyond the tolerance (names the link at fault).
    poses : int
    seed : int
    rtol : float
    problems : tuple of str
        Why the files cannot be compared at all (joints missing), or empty.
    asked : tuple of str
        The engines the user named (``--engines``): each must be compared, or the proof fails (empty: the
        default, every engine that loads both files).
    """

    engines: tuple[EngineProof, ...]
    segments: tuple[SegmentDifference, ...]
    poses: int
    seed: int
    rtol: float
    problems: tuple[str, ...] = ()
    asked: tuple[str, ...] = ()

    @property
    def equivalent(self) -> bool:
        """At least one engine compared, every compared engine within tolerance, every named engine compared."""
        compared = [e for e in self.engines if e.compared]
        return (
            bool(compared)
            and all(e.equivalent for e in compared)
            and not self.problems
            and not self.segments
            and not self.unmade()
        )

    def unmade(self) -> list[str]:
        """The engines the user named that were not compared, each with its reason.

        Returns
        -------
        list of str
        """
        from koenig_check.engines.registry import label

        return [
            f"{label(e.engine)} asked for (--engines) but not compared: {e.reason}"
            for e in self.engines
            if e.engine in self.asked and not e.compared
        ]

    @property
    def max_relative_difference(self) -> float:
        """The largest relative difference of any compared engine (mass matrix or energy)."""
        values = [max(e.mass_matrix, e.energy, e.inverse_dynamics) for e in self.engines if e.compared]
        return max(values) if values else float("nan")

    def summary(self) -> str:
        """``equivalent: ...`` or ``not equivalent: ...`` in one line.

        Returns
        -------
        str
        """
        compared = [e.engine for e in self.engines if e.compared]
        if self.equivalent:
            return (
                f"equivalent: max relative difference {self.max_relative_difference:.2g} over {self.poses} poses, "
                f"engines {', '.join(compared)}"
            )
        return "not equivalent: " + "; ".join(self.reasons())

    def reasons(self) -> list[str]:
        """What differs and why, most specific first (segments name the link).

        Returns
        -------
        list of str
        """
        out = self.unmade() + list(self.problems) + [s.message() for s in self.segments]
        for e in self.engines:
            if e.compared and not e.equivalent:
                out.append(
                    f"{e.engine}: mass matrix differs by {e.mass_matrix:.3g}, rigid energy by {e.energy:.3g}, "
                    f"inverse dynamics by {e.inverse_dynamics:.3g} "
                    f"(tolerance {self.rtol:g}, {e.poses} poses)"
                )
        if not any(e.compared for e in self.engines):
            out.append("no engine loaded the export")
        elif not self.problems:  # every difference at a written file's rounding: say so, and the option
            from koenig_check.diagnosis.reason import rounding_hint

            sizes = [max(e.mass_matrix, e.energy, e.inverse_dynamics) for e in self.engines if e.compared]
            sizes += [s.relative for s in self.segments]
            hint = rounding_hint(max(sizes), self.rtol, between="the original and the export", cli=True)
            out += [hint] if hint else []
        return out

    def notes(self) -> list[str]:
        """Engines that read the original differently from MuJoCo (the export reads as MuJoCo's original).

        Returns
        -------
        list of str
        """
        return [
            f"{e.engine} reads the original differently from MuJoCo (rigid energies differ by up to "
            f"{e.own_reading:.2g} relative to MuJoCo's over {e.poses} poses, as compare measures the gap); "
            "it reads the export as MuJoCo reads the original"
            for e in self.engines
            if e.compared and e.equivalent and e.own_reading > self.rtol
        ]

    def skipped(self) -> list[str]:
        """Engines not compared that the user did not name, with the reason (a named one is in :meth:`unmade`).

        Returns
        -------
        list of str
        """
        return [f"{e.engine}: {e.reason}" for e in self.engines if not e.compared and e.engine not in self.asked]


@dataclass(frozen=True)
class ExportResult:
    """What :func:`koenig_check.export` wrote and whether it is the same robot.

    Parameters
    ----------
    path : Path
        The file written.
    target : str
        ``"urdf"`` or ``"mjcf"``.
    not_carried : tuple of NotCarried
        What the written file does not hold.
    proof : Proof
        The export loaded back and compared with the original in every engine available.
    floating_base : bool
        The written URDF is to be loaded with a floating base (the original's free root joint).
    """

    path: Path
    target: str
    not_carried: tuple[NotCarried, ...]
    proof: Proof
    floating_base: bool = False

    @property
    def equivalent(self) -> bool:
        """The proof's verdict."""
        return self.proof.equivalent

    @property
    def ok(self) -> bool:
        """The proof's verdict, under the name :attr:`koenig_check.run.cross_check.CrossCheck.ok` has."""
        return self.proof.equivalent
