"""How far one mass matrix or force vector is from an engine's: norm-relative error per pose, worst entry."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Discrepancy:
    """One route's ``M`` or ``Q*`` against one engine's, over a batch of poses.

    Attributes
    ----------
    formula : str
        Energy formula (``"(engine)"`` for one engine's own numbers against the other's).
    route : str
        ``lagrange@mujoco`` (the formula on MuJoCo's segment states: polarization and Lagrange),
        ``kane@pinocchio``... or an engine name for the engine-against-engine comparison.
    engine : str
        The reference engine.
    quantity : str
        ``"M"`` or ``"Q*"``.
    rel_error : ndarray, shape (P,)
        ``‖X − X_engine‖ / ‖X_engine‖`` per pose (Frobenius norm for ``M``, Euclidean for ``Q*``).
    worst_pose : int
        Pose of the largest entry error.
    worst_entry : tuple of int
        ``(i, j)`` for ``M``, ``(j,)`` for ``Q*``: canonical dof indices of the largest entry error.
    worst_entry_error : float
        Signed entry difference ``X − X_engine`` there.
    worst_entry_rel : float
        Its size relative to the norm of the engine's ``X`` at that pose.
    """

    formula: str
    route: str
    engine: str
    quantity: str
    rel_error: np.ndarray
    worst_pose: int
    worst_entry: tuple[int, ...]
    worst_entry_error: float
    worst_entry_rel: float

    @property
    def max_rel_error(self) -> float:
        """Largest norm-relative error over the poses."""
        return float(np.max(self.rel_error))

    @property
    def max_pose(self) -> int:
        """Pose of the largest norm-relative error."""
        return int(np.argmax(self.rel_error))


def _ratio(num: np.ndarray, den: np.ndarray) -> np.ndarray:
    with np.errstate(divide="ignore", invalid="ignore"):
        out = num / den
    return np.where(den > 0, out, np.where(num == 0, 0.0, np.inf))


def discrepancy(value: np.ndarray, reference: np.ndarray, formula: str, route: str, engine: str) -> Discrepancy:
    """Compare a batch of matrices (P, n, n) or vectors (P, n) with the engine's.

    Parameters
    ----------
    value, reference : ndarray, shape (P, n, n) or (P, n)
    formula, route, engine : str
        Labels.

    Returns
    -------
    Discrepancy
    """
    value = np.asarray(value, dtype=float)
    reference = np.asarray(reference, dtype=float)
    diff = value - reference
    axes = tuple(range(1, diff.ndim))
    norm = np.sqrt((reference**2).sum(axis=axes))
    rel = _ratio(np.sqrt((diff**2).sum(axis=axes)), norm)
    scaled = _ratio(np.abs(diff), norm.reshape(-1, *([1] * len(axes))))
    flat = int(np.argmax(scaled))
    where = np.unravel_index(flat, diff.shape)
    return Discrepancy(
        formula=formula,
        route=route,
        engine=engine,
        quantity="M" if diff.ndim == 3 else "Q*",
        rel_error=rel,
        worst_pose=int(where[0]),
        worst_entry=tuple(int(k) for k in where[1:]),
        worst_entry_error=float(diff[where]),
        worst_entry_rel=float(scaled[where]),
    )
