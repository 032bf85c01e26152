"""The pipeline at scale: chunked, serial, --jobs and Dask runs agree exactly; streamed summaries equal
summaries of the full record table; memory stays bounded."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.api import compare_model
from koenig_check.run import summaries
from koenig_check.run.poses import random_pose_range, random_poses
from koenig_check.run.records import RECORD_FIELDS
from koenig_check.run.summaries import summarize_records

FREE_BALL_HINGE = Path(__file__).resolve().parents[1] / "data" / "free_ball_hinge.xml"
MODELS = Path(__file__).resolve().parents[2] / "models"
N_POSES = 40


def _run(**options):
    return compare_model(FREE_BALL_HINGE, n_poses=N_POSES, seed=5, records="segments", **options)


def _assert_same(a, b) -> None:
    assert a.stats.n_poses == b.stats.n_poses == N_POSES
    assert summaries.summarize(a) == summaries.summarize(b)
    assert summaries.engine_agreement(a) == summaries.engine_agreement(b)
    assert a.refusals == b.refusals
    assert len(a.records) == len(b.records) > 0
    ca, cb = a.records.columns, b.records.columns
    for name in RECORD_FIELDS:
        np.testing.assert_array_equal(ca[name], cb[name], err_msg=name)


@pytest.fixture(scope="module")
def serial():
    return _run(chunk_poses=10_000)


def test_the_model_has_free_ball_and_hinge_joints(serial) -> None:
    pair = koenig_check.engines.load_model(FREE_BALL_HINGE)
    assert set(pair.mujoco.dofs_by_kind()) == {"free", "ball", "hinge"}
    assert summaries.engine_agreement(serial).agrees


def test_chunked_run_equals_serial_run(serial) -> None:
    chunked = _run(chunk_poses=7)  # 6 chunks, the last one short
    _assert_same(serial, chunked)


def test_two_processes_equal_serial_run(serial) -> None:
    _assert_same(serial, _run(chunk_poses=9, jobs=2))


def test_dask_cluster_equals_serial_run(serial) -> None:
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        _assert_same(serial, _run(chunk_poses=11, client=client))
        check = koenig_check.compare([FREE_BALL_HINGE], n_poses=N_POSES, seed=5, client=client, records="segments")
    assert check.ok and summaries.summarize(check.comparisons[0]) == summaries.summarize(serial)


def test_random_pose_ranges_are_slices_of_the_sequence() -> None:
    model = koenig_check.engines.load_model(FREE_BALL_HINGE).mujoco.model
    whole = random_poses(model, 3000, seed=2)
    part = random_pose_range(model, 1000, 2100, seed=2)  # crosses a block boundary
    np.testing.assert_array_equal(part.qpos, whole.qpos[1000:2100])
    np.testing.assert_array_equal(part.qvel, whole.qvel[1000:2100])
    assert part.ids[0] == "random-1000" and part.ids == whole.ids[1000:2100]
    assert not np.array_equal(random_pose_range(model, 0, 10, seed=3).qpos, whole.qpos[:10])


@pytest.mark.parametrize("model", [FREE_BALL_HINGE, MODELS / "serial7.xml", MODELS / "gimbal.xml"])
def test_streamed_summary_equals_summary_of_the_full_record_table(model: Path) -> None:
    comp = compare_model(model, n_poses=300, seed=1, records="segments", chunk_poses=64)
    streamed = summaries.summaries_from_stats(comp.model, comp.stats)
    from_table = summarize_records(comp.records, comp.stats.rtol, comp.model)
    assert len(streamed) == len(from_table) > 10
    assert streamed == from_table
    # Independent of both: one group recomputed here from the record columns.
    rec = comp.records.where(formula="koenig_world", source="mujoco", reference="mujoco", scope="total")
    rel = np.abs(rec["value"] - rec["reference_value"]) / np.abs(rec["reference_value"])
    kw = next(s for s in streamed if (s.formula, s.source, s.reference) == ("koenig_world", "mujoco", "mujoco"))
    assert kw.median_rel_error == pytest.approx(np.median(rel), rel=1e-12)
    assert kw.max_rel_error == pytest.approx(rel.max(), rel=1e-12)


def test_grid_and_trajectory_poses_stream_the_same(tmp_path: Path) -> None:
    gimbal = MODELS / "gimbal.xml"
    opts = {"pose_kind": "grid", "n_poses": 9, "grid_joints": ("outer_z", "inner_x"), "records": "segments"}
    whole, chunked = compare_model(gimbal, **opts), compare_model(gimbal, chunk_poses=10, **opts)
    assert summaries.summarize(whole) == summaries.summarize(chunked)
    np.testing.assert_array_equal(whole.records["value"], chunked.records["value"])
    traj = compare_model(gimbal, pose_kind="trajectory", n_poses=50, chunk_poses=10)
    assert any(s.formula == "alyushin_paper:integrated" for s in summaries.summarize(traj))


MEMORY_SCRIPT = """
import resource, sys
import koenig_check
from koenig_check.report import RecordFiles
files = RecordFiles(sys.argv[2])
check = koenig_check.compare("talos", n_poses=int(sys.argv[1]), allow_coupled=True, sink=files, debug=True)
files.close()
try:  # this process's own peak (ru_maxrss would carry the parent's over fork + exec on Linux)
    status = open("/proc/self/status").read()
    peak = int(status.split("VmHWM:")[1].split()[0]) * 1024
