"""Arrow arrays built and read on their buffers: the same arrays as pyarrow's own, and no pandas import in a run."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pyarrow as pa
import pytest

from koenig_check.run.arrow_arrays import as_numpy, booleans, numbers, strings
from koenig_check.run.records import RecordTable

NUMBER_TYPES = [pa.int8(), pa.int16(), pa.int32(), pa.int64(), pa.uint8(), pa.float32(), pa.float64()]


@pytest.mark.parametrize("arrow_type", NUMBER_TYPES, ids=str)
def test_numbers_equal_pyarrows_array_and_read_back(arrow_type: pa.DataType, rng: np.random.Generator) -> None:
    values = rng.integers(0, 100, size=(4, 5))
    array = numbers(values, arrow_type)
    assert array.equals(pa.array(values.ravel(), type=arrow_type))
    np.testing.assert_array_equal(as_numpy(array), values.ravel())
    np.testing.assert_array_equal(as_numpy(array.slice(3, 7)), values.ravel()[3:10])  # an offset into the buffer
    with pytest.raises(ValueError, match="read-only"):
        as_numpy(array)[0] = 1  # a view of the table's own memory


def test_booleans_and_strings_equal_pyarrows_arrays(rng: np.random.Generator) -> None:
    mask = rng.random(77) > 0.5  # not a multiple of 8: the last byte's bits are partly padding
    assert booleans(mask).equals(pa.array(mask))
    words = ["total", "segment1", "", "Drehgelenk", "ŝarniro", "関節"]  # ASCII, empty and multi-byte UTF-8
    assert strings(words).equals(pa.array(words, type=pa.string()))
    assert strings([]).equals(pa.array([], type=pa.string()))


def test_as_numpy_of_chunked_arrays_and_its_refusal() -> None:
    chunked = pa.chunked_array([numbers(np.arange(3.0)), numbers(np.arange(3.0, 5.0))])
    np.testing.assert_array_equal(as_numpy(chunked), np.arange(5.0))
    assert as_numpy(pa.chunked_array([], type=pa.float64())).shape == (0,)
    with pytest.raises(ValueError, match="has 1 missing"):
        as_numpy(pa.array([1.0, None]))


def test_a_run_and_its_report_import_no_pandas(tmp_path) -> None:
    pytest.importorskip("pandas")  # in [test]: without it there is nothing to import
    script = textwrap.dedent(
        f"""
        import sys
        import koenig_check
        from koenig_check.cli import main

        koenig_check.compare("ur5", n_poses=300, seed=0)
        assert main(["compare", "ur5", "--poses", "300", "--out", {str(tmp_path)!r}]) == 0
        print("pandas" in sys.modules)
        """
    )
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=False)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip().splitlines()[-1] == "False", "a run imported pandas (0.1-0.2 s of every run)"


def test_a_record_tables_columns_are_read_only() -> None:
    table = RecordTable(
        {
            "model": ["m", "m"],
            "pose": ["p0", "p1"],
            "formula": ["exact", "exact"],
            "source": ["mujoco", "mujoco"],
            "reference": ["mujoco", "mujoco"],
            "scope": ["total", "total"],
            "value": [1.0, 2.0],
            "reference_value": [1.0, 2.5],
        }
    )
    value = table["value"]
    with pytest.raises(ValueError, match="read-only"):
        value[0] = 1e9
    assert table["rel_error"][1] == pytest.approx(0.2)
