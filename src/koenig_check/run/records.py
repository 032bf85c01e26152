"""A tidy table of comparison records, stored column by column in Apache Arrow.

Text columns are categorical (Arrow dictionary columns: small integer codes plus the distinct
strings), so a record costs a few bytes of codes and two floats; the error columns
(``abs_error``, ``rel_error``, ``signed_error``) are derived from ``value`` and ``reference_value``
when read or written.  Rows come pose by pose (every formula, source, reference and scope of a
pose, then the next pose), so that a run cut into chunks lists its records in the same order as the
run in one piece.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa

from koenig_check.exceptions import RecordFileError
from koenig_check.run.arrow_arrays import as_numpy, booleans, numbers, strings
from koenig_check.run.stats import absolute_relative_error

#: The columns of every record, in order.
RECORD_FIELDS = (
    "model",
    "pose",
    "formula",
    "source",
    "reference",
    "scope",
    "value",
    "reference_value",
    "abs_error",
    "rel_error",
    "signed_error",
)
TEXT_FIELDS = ("model", "pose", "formula", "source", "reference", "scope")
DERIVED_FIELDS = ("abs_error", "rel_error", "signed_error")
#: The code width of each categorical column.
_INDEX_TYPES = {
    "model": pa.int16(),
    "pose": pa.int32(),
    "formula": pa.int8(),
    "source": pa.int8(),
    "reference": pa.int8(),
    "scope": pa.int16(),
}
#: The key of a record file's metadata listing the formulas refused per model and state source (JSON).
REFUSED_KEY = "koenig_check.refused"
#: How the error columns follow from the stored ones (kept in the metadata of record files).
DERIVATION = {
    "abs_error": "|value - reference_value|",
    "rel_error": "|value - reference_value| / |reference_value| (0 where both are 0, inf where only the reference is)",
    "signed_error": "value - reference_value",
}
#: The stored columns (the error columns are derived), the schema of ``records.parquet``.
#: No column has missing values (not nullable: Parquet then writes no definition levels, a fifth less
#: writing time).
STORED_SCHEMA = pa.schema(
    [pa.field(k, pa.dictionary(_INDEX_TYPES[k], pa.string()), nullable=False) for k in TEXT_FIELDS]
    + [pa.field("value", pa.float64(), nullable=False), pa.field("reference_value", pa.float64(), nullable=False)],
    metadata={f"koenig_check.{k}": v for k, v in DERIVATION.items()},
)


def categorical(codes: np.ndarray, categories: Sequence[str], name: str) -> pa.DictionaryArray:
    """A categorical column from integer codes into a list of strings.

    Parameters
    ----------
    codes : ndarray of int
    categories : sequence of str
    name : str
        Column name (chooses the code width).

    Returns
    -------
    pyarrow.DictionaryArray
    """
    return pa.DictionaryArray.from_arrays(numbers(codes, _INDEX_TYPES[name]), strings(categories))


def empty_records() -> pa.Table:
    """A table of :data:`STORED_SCHEMA` without rows (``Schema.empty_table`` imports pandas when it is installed).

    Returns
    -------
    pyarrow.Table
    """
    nothing = np.empty(0)
    texts = [categorical(nothing, [], k) for k in TEXT_FIELDS]
    return pa.Table.from_arrays([*texts, numbers(nothing), numbers(nothing)], schema=STORED_SCHEMA)


def derived(value: np.ndarray, reference: np.ndarray) -> dict[str, np.ndarray]:
    """The error columns of records: absolute, relative (absolute value) and signed error.

    Parameters
    ----------
    value, reference : ndarray

    Returns
    -------
    dict of str to ndarray
    """
    signed = value - reference
    rel = absolute_relative_error(signed, np.abs(reference))
    return {"abs_error": np.abs(signed), "rel_error": rel, "signed_error": signed}


def _decode(column: pa.ChunkedArray) -> np.ndarray:
    parts = []
    for chunk in column.chunks:
        if pa.types.is_dictionary(chunk.type):
            words = np.asarray(chunk.dictionary.to_pylist(), dtype=str)
            parts.append(words[as_numpy(chunk.indices)] if len(words) else np.empty(0, str))
        else:
            parts.append(np.asarray(chunk.to_pylist(), dtype=str))
    return np.concatenate(parts) if parts else np.empty(0, dtype=str)


class RecordTable:
    """Tidy records: one row per (model, pose, formula, source, reference, scope).

    Index by column name for a numpy array (text columns decoded to numpy strings, numbers float);
    iterate for one ``dict`` per row.

    Parameters
    ----------
    data : pyarrow.Table or dict of str to array_like, optional
        A table with the columns of :data:`STORED_SCHEMA`, or columns keyed by (at least) the
        stored fields of :data:`RECORD_FIELDS`; derived columns given in a dict are ignored.
    """

    def __init__(self, data: pa.Table | dict[str, Any] | None = None) -> None:
        if data is None:
            data = empty_records()
        elif isinstance(data, dict):
            missing = [k for k in STORED_SCHEMA.names if k not in data]
            lengths = {len(data[k]) for k in STORED_SCHEMA.names if k in data}
            if missing or len(lengths) > 1:
                raise ValueError(f"RecordTable needs equal-length columns {RECORD_FIELDS}")
            arrays = []
            for k in TEXT_FIELDS:
                words, codes = np.unique(np.asarray(data[k], dtype=str), return_inverse=True)
                arrays.append(categorical(codes, words.tolist(), k))
            arrays += [numbers(np.asarray(data[k], dtype=float)) for k in ("value", "reference_value")]
            data = pa.Table.from_arrays(arrays, schema=STORED_SCHEMA)
        elif data.schema != STORED_SCHEMA:
            data = data.select(STORED_SCHEMA.names).cast(STORED_SCHEMA)
        self.table: pa.Table = data

    def __len__(self) -> int:
        return self.table.num_rows

    def __repr__(self) -> str:
        return f"<RecordTable {len(self)} rows, columns {', '.join(RECORD_FIELDS)}>"

    def __bool__(self) -> bool:
        return self.table.num_rows > 0

    def __getitem__(self, name: str) -> np.ndarray:
        if name in TEXT_FIELDS:
            return _decode(self.table.column(name))
        if name in ("value", "reference_value"):
            return as_numpy(self.table.column(name))
        if name in DERIVED_FIELDS:
            return derived(self["value"], self["reference_value"])[name]
        raise KeyError(f"no record column {name!r}; columns: {RECORD_FIELDS}")

    @property
    def columns(self) -> dict[str, np.ndarray]:
        """Every column of :data:`RECORD_FIELDS` as a numpy array."""
        value, ref = self["value"], self["reference_value"]
        out = {k: self[k] for k in TEXT_FIELDS}
        out.update(value=value, reference_value=ref, **derived(value, ref))
        return {k: out[k] for k in RECORD_FIELDS}

    def to_arrow(self) -> pa.Table:
        """The records with every column of :data:`RECORD_FIELDS` (the schema of record files).

        Returns
        -------
        pyarrow.Table
        """
        return with_derived(self.table)

    def __iter__(self) -> Iterator[dict[str, Any]]:
        for row in self.rows():
            yield dict(zip(RECORD_FIELDS, row, strict=True))

    def rows(self) -> list[list[Any]]:
        """Every row as a list in the order of :data:`RECORD_FIELDS`.

        Returns
        -------
        list of list
        """
        cols = self.columns
        return [list(r) for r in zip(*(cols[k].tolist() for k in RECORD_FIELDS), strict=True)]

    def mask(self, **equals: str) -> np.ndarray:
        """Boolean mask of the rows whose text columns equal the given values.

        Parameters
        ----------
        **equals : str
            Column name to required value.

        Returns
        -------
        ndarray of bool
        """
        keep = np.ones(len(self), dtype=bool)
        for name, value in equals.items():
            if name not in TEXT_FIELDS:
                raise KeyError(f"{name!r} is not a text column of the records; text columns: {TEXT_FIELDS}")
            parts = []
            for chunk in self.table.column(name).chunks:
                codes = np.flatnonzero(np.asarray(chunk.dictionary.to_pylist(), dtype=object) == value)
                indices = as_numpy(chunk.indices)
                # One code (a dictionary lists each word once): a comparison, several times faster than isin.
                parts.append(indices == codes[0] if len(codes) == 1 else np.isin(indices, codes))
            if parts:
                keep &= np.concatenate(parts)
        return keep

    def where(self, mask: np.ndarray | None = None, **equals: str) -> RecordTable:
        """The rows selected by a mask and/or equalities.

        Parameters
        ----------
        mask : ndarray of bool, optional
        **equals : str

        Returns
        -------
        RecordTable
        """
        keep = self.mask(**equals)
        if mask is not None:
            keep &= mask
        return RecordTable(self.table.filter(booleans(keep)))

    @staticmethod
    def concat(tables: Iterable[RecordTable]) -> RecordTable:
        """Stack several tables.

        Parameters
        ----------
        tables : iterable of RecordTable

        Returns
        -------
        RecordTable
        """
        tables = [t.table for t in tables if len(t)]
        if not tables:
            return RecordTable()
        return RecordTable(pa.concat_tables(tables))


def with_derived(table: pa.Table) -> pa.Table:
    """Add the derived error columns to a table of stored columns.

    Parameters
    ----------
    table : pyarrow.Table
        With the columns of :data:`STORED_SCHEMA`.

    Returns
    -------
    pyarrow.Table
        With every column of :data:`RECORD_FIELDS`.
    """
    value = as_numpy(table.column("value"))
    ref = as_numpy(table.column("reference_value"))
    cols = derived(value, ref)
    for k in DERIVED_FIELDS:
        table = table.append_column(pa.field(k, pa.float64()), numbers(cols[k]))
    return table


def read_records(path: str | Path) -> RecordTable:
    """Read a record file written by a report (``records.parquet``).

    The file stores the columns of :data:`STORED_SCHEMA`; the returned table answers every column
    of :data:`RECORD_FIELDS`, the error columns computed as :data:`DERIVATION` says
    (``.to_arrow()`` gives them as an Arrow table).  Rows of a formula the run refused for their model
    and state source (listed under :data:`REFUSED_KEY` in the file's metadata) are left out.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    RecordTable

    Raises
    ------
    RecordFileError
        If the file is not a record file (columns missing), naming the file and the missing columns.
    """
    import pyarrow.parquet as pq

    table = pq.read_table(path)
    missing = [k for k in STORED_SCHEMA.names if k not in table.column_names]
    if missing:
        raise RecordFileError(f"{path}: not a koenig-check record file: no column {', '.join(missing)}")
    footer = pq.read_metadata(path).metadata or {}
    refused = json.loads(footer.get(REFUSED_KEY.encode(), b"[]"))
    return without_refused(RecordTable(table), refused)


def without_refused(records: RecordTable, refused: Sequence[Mapping[str, str]]) -> RecordTable:
    """The records without the rows of formulas refused for their model and state source.

    Parameters
    ----------
    records : RecordTable
    refused : sequence of mapping
        Entries with ``model``, ``formula`` and ``source``.

    Returns
    -------
    RecordTable
    """
    if not refused or not len(records):
        return records
    drop = np.zeros(len(records), dtype=bool)
    for r in refused:
        rows = records.mask(formula=r["formula"])  # the most selective column first: usually no row at all
        if rows.any():
            drop |= rows & records.mask(model=r["model"], source=r["source"])
    return records.where(~drop) if drop.any() else records
