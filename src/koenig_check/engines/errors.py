"""Exceptions raised while loading a model into the engines or pairing them.

They live in :mod:`koenig_check.exceptions`; this module keeps their old import path.
"""

from __future__ import annotations

from koenig_check.exceptions import (
    CoupledJointsError,
    EngineUnavailableError,
    InertiaError,
    JointMismatch,
    ModelLoadError,
    NoMassError,
    NoMovingSegmentError,
    NotFloatableError,
)

__all__ = [
    "CoupledJointsError",
    "EngineUnavailableError",
    "InertiaError",
    "JointMismatch",
    "ModelLoadError",
    "NoMassError",
    "NoMovingSegmentError",
    "NotFloatableError",
]
