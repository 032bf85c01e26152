"""Load one file in every engine separately, so that an engine refusing it leaves the others to compare."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any

import mujoco

from koenig_check.engines import registry
from koenig_check.engines.load_options import LoadOptions
from koenig_check.engines.mujoco.adapter import MujocoEngine
from koenig_check.engines.mujoco.loader import load_mujoco
from koenig_check.exceptions import one_line
from koenig_check.sources.catalogue import resolve_model


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


def load_side(path: str | os.PathLike[str], options: LoadOptions, engines: tuple[str, ...] | None = None) -> EngineSide:
    """Load a file in MuJoCo (required: it defines the state layout), then in each other engine.

    Parameters
    ----------
    path : path or model name
    options : LoadOptions
        ``floating``, ``balance_inertia``, ``repair_inertia`` apply to MuJoCo; the other engines get
        a free root exactly where MuJoCo's model has one.
    engines : tuple of str, optional
        Default: every engine (:func:`koenig_check.engines.registry.names`).  Each is loaded by the function
        its spec names (:attr:`~koenig_check.engines.specs.EngineSpec.load_alone`).

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
    layout = registry.reference()  # MuJoCo: its model is the layout the others are loaded against
    side.adapters[layout] = MujocoEngine(mj_model, source.path, mj_findings, body_findings)
    for name in registry.names() if engines is None else engines:
        if name == layout:
            continue
        if not registry.installed(name):
            extra = registry.spec(name).extra
            side.refused[name] = f"{registry.label(name)} is not installed ({f'extra [{extra}]' if extra else name})"
            continue
        try:
            side.adapters[name] = registry.load_function(registry.spec(name).load_alone)(source, mj_model)
        except Exception as err:  # an engine's refusal is a result, not a crash
            side.refused[name] = one_line(err)
    return side