except OSError:
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * (1 if sys.platform == "darwin" else 1024)
print(peak, files.rows, check.ok)
"""
#: Stated bound on the peak memory of 2×10^4 Talos poses, streamed: whole-table memory took ~9 GB.
MEMORY_BOUND = 1 << 30


def test_twenty_thousand_talos_poses_stay_under_a_gibibyte(tmp_path: Path) -> None:
    proc = subprocess.run(
        [sys.executable, "-c", MEMORY_SCRIPT, "20000", str(tmp_path)],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    peak, rows, ok = proc.stdout.split()
    assert ok == "True"
    assert int(rows) == 20000 * 40  # 10 formulas x 2 sources x 2 references per pose, streamed to the file
    assert int(peak) < MEMORY_BOUND, f"peak memory {int(peak) / 2**20:.0f} MiB"


def test_benchmark_smoke_run_does_not_crash() -> None:
    script = Path(__file__).resolve().parents[2] / "comparisons" / "benchmark.py"
    proc = subprocess.run(
        [sys.executable, str(script), "--smoke"], capture_output=True, text=True, check=False, timeout=600
    )
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    table = [line for line in proc.stdout.splitlines() if line.startswith("| ur5") or line.startswith("| talos")]
    assert len(table) == 2 and all("nan" not in line for line in table), proc.stdout


def test_record_files_are_parquet_with_categorical_columns(tmp_path: Path) -> None:
    import pyarrow.parquet as pq

    from koenig_check.cli import main

    out = tmp_path / "r"
    code = main(["compare", str(FREE_BALL_HINGE), "--poses", "30", "--records", "segments", "--out", str(out)])
    assert code == 0
    table = pq.read_table(out / "records.parquet")
    # The file stores value and reference; the error columns are derived when read.
    assert table.column_names == [k for k in RECORD_FIELDS if k not in ("abs_error", "rel_error", "signed_error")]
    for name in ("model", "formula", "source", "reference", "scope"):
        assert str(table.schema.field(name).type).startswith("dictionary<"), name
    assert b"koenig_check.rel_error" in table.schema.metadata
    doc = json.loads((out / "records.json").read_text())
    assert doc["record_count"] == table.num_rows == len(doc["records"])
    assert set(table.column("scope").to_pylist()) >= {"total", "root", "shoulder", "elbow"}
    value, ref = table.column("value").to_numpy(), table.column("reference_value").to_numpy()
    records = koenig_check.read_records(out / "records.parquet")
    assert records.to_arrow().column_names == list(RECORD_FIELDS)
    np.testing.assert_allclose(records["rel_error"], np.abs(value - ref) / np.abs(ref), rtol=1e-12, atol=0)
    np.testing.assert_array_equal(records["signed_error"], value - ref)
    np.testing.assert_array_equal(records["abs_error"], np.abs(value - ref))
    # The JSON rows (a small run) carry the same records, errors included.
    rows = np.array([r[RECORD_FIELDS.index("rel_error")] for r in doc["records"]], dtype=float)
    np.testing.assert_allclose(rows, records["rel_error"], rtol=1e-12, atol=0)
    code = main(["compare", str(FREE_BALL_HINGE), "--poses", "30", "--records", "none", "--out", str(tmp_path / "n")])
    assert code == 0 and pq.read_table(tmp_path / "n" / "records.parquet").num_rows == 0


@pytest.mark.parametrize("flag", [["--jobs", "0"], ["--records", "all"], ["--jobs", "x"]])
def test_bad_scale_flags_are_usage_errors(flag: list[str], capsys: pytest.CaptureFixture[str]) -> None:
    from koenig_check.cli import main

    with pytest.raises(SystemExit) as exc:
        main(["compare", str(FREE_BALL_HINGE), *flag])
    assert exc.value.code == 2
    assert flag[0] in capsys.readouterr().err


def test_scheduler_flag_runs_the_chunks_on_a_dask_cluster(tmp_path: Path) -> None:
    distributed = pytest.importorskip("distributed")
    from koenig_check.cli import main

    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=None) as c:
        code = main(["compare", str(FREE_BALL_HINGE), "--poses", "40", "--seed", "5", "--scheduler",
                     c.scheduler_address, "--out", str(tmp_path / "dask")])  # fmt: skip
    assert code == 0
    assert main(["compare", str(FREE_BALL_HINGE), "--poses", "40", "--seed", "5", "--out", str(tmp_path / "one")]) == 0
    a = json.loads((tmp_path / "dask" / "records.json").read_text())
    b = json.loads((tmp_path / "one" / "records.json").read_text())
    assert a["summaries"] == b["summaries"] and a["records"] == b["records"] and a["parity"] == b["parity"]


def test_no_writing_thread_is_alive_when_jobs_fork_their_workers(tmp_path: Path, monkeypatch) -> None:
    """A thread holding Arrow's locks at fork time can deadlock the forked workers: writes are finished first."""
    import threading
    import time

    from koenig_check.cli import main
    from koenig_check.report import RecordFiles
    from koenig_check.run import chunk_tasks, pipeline

    monkeypatch.setattr(chunk_tasks, "chunk_size", lambda n_segments: 8)
    write = RecordFiles._write_now

    def slow(self, table):  # a slow disk: without the flush the write is still running at the next fork
        time.sleep(0.3)
        write(self, table)

    monkeypatch.setattr(RecordFiles, "_write_now", slow)
    alive_at_fork: list[list[str]] = []
    pool = pipeline._pool

    def watched(jobs, *model):
        alive_at_fork.append([t.name for t in threading.enumerate() if t.name == "records-parquet"])
        return pool(jobs, *model)

    monkeypatch.setattr(pipeline, "_pool", watched)
    code = main(["compare", "gimbal.xml", "serial7.urdf", "--poses", "24", "--jobs", "2", "--out", str(tmp_path / "r")])
    assert code == 0 and len(alive_at_fork) == 2 and alive_at_fork == [[], []]


