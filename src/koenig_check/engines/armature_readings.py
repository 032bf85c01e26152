"""Where an attached engine's armature departs from MuJoCo's, joint by joint: the engine-independent part.

An engine reads a joint's rotor inertia its own way (Drake: a motor's reflected inertia, rotor inertia × gear
ratio²; none for a joint no motor drives).  What it lacks, and what it adds, are read here from the engine's
own :meth:`~koenig_check.engines.base.Engine.armature_per_dof` against MuJoCo's ``dof_armature``; the engine's
subpackage says in its own words what that means (``engines/drake/attach.py``).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np


class ArmatureDifferences(NamedTuple):
    """The joints whose armature an engine reads otherwise than MuJoCo, in the engine's state-map order."""

    missing: list[str]
    """Joints MuJoCo gives an armature the engine does not match, where the engine has none of its own."""
    added: list[str]
    """Joints the engine gives an armature (its own reading) that MuJoCo's does not match."""
    mujoco: dict[str, float]
    """MuJoCo's armature of each joint concerned."""
    engine: dict[str, float]
    """The engine's armature of each joint concerned."""


def armature_differences(model: Any, engine: Any) -> ArmatureDifferences:
    """The joints whose armature an attached engine reads otherwise than MuJoCo.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel
        The model loaded in MuJoCo (its ``dof_armature`` is the file's armature as MuJoCo reads it).
    engine : Engine
        An attached engine with a ``state_map`` pairing its joints with MuJoCo's (``pairs``, each with
        ``name`` and ``vadr``) and :meth:`~koenig_check.engines.base.Engine.armature_per_dof`.

    Returns
    -------
    ArmatureDifferences
    """
    arm = np.asarray(model.mujoco.model.dof_armature, dtype=float)
    own = np.asarray(engine.armature_per_dof(), dtype=float)
    pairs = list(engine.state_map.pairs)
    differ = [p for p in pairs if not np.isclose(own[p.vadr], arm[p.vadr])]
    added = [p.name for p in differ if own[p.vadr] > 0]
    missing = [p.name for p in differ if arm[p.vadr] > 0 and p.name not in added]
    return ArmatureDifferences(
        missing,
        added,
        {p.name: float(arm[p.vadr]) for p in differ},
        {p.name: float(own[p.vadr]) for p in differ},
    )
