"""koenig-check: cross-check rigid-body kinetic energy between MuJoCo, Pinocchio and a paper's formulas."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from koenig_check import _moved
from koenig_check.segments import SegmentStates

_moved.install()

if TYPE_CHECKING:
    from pathlib import Path

    from koenig_check.api import CrossCheck
    from koenig_check.export.result import ExportResult
    from koenig_check.implied_dynamics.analysis import DynamicsResult
    from koenig_check.run.records import RecordTable

__all__ = ["SegmentStates", "compare", "dynamics", "export", "read_records"]
__version__ = "0.1.0"


def compare(models: Any, **options: Any) -> CrossCheck:
    """Cross-check kinetic energy for one or several models (see :func:`koenig_check.api.compare`).

    Parameters
    ----------
    models : str, Path or sequence of them
        Model files or names (``koenig-check models``).
    **options
        ``rtol``, ``progress``, ``pose_kind``, ``n_poses``, ``seed``, ``formulas``, ``velocity_scale``,
        ``grid_joints``, ``duration``, ``pose_set``, ``pose_file``, ``load_options``, and every load
        option by name (``floating``, ``balance_inertia``, ``repair_inertia``, ``pinocchio_model``: see
        :class:`koenig_check.engines.load_options.LoadOptions`).

    Returns
    -------
    CrossCheck
        Records, summaries, engine parity and failures.
    """
    from koenig_check.api import compare as _compare

    return _compare(models, **options)


def dynamics(model: Any, **options: Any) -> DynamicsResult:
    """Mass matrix and generalized inertia forces implied by each energy formula, against both engines.

    See :func:`koenig_check.implied_dynamics.analysis.dynamics`.

    Parameters
    ----------
    model : str or Path
        A model file or name (``koenig-check models``).
    **options
        ``n_poses``, ``seed``, ``formulas``, ``m_rtol``, ``q_rtol``, ``velocity_scale`` and the load
        options ``floating``, ``balance_inertia``, ``pinocchio_model``, ``allow_coupled``.

    Returns
    -------
    DynamicsResult
        Matrices and forces per formula and route, the engines' own, and the errors as arrays.
    """
    from koenig_check.implied_dynamics.analysis import dynamics as _dynamics

    return _dynamics(model, **options)


def read_records(path: str | Path) -> RecordTable:
    """Read a report's ``records.parquet`` back, the error columns included.

    See :func:`koenig_check.run.records.read_records`.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    RecordTable
        Index by column name (``value``, ``rel_error``, …) for numpy arrays; ``.to_arrow()`` for a table.
    """
    from koenig_check.run.records import read_records as _read

    return _read(path)


def export(
    model: str | Path,
    *,
    to: str,
    out: str | Path,
    floating: bool = False,
    repair_inertia: bool = False,
    balance_inertia: bool = False,
    drake_extensions: bool = False,
    poses: int = 10,
    seed: int = 0,
    rtol: float = 1e-9,
    engines: tuple[str, ...] = ("mujoco", "pinocchio", "drake"),
) -> ExportResult:
    """Write a model as URDF or portable MJCF and prove, in every engine, that it is the same robot.

    See :func:`koenig_check.export.api.export_model`.  (After ``import koenig_check.export.…`` the name
    is the subpackage, which is callable with the same signature.)

    Parameters
    ----------
    model : str or Path
        A model file or name (``koenig-check models``).
    to : {"urdf", "mjcf"}
        Target format; an MJCF exported to MJCF is the portable form.
    out : str or Path
        The file to write.
    floating, repair_inertia, balance_inertia : bool
        How the original is loaded (see :class:`koenig_check.engines.load_options.LoadOptions`).
    drake_extensions : bool
        URDF: write armature as Drake's ``drake:rotor_inertia``.
    poses, seed, rtol
        The proof: seeded random poses and the relative tolerance.
    engines : tuple of str
        Engines the proof uses (those not installed are reported as not compared).

    Returns
    -------
    ExportResult
        The path written, the target, what was not carried, and the proof per engine.
    """
    from koenig_check.export.api import export_model

    return export_model(
        model,
        to=to,
        out=out,
        floating=floating,
        repair_inertia=repair_inertia,
        balance_inertia=balance_inertia,
        drake_extensions=drake_extensions,
        poses=poses,
        seed=seed,
        rtol=rtol,
        engines=engines,
    )
