"""Load one file in every engine separately, so that an engine refusing it leaves the others to compare."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any

import mujoco

from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.mujoco.adapter import MujocoEngine
from koenig_check.engines.mujoco.loader import load_mujoco, root_free_joint
from koenig_check.exceptions import one_line
from koenig_check.sources.catalogue import resolve_model

#: The engines a proof compares, in report order.
PROOF_ENGINES = ("mujoco", "pinocchio", "drake")


@dataclass
class EngineSide:
    """One file loaded in each engine: adapters answering canonical (MuJoCo-layout) states.

    Parameters
    ----------
    path : str
    mj_model : mujoco.MjModel
        MuJoCo's model of the file: the canonical layout every adapter takes.
    adapters : dict of str to adapter
        ``mass_matrix``, ``armature_matrix``, ``kinetic_energy``, ``segment_states`` per engine.
    refused : dict of str to str
        Engine -> its one-line reason for not loading the file.
    """

    path: str
    mj_model: mujoco.MjModel
    adapters: dict[str, Any] = field(default_factory=dict)
    refused: dict[str, str] = field(default_factory=dict)


def load_side(
    path: str | os.PathLike[str], options: LoadOptions, engines: tuple[str, ...] = PROOF_ENGINES
) -> EngineSide:
    """Load a file in MuJoCo (required: it defines the state layout), then in each other engine.

    Parameters
    ----------
    path : path or model name
    options : LoadOptions
        ``floating``, ``balance_inertia``, ``repair_inertia`` apply to MuJoCo; Pinocchio and Drake get
        a free root exactly where MuJoCo's model has one.
    engines : tuple of str

    Returns
    -------
    EngineSide

    Raises
    ------
    koenig_check.engines.ModelLoadError
        MuJoCo refuses the file.
    """
    source = resolve_model(path)
    mj_model, mj_findings, body_findings = load_mujoco(
        source,
        floating=options.floating,
        balance_inertia=options.balance_inertia,
        repair_inertia=options.repair_inertia,
    )
    side = EngineSide(str(source.path), mj_model)
    side.adapters["mujoco"] = MujocoEngine(mj_model, source.path, mj_findings, body_findings)
    if "pinocchio" in engines:
        try:
            from koenig_check.engines.pinocchio.adapter import PinocchioEngine
            from koenig_check.engines.pinocchio.loader import load_pinocchio
            from koenig_check.engines.pinocchio.state_map import build_state_map

            pin_model, pin_findings = load_pinocchio(source, root_joint=root_free_joint(mj_model))
            state_map = build_state_map(mj_model, pin_model, str(source.path))
            side.adapters["pinocchio"] = PinocchioEngine(pin_model, state_map, source.path, pin_findings)
        except Exception as err:  # an engine's refusal is a result, not a crash
            side.refused["pinocchio"] = one_line(err)
    if "drake" in engines:
        from koenig_check.engines.drake.loader import drake_available

        if not drake_available():
            side.refused["drake"] = "Drake is not installed (extra [drake])"
        else:
            try:
                from koenig_check.engines.drake.building import load_drake_engine

                side.adapters["drake"] = load_drake_engine(source, mj_model)
            except Exception as err:
                side.refused["drake"] = one_line(err)
    return side
