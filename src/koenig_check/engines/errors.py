"""Exceptions raised while loading a model into the engines or pairing them."""

from __future__ import annotations

from koenig_check.findings import KoenigCheckError


class ModelLoadError(KoenigCheckError, ValueError):
    """A model file cannot be loaded by one engine; the message names the file and the element."""


class InertiaError(ModelLoadError):
    """MuJoCo rejects a link's mass or inertia; the message names the link and the reason."""


class CoupledJointsError(ModelLoadError):
    """The model couples joints (mimic, equality constraints) or closes loops; the message names them."""


class NoMovingSegmentError(ModelLoadError):
    """The model has no joint: nothing moves, there is no kinetic energy to compare."""


class NoMassError(ModelLoadError):
    """Nothing that moves has mass (at most round-off, e.g. MuJoCo's minimum masses of a repair).

    Parameters
    ----------
    message : str
        One line naming the file and the massless moving links.
    links : tuple of str
        The moving links (bodies) without mass.
    """

    def __init__(self, message: str, links: tuple[str, ...] = ()) -> None:
        super().__init__(message)
        self.links = tuple(links)


class JointMismatch(KoenigCheckError, ValueError):  # noqa: N818 - the name the design uses
    """The joints of the MuJoCo model and the Pinocchio model cannot be paired by name.

    Parameters
    ----------
    path : str
        The model file.
    only_in_mujoco : list of str
        Canonical (MuJoCo) joint names with no Pinocchio counterpart.
    only_in_pinocchio : list of str
        Pinocchio joint names with no MuJoCo counterpart.
    kind_mismatch : list of str
        Joints present in both engines whose types are incompatible, as ``"name: mujoco-kind vs pin-kind"``.
    """

    def __init__(
        self,
        path: str,
        only_in_mujoco: list[str],
        only_in_pinocchio: list[str],
        kind_mismatch: list[str] | None = None,
    ) -> None:
        self.path = path
        self.only_in_mujoco = list(only_in_mujoco)
        self.only_in_pinocchio = list(only_in_pinocchio)
        self.kind_mismatch = list(kind_mismatch or [])
        parts = []
        if self.only_in_mujoco:
            parts.append(f"only in MuJoCo: {self.only_in_mujoco}")
        if self.only_in_pinocchio:
            parts.append(f"only in Pinocchio: {self.only_in_pinocchio}")
        if self.kind_mismatch:
            parts.append(f"incompatible types: {self.kind_mismatch}")
        super().__init__(f"{path}: joints do not match between the engines ({'; '.join(parts)})")


class EngineUnavailableError(KoenigCheckError, ValueError):
    """An engine was asked for but cannot run: not installed, or it cannot check the model.

    Parameters
    ----------
    message : str
        One line naming the engine (and the file, when the engine refused it) with the engine's own reason.
    engine : str
        The engine's name.
    """

    def __init__(self, message: str, engine: str = "") -> None:
        super().__init__(message)
        self.engine = engine
