"""Engines: one model file loaded in MuJoCo and Pinocchio (and optional engines), driven in canonical states.

Public API
----------
``load_model(path_or_name, options=None, *, fmt=None, check=True, **load_options) -> LoadedModel``
    ``model.engines`` holds every engine by name (``"mujoco"``, ``"pinocchio"``, and ``"drake"`` once
    attached with ``model.attach("drake")``); each is an :class:`~koenig_check.engines.base.Engine` answering
    the same methods for canonical (MuJoCo-layout) states: ``sweep``, ``segment_states``,
    ``point_velocities``, ``kinetic_energy``, ``mass_matrix``, ``inverse_dynamics``; ``model.state_map``
    converts states for Pinocchio; ``model.findings`` (typed :class:`~koenig_check.findings.Finding` records)
    say what was changed or noticed while loading and what each engine includes.
``list_models()``, ``resolve_model()``
    Names of the project's models and of every example-robot-data URDF.
``random_states(model, n, seed)``
    Seeded random canonical states: the package's one sampler (its distribution in ``sampling.py``).

Layout: ``base.py`` (the :class:`Engine` interface), ``specs.py`` (:class:`EngineSpec`, and the engines found
among the subpackages), ``registry.py`` (names, optional engines, attaching one), ``loading.py``
(:class:`LoadedModel`), ``canonical.py`` (canonical coordinates), one subpackage per engine (``mujoco/``,
``pinocchio/``, ``drake/``: loader, adapter, state map; its ``SPEC`` in ``__init__.py``).  A new engine is one
subpackage: its adapter derives from :class:`Engine`, its ``__init__.py`` declares ``SPEC = EngineSpec(...)``.
Names are imported on first use, so that importing one engine's module does not import the others.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from koenig_check.engines.base import Engine
    from koenig_check.engines.canonical import mujoco_coordinate_names, mujoco_joint_names
    from koenig_check.engines.energy import EnergyParts
    from koenig_check.engines.errors import (
        CoupledJointsError,
        EngineUnavailableError,
        InertiaError,
        JointMismatch,
        ModelLoadError,
        NoMovingSegmentError,
    )
    from koenig_check.engines.load_options import LoadOptions
    from koenig_check.engines.loading import LoadedModel, load_model
    from koenig_check.engines.mujoco.adapter import MujocoEngine
    from koenig_check.engines.mujoco.loader import ROOT_JOINT_NAME
    from koenig_check.engines.pinocchio.adapter import PinocchioEngine
    from koenig_check.engines.pinocchio.state_map import StateMap
    from koenig_check.engines.sampling import random_states
    from koenig_check.sources.catalogue import ModelSource, list_models, resolve_model

#: Public name -> the module that defines it.
_HOME = {
    "Engine": "base",
    "mujoco_coordinate_names": "canonical",
    "mujoco_joint_names": "canonical",
    "EnergyParts": "energy",
    "CoupledJointsError": "errors",
    "EngineUnavailableError": "errors",
    "InertiaError": "errors",
    "JointMismatch": "errors",
    "ModelLoadError": "errors",
    "NoMovingSegmentError": "errors",
    "LoadOptions": "load_options",
    "LoadedModel": "loading",
    "load_model": "loading",
    "CONSISTENCY_POSES": "loading",
    "POSE_ATOL": "loading",
    "MujocoEngine": "mujoco.adapter",
    "ROOT_JOINT_NAME": "mujoco.loader",
    "PinocchioEngine": "pinocchio.adapter",
    "StateMap": "pinocchio.state_map",
    "random_states": "sampling",
    "ModelSource": "koenig_check.sources.catalogue",
    "list_models": "koenig_check.sources.catalogue",
    "resolve_model": "koenig_check.sources.catalogue",
}

__all__ = [
    "CONSISTENCY_POSES",
    "POSE_ATOL",
    "ROOT_JOINT_NAME",
    "CoupledJointsError",
    "EnergyParts",
    "Engine",
    "EngineUnavailableError",
    "InertiaError",
    "JointMismatch",
    "LoadOptions",
    "LoadedModel",
    "ModelLoadError",
    "ModelSource",
    "MujocoEngine",
    "NoMovingSegmentError",
    "PinocchioEngine",
    "StateMap",
    "list_models",
    "load_model",
    "mujoco_coordinate_names",
    "mujoco_joint_names",
    "random_states",
    "resolve_model",
]


def __getattr__(name: str) -> Any:
    if name not in _HOME:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    home = _HOME[name] if _HOME[name].startswith("koenig_check.") else f"{__name__}.{_HOME[name]}"
    value = getattr(importlib.import_module(home), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_HOME))
