"""One pass through ``compare``: models prepared once, engines attached in one place, the verdicts on the run's own
energies, a comparison immutable once built, no model kept by the pipeline."""

from __future__ import annotations

import ast
import dataclasses
from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.engines.registry import installed
from koenig_check.roundoff import ROUNDOFF

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"
PACKAGE = Path(koenig_check.__file__).parent


def test_the_command_line_prepares_its_models_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from koenig_check.cli import main
    from koenig_check.sources import external

    calls: list[list] = []
    prepare = external.prepare

    def counted(models):
        calls.append(list(models))
        return prepare(models)

    monkeypatch.setattr(external, "prepare", counted)
    assert main(["compare", "gimbal.xml", "serial7.urdf", "--poses", "3", "--quiet"]) == 0
    assert calls == [["gimbal.xml", "serial7.urdf"]]  # once for the batch, not again in the API


def test_the_api_prepares_models_given_as_names(monkeypatch: pytest.MonkeyPatch) -> None:
    from koenig_check.sources import external

    calls: list[list] = []
    monkeypatch.setattr(external, "prepare", lambda models: calls.append(list(models)))
    koenig_check.compare("gimbal.xml", n_poses=2)
    assert calls == [["gimbal.xml"]]


def test_the_verdict_poses_are_the_run_s_first_poses_with_its_energies() -> None:
    """Cut in chunks of 10, the run hands back its first poses whole, and each engine's energies on them are the
    engine's own (Engine.kinetic_energy on the same states, an independent call), to rounding."""
    from koenig_check.engines import load_model
    from koenig_check.run import pipeline
    from koenig_check.run.poses import random_poses

    model = load_model(CAUSES / "class_mass.xml")
    _, verdict = pipeline.run_model(
        model,
        pipeline.WorkerModel(str(CAUSES / "class_mass.xml")),
        "class_mass.xml",
        ["exact"],
        random=pipeline.RandomRange(0, 37, 5, 1.0),
        chunk_poses=10,
    )
    assert verdict is not None
    poses = random_poses(model.mujoco.model, 37, seed=5)
    np.testing.assert_array_equal(verdict.qpos, poses.qpos)
    np.testing.assert_array_equal(verdict.qvel, poses.qvel)
    assert set(verdict.energies) == {"mujoco", "pinocchio"}
    for name, energies in verdict.energies.items():
        own = model.engines[name].kinetic_energy(poses.qpos, poses.qvel)
        scale = np.abs(own.rigid).max()
        np.testing.assert_allclose(energies.rigid, own.rigid, rtol=0, atol=ROUNDOFF * scale, err_msg=name)
        np.testing.assert_allclose(energies.armature, own.armature, rtol=0, atol=ROUNDOFF * scale, err_msg=name)


@pytest.mark.skipif(not installed("drake"), reason="Drake (the optional extra [drake]) is not installed")
def test_the_verdicts_compute_no_energy_the_run_computed(monkeypatch: pytest.MonkeyPatch) -> None:
    """Drake, consulted after the run, computes its energies on the run's first poses; MuJoCo's and Pinocchio's
    are the run's.  The verdicts are those computed from scratch on the same poses."""
    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.engines import load_model
    from koenig_check.engines.drake.adapter import DrakeEngine
    from koenig_check.engines.mujoco.adapter import MujocoEngine
    from koenig_check.engines.pinocchio.adapter import PinocchioEngine
    from koenig_check.findings import Kind
    from koenig_check.run.poses import random_poses

    asked: list[tuple[str, int]] = []
    for cls in (MujocoEngine, PinocchioEngine, DrakeEngine):
        original = cls.kinetic_energy

        def counted(self, qpos, qvel, _original=original):
            asked.append((self.engine, len(qpos)))
            return _original(self, qpos, qvel)

        monkeypatch.setattr(cls, "kinetic_energy", counted)
    check = koenig_check.compare(CAUSES / "class_mass.xml", n_poses=37, chunk_poses=10)
    (comparison,) = check.comparisons
    verdicts = [f for f in comparison.findings if f.kind is Kind.VERDICT]
    assert verdicts and [a for a in asked if a[1] == 37] == [("drake", 37)]
    monkeypatch.undo()
    model = load_model(CAUSES / "class_mass.xml")
    poses = random_poses(model.mujoco.model, 37, seed=0)
    anew = diagnose(model, disagree=True, qpos=poses.qpos, qvel=poses.qvel, rtol=check.rtol)
    assert [f.as_dict() for f in verdicts] == [f.as_dict() for f in anew.verdicts]


def test_a_comparison_is_immutable_once_built() -> None:
    (comparison,) = koenig_check.compare("gimbal.xml", n_poses=2).comparisons
    with pytest.raises(dataclasses.FrozenInstanceError):
        comparison.findings = []  # type: ignore[misc]


def test_no_model_is_kept_by_the_pipeline_after_a_run() -> None:
    from koenig_check.run import pipeline

    koenig_check.compare("gimbal.xml", n_poses=2)
    assert pipeline._WORKER.models == {}  # a worker's cache: the process that ran the comparison never fills it


def attach_calls() -> list[str]:
    """The modules of the package that call ``.attach(...)`` on something."""
    found = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "attach":
                found.append(str(path.relative_to(PACKAGE)))
    return sorted(set(found))


def test_optional_engines_are_attached_in_one_place() -> None:
    """The policy's attach_engines decides; LoadedModel.engine attaches what a worker's chunk names (the engines
    the parent attached through the policy)."""
    assert attach_calls() == ["diagnosis/policy.py", "engines/loading.py"]
