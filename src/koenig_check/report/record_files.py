"""The record files of a report directory (``records.parquet``, ``records.csv``), written as the records stream in."""

from __future__ import annotations

import json
import threading
from pathlib import Path
from typing import Protocol

import pyarrow as pa
import pyarrow.csv as pacsv
import pyarrow.parquet as pq

from koenig_check.report.engine_energies import EnergyChunk, energy_chunks
from koenig_check.run.records import REFUSED_KEY, STORED_SCHEMA, TEXT_FIELDS, RecordTable, without_refused


def _text_columns(table: pa.Table) -> pa.Table:
    """The same table with categorical columns decoded to strings (for CSV)."""
    schema = pa.schema([pa.field(f.name, pa.string()) if pa.types.is_dictionary(f.type) else f for f in table.schema])
    return table.cast(schema)


def write_records_csv(path: Path, records: RecordTable) -> Path:
    """Write tidy records as CSV with the columns of :data:`RECORD_FIELDS`.

    Parameters
    ----------
    path : Path
    records : RecordTable

    Returns
    -------
    Path
    """
    pacsv.write_csv(_text_columns(records.to_arrow()), path)
    return path


#: Record files of runs up to this many rows are also written as CSV and inside records.json.
SMALL_RUN_ROWS = 50_000


class RecordSink(Protocol):
    """Receives a run's records chunk by chunk (tables with the columns of ``STORED_SCHEMA``)."""

    def write(self, table: pa.Table) -> None:
        """Take one chunk's records."""
        ...

    def flush(self) -> None:
        """Finish every write taken (called at the end of each model, before the next one's workers are forked)."""
        ...

    def refuse(self, model: str, formula: str, source: str, reason: str) -> None:
        """A formula refused for a model on one engine's states: rows of it already taken do not count."""
        ...


class RecordFiles:
    """The record files of a report directory, written as the records stream in.

    Every chunk goes straight to ``records.parquet`` (Parquet through pyarrow: columnar,
    categorical columns stored as dictionary codes, read directly by pandas, polars, DuckDB,
    Spark).  The file holds the stored columns (:data:`~koenig_check.run.records.STORED_SCHEMA`); the
    error columns are one subtraction away (:func:`~koenig_check.run.records.read_records` adds them)
    and would triple its size and its writing time, being incompressible floats.  Runs of at most
    ``csv_rows`` records also get ``records.csv`` when closed, and keep their rows for
    ``records.json``; beyond that the small copy is dropped, so memory stays bounded.

    Parameters
    ----------
    out : Path
        The report directory (created if missing).
    name : str
        File stem.
    csv_rows : int
        Largest run written as CSV too.
    """

    def __init__(self, out: Path, name: str = "records", csv_rows: int = SMALL_RUN_ROWS) -> None:
        self.out = Path(out)
        self.out.mkdir(parents=True, exist_ok=True)
        self.parquet = self.out / f"{name}.parquet"
        self.csv = self.out / f"{name}.csv"
        self.csv_rows = csv_rows
        self.rows = 0
        self._small: list[pa.Table] | None = [] if csv_rows > 0 else None
        # Dictionary pages for the text columns only: the float columns are all distinct, and trying a
        # dictionary for them first doubles the writing time.  No min/max statistics: they cost half the
        # writing time, and every chunk spans the same models, formulas and a wide range of values.
        self._writer = pq.ParquetWriter(
            self.parquet, STORED_SCHEMA, use_dictionary=list(TEXT_FIELDS), write_statistics=False
        )
        # One chunk is written in a thread while the next is computed (Arrow's writer releases the GIL);
        # at most one write is pending, so at most two chunks of records are held.  The thread lives for
        # one write only: after flush() no thread of ours is left when --jobs forks its workers.
        self._pending: threading.Thread | None = None
        self._error: BaseException | None = None
        self.refused: list[dict[str, str]] = []
        self.written: list[Path] = []
        self._energy: list[EnergyChunk] = []  # each engine's energy per pose, for the engine-gap figures

    def write(self, table: pa.Table) -> None:
        """Append one chunk's records.

        Parameters
        ----------
        table : pyarrow.Table
            Columns of :data:`~koenig_check.run.records.STORED_SCHEMA`.
        """
        if not table.num_rows:
            return
        self.flush()
        self._pending = threading.Thread(target=self._write_now, args=(table,), name="records-parquet")
        self._pending.start()
        self.rows += table.num_rows
        self._energy += energy_chunks(RecordTable(table))
        if self._small is not None:
            self._small.append(table)
            if self.rows > self.csv_rows:
                self._small = None

    def _write_now(self, table: pa.Table) -> None:
        try:
            self._writer.write_table(table)
        except BaseException as err:  # raised in the caller's thread by flush()
            self._error = err

    def flush(self) -> None:
        """Finish the pending write, raising its error if it failed."""
        pending, self._pending = self._pending, None
        if pending is not None:
            pending.join()
        error, self._error = self._error, None
        if error is not None:
            raise error

    def refuse(self, model: str, formula: str, source: str, reason: str) -> None:
        """Record that a formula is refused for a model on one engine's states.

        A refusal can come in a later chunk than the first (``planar`` on a pose file whose first poses
        move in a plane): rows of that formula already written stay in the Parquet file, which cannot
        take them back, and are listed as refused in its metadata (:data:`~koenig_check.run.records.REFUSED_KEY`);
        :func:`~koenig_check.run.records.read_records`, ``records.csv`` and ``records.json`` leave them out,
        so that a run in chunks reads back as the run in one piece.

        Parameters
        ----------
        model, formula, source, reason : str
        """
        entry = {"model": model, "formula": formula, "source": source, "reason": reason}
        if entry not in self.refused:
            self.refused.append(entry)

    @property
    def small(self) -> RecordTable | None:
        """The records of a small run (None once the run outgrew ``csv_rows``), refused rows left out."""
        if self._small is None:
            return None
        return without_refused(RecordTable.concat(RecordTable(t) for t in self._small), self.refused)

    @property
    def energies(self) -> list[EnergyChunk]:
        """Each engine's energy per pose of every model written (see :mod:`koenig_check.report.engine_energies`)."""
        return self._energy

    def close(self) -> list[Path]:
        """Finish the files; return every file written.

        Returns
        -------
        list of Path
        """
        if self._writer is not None:
            try:
                self.flush()
                if self.refused:
                    self._writer.add_key_value_metadata({REFUSED_KEY: json.dumps(self.refused)})
            finally:
                self._writer.close()
                self._writer = None
            self.written = [self.parquet]
            small = self.small
            if small is not None:
                self.written.append(write_records_csv(self.csv, small))
        return self.written

    def abort(self) -> None:
        """Stop after a failed or interrupted run: finish the pending write, close and delete the partial file.

        A run that did not finish leaves no ``records.parquet`` that could pass for its records (and no
        writing thread of ours).  Write errors are dropped: the run's own failure is the one reported.
        """
        try:
            self.flush()
        except Exception:  # the interruption is what the user is told about
            pass
        if self._writer is not None:
            try:
                self._writer.close()
            except Exception:
                pass
            self._writer = None
        self._small = None
        self.parquet.unlink(missing_ok=True)

    def __enter__(self) -> RecordFiles:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
