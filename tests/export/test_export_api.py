"""``koenig_check.export``: real keyword parameters, a frozen result, callable before and after the subpackage loads."""

from __future__ import annotations

import dataclasses
import inspect
from pathlib import Path

import pytest
from export_helpers import MODELS

import koenig_check


def test_signature_has_real_keywords() -> None:
    parameters = inspect.signature(koenig_check.export).parameters
    for name in ("to", "out", "floating", "repair_inertia", "drake_extensions", "poses", "seed", "rtol", "engines"):
        assert parameters[name].kind is inspect.Parameter.KEYWORD_ONLY
    assert not any(p.kind is inspect.Parameter.VAR_KEYWORD for p in parameters.values())


def test_callable_after_the_subpackage_is_imported(tmp_path: Path) -> None:
    # importing a submodule makes the import system set koenig_check.export to the package
    import koenig_check.export.proof

    result = koenig_check.export(MODELS / "slide.xml", to="mjcf", out=tmp_path / "s.xml", poses=2)
    assert result.equivalent
    assert "to" in inspect.signature(koenig_check.export).parameters
    with pytest.raises(TypeError):
        koenig_check.export(MODELS / "slide.xml", to="mjcf", out=tmp_path / "s.xml", flaoting=True)  # type: ignore[call-arg]


def test_result_is_frozen_data(tmp_path: Path) -> None:
    result = koenig_check.export(MODELS / "armature.xml", to="urdf", out=tmp_path / "a.urdf", poses=2)
    with pytest.raises(dataclasses.FrozenInstanceError):
        result.target = "mjcf"  # type: ignore[misc]
    assert result.target == "urdf" and result.path == tmp_path / "a.urdf"
    engines = {e.engine: e for e in result.proof.engines}
    assert engines["mujoco"].compared and engines["mujoco"].mass_matrix < 1e-9
    assert result.proof.poses == 2