def test_a_failed_record_write_fails_its_own_model_not_the_next(tmp_path: Path, monkeypatch) -> None:
    """Records are written in a thread: the error of a model's last write belongs to that model."""
    import pyarrow.parquet as pq

    from koenig_check.report import RecordFiles

    write = pq.ParquetWriter.write_table
    calls: list[int] = []

    def first_write_fails(self, table, *args, **kwargs):
        calls.append(table.num_rows)
        if len(calls) == 1:
            raise OSError("records.parquet: No space left on device")
        write(self, table, *args, **kwargs)

    monkeypatch.setattr(pq.ParquetWriter, "write_table", first_write_fails)
    sink = RecordFiles(tmp_path)
    check = koenig_check.compare(["gimbal.xml", "double_pendulum.xml"], n_poses=20, sink=sink)
    sink.close()
    assert [c.model for c in check.comparisons] == ["double_pendulum.xml"]
    assert len(check.failures) == 1
    assert check.failures[0][0] == "gimbal.xml" and "No space left" in check.failures[0][1]


def test_an_interrupted_run_leaves_no_partial_record_file_and_no_writing_thread(tmp_path: Path, monkeypatch) -> None:
    import threading

    from koenig_check.cli import main
    from koenig_check.run import chunk_tasks, pipeline

    run_chunk, started = pipeline.run_chunk, []

    def interrupted_at_third_chunk(task, model=None):
        started.append(task)
        if len(started) == 3:
            raise KeyboardInterrupt
        return run_chunk(task, model)

    monkeypatch.setattr(chunk_tasks, "chunk_size", lambda n_segments: 8)
    monkeypatch.setattr(pipeline, "run_chunk", interrupted_at_third_chunk)
    out = tmp_path / "r"
    assert main(["compare", "gimbal.xml", "--poses", "64", "--out", str(out)]) == 130
    assert len(started) == 3
    assert not (out / "records.parquet").exists()
    assert [t for t in threading.enumerate() if t.name == "records-parquet"] == []


def test_dask_threads_sharing_one_model_equal_serial_run(monkeypatch) -> None:
    """A Dask worker runs chunks in several threads of one process, all on the model that process loaded once:
    the engines' data (MuJoCo's MjData, Pinocchio's Data) must not be used by two chunks at a time (it gave
    other numbers in about half of such runs)."""
    import threading
    import time

    from koenig_check.run import pipeline

    distributed = pytest.importorskip("distributed")
    run_engine, lock, active, most = pipeline.run_engine, threading.Lock(), [0], [0]

    def watched(engine, poses):  # counts the chunks inside an engine at once; the sleep widens the window
        with lock:
            active[0] += 1
            most[0] = max(most[0], active[0])
        try:
            time.sleep(0.02)
            return run_engine(engine, poses)
        finally:
            with lock:
                active[0] -= 1

    options = dict(n_poses=1000, seed=5, records="totals", chunk_poses=50, keep_records=True)
    serial = compare_model("ur5", **options)
    monkeypatch.setattr(pipeline, "run_engine", watched)
    with (
        distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        threaded = compare_model("ur5", client=client, **options)
    assert most[0] == 1
    for name in ("value", "reference_value"):
        np.testing.assert_array_equal(threaded.records[name], serial.records[name], err_msg=name)
    assert summaries.summarize(threaded) == summaries.summarize(serial)
