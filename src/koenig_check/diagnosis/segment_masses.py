"""Each engine's mass per segment, and MuJoCo's after an edit of the file: what the mass causes compare.

A segment is the set of bodies one joint moves, named by that joint (:mod:`koenig_check.engines.canonical`).
"""

from __future__ import annotations

import warnings
from typing import Any

import mujoco

from koenig_check.engines.canonical import segment_of_body


def compiled(spec: mujoco.MjSpec) -> mujoco.MjModel | None:
    """MuJoCo's model of an (edited) spec, or ``None`` when MuJoCo refuses it.

    Parameters
    ----------
    spec : mujoco.MjSpec

    Returns
    -------
    mujoco.MjModel or None
        ``None`` for a file MuJoCo compiles only after the loader's repairs: no cause is read from it.
    """
    try:
        with warnings.catch_warnings():  # the compiler's warnings are the loader's findings already
            warnings.simplefilter("ignore")
            return spec.compile()
    except Exception:
        return None


def mujoco_segment_masses(model: mujoco.MjModel) -> dict[str, float]:
    """MuJoCo's mass of every segment (the bodies each joint moves).

    Parameters
    ----------
    model : mujoco.MjModel

    Returns
    -------
    dict of str to float
    """
    out: dict[str, float] = {}
    for body, segment in segment_of_body(model).items():
        if segment:
            out[segment] = out.get(segment, 0.0) + float(model.body(body).mass[0])
    return out


def pinocchio_segment_masses(pair: Any) -> dict[str, float]:
    """Pinocchio's mass of every joint-keyed segment, massless ones included.

    Parameters
    ----------
    pair : LoadedModel

    Returns
    -------
    dict of str to float
    """
    names = pair.state_map.segment_names
    inertias = pair.pinocchio.model.inertias
    return {names[i]: float(inertias[i].mass) for i in range(1, len(inertias)) if names[i]}
