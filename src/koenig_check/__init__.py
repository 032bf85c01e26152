"""koenig-check: cross-check rigid-body kinetic energy between MuJoCo, Pinocchio and a paper's formulas."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from koenig_check.segments import SegmentStates

if TYPE_CHECKING:
    from koenig_check.api import CrossCheck

__all__ = ["SegmentStates", "compare"]
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
