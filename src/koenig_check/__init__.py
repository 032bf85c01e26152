"""koenig-check: cross-check rigid-body kinetic energy between MuJoCo, Pinocchio and a paper's formulas."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from koenig_check.segments import SegmentStates

if TYPE_CHECKING:
    from pathlib import Path

    from koenig_check.api import compare
    from koenig_check.export.result import ExportResult
    from koenig_check.implied_dynamics.analysis import dynamics
    from koenig_check.run.records import RecordTable

__all__ = ["SegmentStates", "compare", "dynamics", "export", "read_records"]
__version__ = "0.1.0"


def __getattr__(name: str) -> Any:
    """``compare`` and ``dynamics`` are imported on first use (``import koenig_check`` stays light).

    They are the functions themselves, :func:`koenig_check.api.compare` and
    :func:`koenig_check.implied_dynamics.analysis.dynamics`, so that ``help()``, ``inspect.signature`` and
    IDEs show every keyword.
    """
    function: Any
    if name == "compare":
        from koenig_check.api import compare as function
    elif name == "dynamics":
        from koenig_check.implied_dynamics.analysis import dynamics as function
    else:
        raise AttributeError(f"module 'koenig_check' has no attribute {name!r}")
    globals()[name] = function
    return function


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


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
    engines: tuple[str, ...] | str | None = None,
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
    engines : tuple of str or "all", optional
        Engines the proof uses (those not installed are reported as not compared); default: every engine that reads
        the export's format; ``"all"``: every installed engine that reads both files' formats, each asked for.

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
