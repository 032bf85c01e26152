"""Record files: what ``records.parquet`` stores and how it reads back (koenig_check.run.records)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import koenig_check
from koenig_check.report import RecordFiles
from koenig_check.run.records import STORED_SCHEMA, RecordFileError, RecordTable, categorical


def _table(value: list[float], reference: list[float]) -> pa.Table:
    n = len(value)
    codes = np.zeros(n, dtype=np.int8)
    arrays = [
        categorical(np.zeros(n, dtype=np.int16), ["m"], "model"),
        categorical(np.arange(n, dtype=np.int32), [f"p{i}" for i in range(n)], "pose"),
        categorical(codes, ["exact"], "formula"),
        categorical(codes, ["mujoco"], "source"),
        categorical(codes, ["pinocchio"], "reference"),
        categorical(np.zeros(n, dtype=np.int16), ["total"], "scope"),
        pa.array(value, pa.float64()),
        pa.array(reference, pa.float64()),
    ]
    return pa.Table.from_arrays(arrays, schema=STORED_SCHEMA)


def test_record_file_reads_back_with_errors_computed_by_hand(tmp_path: Path) -> None:
    files = RecordFiles(tmp_path, csv_rows=0)
    files.write(_table([3.0, -1.0], [2.0, 4.0]))
    files.write(_table([0.0, 5.0], [0.0, 0.0]))
    files.close()
    records = koenig_check.read_records(tmp_path / "records.parquet")
    assert len(records) == 4
    # By hand: |3-2|/2, |-1-4|/4, 0/0 is 0, 5/0 is inf.
    np.testing.assert_array_equal(records["rel_error"], [0.5, 1.25, 0.0, np.inf])
    np.testing.assert_array_equal(records["signed_error"], [1.0, -5.0, 0.0, 5.0])
    np.testing.assert_array_equal(records["abs_error"], [1.0, 5.0, 0.0, 5.0])
    np.testing.assert_array_equal(records["pose"], ["p0", "p1", "p0", "p1"])


def test_record_file_stores_no_error_columns_and_says_how_to_derive_them(tmp_path: Path) -> None:
    files = RecordFiles(tmp_path, csv_rows=0)
    files.write(_table([1.0], [1.0]))
    files.close()
    schema = pq.read_schema(tmp_path / "records.parquet")
    assert schema.names == STORED_SCHEMA.names
    assert not any(field.nullable for field in schema)  # no missing values: no definition levels written
    assert schema.metadata[b"koenig_check.signed_error"] == b"value - reference_value"


def test_a_parquet_file_that_is_not_records_is_refused_naming_file_and_columns(tmp_path: Path) -> None:
    path = tmp_path / "other.parquet"
    pq.write_table(pa.table({"value": [1.0]}), path)
    with pytest.raises(RecordFileError, match=r"other\.parquet.*no column model, pose, formula"):
        koenig_check.read_records(path)


def test_record_table_round_trips_through_the_file(tmp_path: Path) -> None:
    table = _table([1.5, 2.5, 3.5], [1.0, 2.0, 4.0])
    files = RecordFiles(tmp_path, csv_rows=0)
    files.write(table)
    files.close()
    back = koenig_check.read_records(tmp_path / "records.parquet")
    assert back.rows() == RecordTable(table).rows()


def test_chunks_written_in_the_background_keep_their_order(tmp_path: Path) -> None:
    import time

    files = RecordFiles(tmp_path, csv_rows=0)
    write = files._writer.write_table

    def slow(table: pa.Table) -> None:  # a slow disk: the next chunk arrives while this one is written
        time.sleep(0.05)
        write(table)

    files._writer.write_table = slow
    for k in range(4):
        files.write(_table([float(k), float(k) + 0.5], [1.0, 1.0]))
    files.close()
    back = koenig_check.read_records(tmp_path / "records.parquet")
    np.testing.assert_array_equal(back["value"], [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5])


def test_a_failed_background_write_is_raised_not_lost(tmp_path: Path) -> None:
    files = RecordFiles(tmp_path, csv_rows=0)

    def full(table: pa.Table) -> None:
        raise OSError(f"{files.parquet}: No space left on device")

    files._writer.write_table = full
    files.write(_table([1.0], [1.0]))
    with pytest.raises(OSError, match="No space left"):
        files.close()


def test_rows_of_a_formula_refused_in_a_later_chunk_are_listed_and_left_out_when_read(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """planar accepted by the first chunks (the gimbal turning about z), refused by a later one."""
    import json

    from koenig_check.cli import main
    from koenig_check.run import chunk_tasks

    rng = np.random.default_rng(0)
    planar = [[rng.uniform(-1, 1), 0.0, rng.normal(), 0.0] for _ in range(chunk_tasks.PROBE_POSES + 44)]
    spatial = [[rng.uniform(-1, 1), rng.uniform(-1, 1), rng.normal(), rng.normal()] for _ in range(20)]
    poses = tmp_path / "poses.csv"
    np.savetxt(poses, np.array(planar + spatial), delimiter=",")
    argv = ["compare", "gimbal.xml", "--pose-file", str(poses), "--formulas", "exact", "planar"]
    assert main([*argv, "--out", str(tmp_path / "whole")]) == 0  # one chunk: planar refused, no row of it
    monkeypatch.setattr(chunk_tasks, "chunk_size", lambda n_segments: 50)
    assert main([*argv, "--out", str(tmp_path / "chunked")]) == 0
    raw = pq.read_table(tmp_path / "chunked" / "records.parquet")
    assert "planar" in raw.column("formula").to_pylist()  # written by the chunks that accepted it
    refused = json.loads(pq.read_metadata(tmp_path / "chunked" / "records.parquet").metadata[b"koenig_check.refused"])
    assert {(r["formula"], r["source"]) for r in refused} == {("planar", "mujoco"), ("planar", "pinocchio")}
    whole = koenig_check.read_records(tmp_path / "whole" / "records.parquet")
    chunked = koenig_check.read_records(tmp_path / "chunked" / "records.parquet")
    assert "planar" not in set(chunked["formula"]) and chunked.rows() == whole.rows()
    small = json.loads((tmp_path / "chunked" / "records.json").read_text())["records"]
    assert len(small) == len(whole) and not any(r[2] == "planar" for r in small)


def _two_sources(formula: str) -> pa.Table:
    """Rows of ``formula`` on MuJoCo's and on Pinocchio's states, two poses each."""
    codes = np.zeros(4, dtype=np.int8)
    arrays = [
        categorical(np.zeros(4, dtype=np.int16), ["m"], "model"),
        categorical(np.array([0, 1, 0, 1], dtype=np.int32), ["p0", "p1"], "pose"),
        categorical(codes, [formula], "formula"),
        categorical(np.array([0, 0, 1, 1], dtype=np.int8), ["mujoco", "pinocchio"], "source"),
        categorical(np.array([1, 1, 0, 0], dtype=np.int8), ["mujoco", "pinocchio"], "reference"),
        categorical(np.zeros(4, dtype=np.int16), ["total"], "scope"),
        pa.array([1.0, 2.0, 3.0, 4.0], pa.float64()),
        pa.array([1.0, 2.0, 3.0, 4.0], pa.float64()),
    ]
    return pa.Table.from_arrays(arrays, schema=STORED_SCHEMA)


def test_a_formula_refused_on_one_engines_states_keeps_the_other_engines_rows(tmp_path: Path) -> None:
    """planar refused on MuJoCo's states only: its rows on Pinocchio's states are results and stay."""
    files = RecordFiles(tmp_path, csv_rows=100)
    files.write(_two_sources("exact"))
    files.write(_two_sources("planar"))
    files.refuse("m", "planar", "mujoco", "not plane-parallel")
    files.close()
    expected = [("exact", "mujoco"), ("exact", "mujoco"), ("exact", "pinocchio"), ("exact", "pinocchio")]
    expected += [("planar", "pinocchio"), ("planar", "pinocchio")]
    back = koenig_check.read_records(tmp_path / "records.parquet")
    assert list(zip(back["formula"], back["source"], strict=True)) == expected
    np.testing.assert_array_equal(back["value"], [1.0, 2.0, 3.0, 4.0, 3.0, 4.0])
    small = files.small
    assert small is not None and list(zip(small["formula"], small["source"], strict=True)) == expected
