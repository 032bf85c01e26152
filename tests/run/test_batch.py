"""Several models in one run behave as each alone: same records, summaries, agreements and findings."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check

TESTS = Path(__file__).resolve().parents[1]
#: An agreeing MJCF, a disagreeing MJCF (a default-class geom mass Pinocchio ignores), an agreeing URDF.
MODELS = ["gimbal.xml", TESTS / "models" / "causes" / "class_mass.xml", "double_pendulum.urdf"]
OPTIONS = dict(
    n_poses=300, seed=3, records="segments", chunk_poses=100, keep_records=True, engines=("mujoco", "pinocchio")
)


def _by_model(check: koenig_check.api.CrossCheck) -> dict[str, tuple]:
    out = {}
    for comp, agreement in zip(check.comparisons, check.agreements, strict=True):
        rec = comp.records.columns
        out[comp.model] = (
            [s for s in check.summaries if s.model == comp.model],
            agreement,
            [f.as_dict() for f in comp.findings],
            {name: np.asarray(rec[name]) for name in ("pose", "formula", "source", "reference", "scope", "value")},
        )
    return out


def _fresh_process() -> None:
    """Forget what earlier models left in this process (the caches a fresh process starts without)."""
    from koenig_check.run import chunks, engine_runs, pipeline

    engine_runs._POINTS.clear()
    chunks._CODES.clear()
    pipeline._WORKER.models.clear()


@pytest.fixture(scope="module")
def alone() -> dict[str, tuple]:
    out: dict[str, tuple] = {}
    for model in MODELS:  # each model as if in a fresh process
        _fresh_process()
        out.update(_by_model(koenig_check.compare(model, **OPTIONS)))
    return out


@pytest.mark.parametrize("jobs", [1, 2])
def test_a_run_over_several_models_equals_each_model_alone(alone: dict[str, tuple], jobs: int) -> None:
    _fresh_process()
    together = _by_model(koenig_check.compare(MODELS, jobs=jobs, **OPTIONS))
    assert list(together) == list(alone) == ["gimbal.xml", "class_mass.xml", "double_pendulum.urdf"]
    for model, (summaries, agreement, findings, records) in together.items():
        s_alone, a_alone, f_alone, r_alone = alone[model]
        assert summaries == s_alone and agreement == a_alone and findings == f_alone, model
        for name, values in records.items():
            np.testing.assert_array_equal(values, r_alone[name], err_msg=f"{model}: {name}")
    assert [a.agrees for _, a, _, _ in together.values()] == [True, False, True]


#: Three engines, so that a worker must attach Drake to the model it loads itself.
DASK_OPTIONS = {**OPTIONS, "n_poses": 40, "chunk_poses": 20, "engines": ("mujoco", "pinocchio", "drake")}


def test_a_dask_worker_process_running_several_models_gives_each_its_own_result(tmp_path: Path) -> None:
    """One Dask worker process runs the chunks of every model of the batch, one model after the other.

    It keeps the model it loaded between chunks: a later model's chunks must not be computed on an earlier model,
    nor without the engines the run asked for (Drake).  A missing file in the middle fails alone.  Expected: each
    model run alone in this process, with the same options (pose ``i`` depends on the seed and ``i`` only).
    """
    distributed = pytest.importorskip("distributed")
    pytest.importorskip("pydrake")
    missing = tmp_path / "missing.xml"
    alone: dict[str, tuple] = {}
    for model in MODELS:
        _fresh_process()
        alone.update(_by_model(koenig_check.compare(model, **DASK_OPTIONS)))
    with (
        distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        check = koenig_check.compare([MODELS[0], missing, *MODELS[1:]], client=client, **DASK_OPTIONS)
    together = _by_model(check)
    assert list(together) == ["gimbal.xml", "class_mass.xml", "double_pendulum.urdf"]
    assert [label for label, _ in check.failures] == ["missing.xml"]
    for model, (summaries, agreement, findings, records) in together.items():
        s_alone, a_alone, f_alone, r_alone = alone[model]
        assert {s.source for s in summaries} == {"mujoco", "pinocchio", "drake"}, model
        assert summaries == s_alone and agreement == a_alone and findings == f_alone, model
        for name, values in records.items():
            np.testing.assert_array_equal(values, r_alone[name], err_msg=f"{model}: {name}")
