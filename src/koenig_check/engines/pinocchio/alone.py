"""A file loaded in Pinocchio alone, paired with MuJoCo's model of it (what the export's proof compares)."""

from __future__ import annotations

from typing import Any

from koenig_check.engines.pinocchio.adapter import PinocchioEngine


def load_alone(source: Any, mj_model: Any) -> PinocchioEngine:
    """Load a file in Pinocchio, with a free root exactly where MuJoCo's model has one.

    Parameters
    ----------
    source : koenig_check.sources.catalogue.ModelSource
    mj_model : mujoco.MjModel
        MuJoCo's model of the same file: the canonical layout.

    Returns
    -------
    PinocchioEngine

    Raises
    ------
    Exception
        Pinocchio refuses the file, or its joints cannot be paired with MuJoCo's.
    """
    from koenig_check.engines.mujoco.loader import root_free_joint
    from koenig_check.engines.pinocchio.loader import load_pinocchio
    from koenig_check.engines.pinocchio.state_map import build_state_map

    pin_model, pin_findings = load_pinocchio(source, root_joint=root_free_joint(mj_model))
    state_map = build_state_map(mj_model, pin_model, str(source.path))
    return PinocchioEngine(pin_model, state_map, source.path, pin_findings)
