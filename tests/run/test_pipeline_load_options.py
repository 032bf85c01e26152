"""Load options travel with the chunks: ``--jobs`` workers (forked or spawned) and the processes of a Dask
cluster load the model as the caller asked (``floating=True`` here), so their records equal the serial run's.

A worker that loaded the file with the default options would compute another robot (serial7.urdf with a
fixed base): other energies, and the check would still pass, since both engines agree on that robot too.
"""

from __future__ import annotations

import multiprocessing
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import koenig_check
from koenig_check.api import compare_model
from koenig_check.run import pipeline, summaries

MODEL = "serial7.urdf"
OPTIONS = dict(n_poses=24, seed=3, records="totals", floating=True)


def _assert_same(serial, other) -> None:
    assert other.stats.n_poses == serial.stats.n_poses
    assert summaries.summarize(other) == summaries.summarize(serial)
    for name in ("value", "reference_value"):
        np.testing.assert_array_equal(other.records[name], serial.records[name], err_msg=name)


@pytest.fixture(scope="module")
def serial():
    comp = compare_model(MODEL, chunk_poses=10_000, **OPTIONS)
    fixed = compare_model(MODEL, chunk_poses=10_000, **{**OPTIONS, "floating": False})
    # The floating base changes what is computed: the test below can tell the two robots apart.
    assert not np.allclose(comp.records["reference_value"], fixed.records["reference_value"])
    return comp


@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_jobs_workers_load_the_model_with_the_callers_options(serial, method, monkeypatch) -> None:
    """fork is what Linux uses; spawn is what macOS and Windows use: a spawned worker inherits no loaded model."""
    if method not in multiprocessing.get_all_start_methods():
        pytest.skip(f"no {method} start method here")
    context = multiprocessing.get_context(method)
    monkeypatch.setattr(
        pipeline, "_pool", lambda jobs, *model: ProcessPoolExecutor(max_workers=jobs, mp_context=context)
    )
    _assert_same(serial, compare_model(MODEL, chunk_poses=9, jobs=2, **OPTIONS))


def test_dask_worker_processes_load_the_model_with_the_callers_options(serial) -> None:
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        _assert_same(serial, compare_model(MODEL, chunk_poses=9, client=client, **OPTIONS))
        check = koenig_check.compare([MODEL], client=client, keep_records=True, **OPTIONS)
    assert check.ok, check.reason()
    np.testing.assert_array_equal(check.comparisons[0].records["reference_value"], serial.records["reference_value"])


def test_a_non_finite_state_is_reported_as_such_not_as_an_engine_disagreement(tmp_path, capsys) -> None:
    """Rates of 1e160 overflow the energy (½ m v² > 1e308): the pose is named, no engine gap is made of NaNs."""
    from koenig_check.cli import main

    path = tmp_path / "huge.csv"
    np.savetxt(path, np.array([[0.1, 0.2, 1e160, 1e160], [0.0, 0.3, 1.0, 2.0]]), delimiter=",")
    with np.errstate(over="ignore", invalid="ignore"):
        check = koenig_check.compare(["gimbal.xml"], pose_file=path)
        code = main(["compare", "gimbal.xml", "--pose-file", str(path)])
    assert not check.ok
    reason = check.reason().lower()
    assert "mujoco gives a non-finite rigid energy at pose file-0" in reason, reason
    assert "differ" not in reason and "nan" not in reason and "disagree" not in reason.split(":")[-1]
    out = " ".join(capsys.readouterr().out.split()).lower()
    assert code == 1
    assert "mujoco gives a non-finite rigid energy at pose file-0" in out, out
    assert "differ" not in out and "drake" not in out  # no tie-breaker consulted on NaNs
