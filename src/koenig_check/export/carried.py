"""What an export could not carry into its target format, and the refusal when the robot itself cannot go.

A :class:`NotCarried` record is data (what construct, which element, why, and whether it changes the
joint-space mass matrix), listed in the export's result and printed in its summary; nothing the target
format cannot hold is dropped silently.  A construct without which the target would be another robot
(a ball joint in URDF) is an :class:`ExportRefusedError` naming the elements.
"""

from __future__ import annotations

from dataclasses import dataclass

from koenig_check.exceptions import KoenigCheckError


@dataclass(frozen=True)
class NotCarried:
    """One construct of the original that the written file does not hold.

    Parameters
    ----------
    construct : str
        What it is: ``"armature"``, ``"equality"``, ``"tendon"``, ``"actuator"``, ``"geom"``,
        ``"floating base"``, ``"inertia repair"``, ...
    element : str
        ``"<tag> <name>"`` of the element concerned (``"joint elbow"``), or ``"model"``.
    reason : str
        Why the target does not hold it, and what the user does about it.
    affects_mass_matrix : bool
        Whether the file loaded on its own gives another joint-space mass matrix than the original
        (armature does; an actuator does not).
    """

    construct: str
    element: str
    reason: str
    affects_mass_matrix: bool = False

    def message(self) -> str:
        """One line for people.

        Returns
        -------
        str
        """
        return f"{self.construct}: {self.element}: {self.reason}"


class ExportRefusedError(KoenigCheckError, ValueError):
    """The target format cannot express the robot; the message names the constructs and elements.

    Parameters
    ----------
    message : str
    constructs : tuple of NotCarried
        What stopped the export.
    """

    def __init__(self, message: str, constructs: tuple[NotCarried, ...] = ()) -> None:
        super().__init__(message)
        self.constructs = constructs
