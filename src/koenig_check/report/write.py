"""Markdown, JSON, Parquet, CSV and PNG out of the comparison: summaries, records and figures."""

from __future__ import annotations

import json
import re
import threading
from collections.abc import Sequence
from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
import pyarrow as pa
import pyarrow.csv as pacsv
import pyarrow.parquet as pq

from koenig_check.grid import EngineParity, FormulaSummary, ModelComparison
from koenig_check.records import RECORD_FIELDS, REFUSED_KEY, STORED_SCHEMA, TEXT_FIELDS, RecordTable, without_refused
from koenig_check.report.content import (
    COLUMNS,
    POSE_LABELS,
    glossary,
    model_findings,
    model_table,
    refusal_lines,
    run_conditions,
    run_overview,
    shared_notes,
)
from koenig_check.roundoff import ROUNDOFF, fmt

if TYPE_CHECKING:
    from koenig_check.api import CrossCheck

#: Smallest relative error drawn on a log axis (exact agreement is drawn here).
LOG_FLOOR = 1e-17


def _fmt(x: float) -> str:
    return f"{x:.2e}" if np.isfinite(x) else str(x)


def summary_markdown(
    comparisons: Sequence[ModelComparison],
    summaries: Sequence[FormulaSummary],
    parities: Sequence[EngineParity],
    failures: Sequence[tuple[str, str]] = (),
    rtol: float = 1e-9,
    settings: dict[str, dict] | None = None,
) -> str:
    """The Markdown summary, readable without the paper.

    Sections: what this run found (per model, in plain words), the formulas (glossary with the paper's
    equation numbers in brackets), how to read the tables (every column and pose label), one section per
    model (conditions, engine parity, the table, refusals), models that could not be compared, notes (each
    once, with the models it concerns).

    Parameters
    ----------
    comparisons : sequence of ModelComparison
    summaries : sequence of FormulaSummary
    parities : sequence of EngineParity
    failures : sequence of (model, reason)
        Models that could not be compared.
    rtol : float
    settings : dict, optional
        Per model, the run's pose settings (:attr:`koenig_check.api.CrossCheck.settings`).

    Returns
    -------
    str
    """
    settings = settings or {}
    parity = {p.model: p for p in parities}
    by_model: dict[str, list[FormulaSummary]] = {}
    for s in summaries:
        by_model.setdefault(s.model, []).append(s)
    formulas = list(dict.fromkeys(s.formula for s in summaries)) + sorted(
        {r["formula"] for c in comparisons for r in c.refusals} - {s.formula for s in summaries}
    )
    lines = [
        "# koenig-check report",
        "",
        "Kinetic energy of every moving segment of each model, computed by MuJoCo and by Pinocchio from the "
        "same joint positions and rates, and by each formula under test (Yu. Alyushin, *Correction of the "
        "Koenig formula for the kinetic energy of a rotating solid*) from each engine's segment states. "
        f"Tolerance: relative {rtol:g}. Numbers below {ROUNDOFF:g} are rounding and are printed as 0.",
        "",
        "## What this run found",
        "",
        *[" ".join(run_overview(comparisons, summaries, parities, failures))],
        "",
    ]
    for comp in comparisons:
        f = model_findings(comp, by_model.get(comp.model, []), parity.get(comp.model), rtol)
        lines.append(f"- **{comp.model}** ({f.poses}): {f.engines}.")
        if f.exact:
            lines.append(f"  - exact to rounding: {', '.join(f'`{n}`' for n in f.exact)}.")
        for text in f.inexact:
            name, rest = text.split(": ", 1)
            lines.append(f"  - not exact: `{name}` {rest}.")
        if f.refused:
            lines.append(f"  - refused (does not apply to this motion): {', '.join(f'`{n}`' for n in f.refused)}.")
    for model, reason in failures:
        lines.append(f"- **{model}**: could not be compared: {reason}")
    lines += ["", "## Formulas", "", "The paper's equation numbers are in brackets.", ""]
    lines += [f"- `{g.name}` [{g.equations}]: {g.text}." for g in glossary(formulas)]
    lines += ["", "## How to read the tables", ""]
    lines += [f"- **{name}**: {text}." for name, text in COLUMNS.items()]
    lines += ["", "Pose labels:", ""]
    lines += [f"- `{label}`: {text}." for label, text in POSE_LABELS.items()]
    lines.append("")
    for comp in comparisons:
        p = parity.get(comp.model)
        lines += [f"## {comp.model}", "", f"Conditions: {run_conditions(comp, settings.get(comp.model))}.", ""]
        if p is not None:
            exact = ", ".join(f"{k} {fmt(v)}" for k, v in p.exact_vs_engine.items())
            verdict = "the engines agree" if p.agrees else f"the engines DISAGREE: {p.reason}"
            lines.append(
                f"Engine parity: {verdict}. MuJoCo vs Pinocchio rigid-body energy, largest relative difference "
                f"{fmt(p.rigid_max_rel)} (pose {p.worst_pose}); armature energy, largest difference "
                f"{fmt(p.armature_max_abs)} J; `exact` on each engine's states vs that engine's energy: {exact}."
            )
            lines.append("")
        engines = list(comp.engines)
        lines.append(f"Max rel. error is given as {' / '.join(engines)}.")
        lines.append("")
        lines.append("| " + " | ".join(COLUMN_TITLES) + " |")
        lines.append("| " + " | ".join("---" for _ in COLUMN_TITLES) + " |")
        for row in model_table(by_model.get(comp.model, []), engines):
            lines.append(
                f"| `{row.formula}` [{row.equations}] | {row.verdict} | {row.max_error} | {row.median} | "
                f"{row.over_under} | {row.worst_pose} | {row.worst_segment or '—'} |"
            )
        refusals = refusal_lines(comp)
        if refusals:
            lines.append("")
            lines += [f"- {text}" for text in refusals]
        lines.append("")
    if failures:
        lines += ["## Models that could not be compared", ""]
        lines += [f"- {model}: {reason}" for model, reason in failures]
        lines.append("")
    notes = shared_notes(comparisons)
    if notes:
        lines += ["## Notes", "", "Each note once, with the models it concerns.", ""]
        for note, models in notes:
            lines.append(f"- {note} ({'all models' if not models else ', '.join(models)})")
        lines.append("")
    return "\n".join(lines)


#: Column titles of the per-model tables (defined in :data:`koenig_check.report.content.COLUMNS`).
COLUMN_TITLES = ("formula", "verdict", "max rel. error", "median", "over / under", "worst pose", "worst segment")


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
    Spark).  The file holds the stored columns (:data:`~koenig_check.records.STORED_SCHEMA`); the
    error columns are one subtraction away (:func:`~koenig_check.records.read_records` adds them)
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

    def write(self, table: pa.Table) -> None:
        """Append one chunk's records.

        Parameters
        ----------
        table : pyarrow.Table
            Columns of :data:`~koenig_check.records.STORED_SCHEMA`.
        """
        if not table.num_rows:
            return
        self.flush()
        self._pending = threading.Thread(target=self._write_now, args=(table,), name="records-parquet")
        self._pending.start()
        self.rows += table.num_rows
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
        take them back, and are listed as refused in its metadata (:data:`~koenig_check.records.REFUSED_KEY`);
        :func:`~koenig_check.records.read_records`, ``records.csv`` and ``records.json`` leave them out,
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


def _jsonable(x: Any) -> Any:
    if isinstance(x, float) and not np.isfinite(x):
        return str(x)
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.generic):
        return _jsonable(x.item())
    return x


def write_json(
    path: Path,
    records: RecordTable | None,
    summaries: Sequence[FormulaSummary],
    parities: Sequence[EngineParity],
    failures: Sequence[tuple[str, str]] = (),
    extra: dict[str, Any] | None = None,
) -> Path:
    """Write records, summaries, parity and failures as one JSON document.

    Records are stored as rows (lists) in the order of ``record_fields``, to keep the
    file small; summaries, parity and failures are objects.  Without records (a large run, whose
    records are in ``records.parquet``) the document has ``"records": null``.

    Parameters
    ----------
    path : Path
    records : RecordTable or None
    summaries : sequence of FormulaSummary
    parities : sequence of EngineParity
    failures : sequence of (model, reason)
    extra : dict, optional
        Anything else to store (e.g. load notes).

    Returns
    -------
    Path
    """
    doc = {
        "record_fields": list(RECORD_FIELDS),
        "records": records.rows() if records is not None else None,
        "summaries": [asdict(s) for s in summaries],
        "parity": [asdict(p) for p in parities],
        "failures": [{"model": m, "reason": r} for m, r in failures],
        **(extra or {}),
    }
    path.write_text(json.dumps(_jsonable(doc), separators=(",", ":")), encoding="utf-8")
    return path


def figure_name(model: str) -> str:
    """The file name of a model's error-distribution figure (``error_distribution_<model>.png``)."""
    slug = re.sub(r"[^A-Za-z0-9._-]+", "_", model).strip("_")
    return f"error_distribution_{slug}.png"


def write_report(
    out: Path,
    check: CrossCheck,
    grid_comparison: ModelComparison | None = None,
    trajectory_comparison: ModelComparison | None = None,
    map_formulas: Sequence[str] = ("koenig_world", "alyushin_paper:rotvec", "alyushin_paper:euler_xyz"),
    trajectory_formulas: Sequence[str] = (
        "exact",
        "koenig_world",
        "alyushin_paper:rotvec",
        "alyushin_paper:euler_xyz",
        "alyushin_paper:integrated",
    ),
    records: RecordFiles | None = None,
) -> list[Path]:
    """Write the report directory: summary.md, report.html, records.json, the record files and the figures.

    Figures: ``error_distribution_<model>.png`` per model, ``error_distribution.png`` pooled over the models
    (labelled so, with the models named) when there are several, ``error_map.png`` for a grid sweep and
    ``trajectory_energy.png`` for a trajectory.  ``report.html`` embeds them all.

    Parameters
    ----------
    out : Path
        Created if missing.
    check : CrossCheck
    grid_comparison : ModelComparison, optional
        A two-joint grid sweep: adds ``error_map.png``.
    trajectory_comparison : ModelComparison, optional
        A simulated trajectory: adds ``trajectory_energy.png``.
    map_formulas, trajectory_formulas : sequence of str
        Formulas drawn in those figures.
    records : RecordFiles, optional
        The record files the run streamed into (closed here).  Without it, the records the
        check holds in memory are written to ``records.parquet`` (and ``records.csv`` for a small run).

    Returns
    -------
    list of Path
        Every file written.
    """
    from koenig_check.report.figures import error_distribution_figure, error_map_figure, trajectory_figure
    from koenig_check.report.html import report_html

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if records is None:
        records = RecordFiles(out)
        for comp in check.comparisons:
            records.write(comp.records.table)
    written = [
        _write_text(
            out / "summary.md",
            summary_markdown(
                check.comparisons, check.summaries, check.parities, check.failures, check.rtol, check.settings
            ),
        ),
        *records.close(),
    ]
    written.append(
        write_json(
            out / "records.json",
            records.small,
            check.summaries,
            check.parities,
            check.failures,
            extra={
                "rtol": check.rtol,
                "records_file": records.parquet.name,
                "record_count": records.rows,
                "notes": {c.model: c.notes for c in check.comparisons},
                "refusals": [r for c in check.comparisons for r in c.refusals],
                "settings": check.settings,
            },
        )
    )
    figures: dict[int | None, list[tuple[Path, str]]] = {}  # by position in check.comparisons; None: the run
    with_stats = [c for c in check.comparisons if c.stats is not None and c.stats.kept_groups()]
    names: set[str] = set()
    for k, comp in enumerate(check.comparisons):
        if comp not in with_stats:
            continue
        name = figure_name(comp.model)
        while name in names:  # two comparisons with one label: both figures kept
            name = name.replace(".png", "_.png")
        names.add(name)
        caption = run_conditions(comp, check.settings.get(comp.model))
        path = error_distribution_figure([comp], out / name, check.rtol, caption)
        figures.setdefault(k, []).append(
            (path, f"{comp.model}: relative error of each formula's total energy. {caption}.")
        )
    if len(with_stats) > 1:
        names = ", ".join(c.model for c in with_stats)
        caption = f"pooled over {len(with_stats)} models ({names}); each model's own figure is in its section"
        # The figure's own title names the pooled models; its caption only points to the per-model figures.
        path = error_distribution_figure(
            with_stats, out / "error_distribution.png", check.rtol, "each model's own figure is in its section"
        )
        figures.setdefault(None, []).append((path, f"Relative error of each formula, {caption}."))
    if grid_comparison is not None:
        caption = run_conditions(grid_comparison, check.settings.get(grid_comparison.model))
        path = error_map_figure(grid_comparison, map_formulas, out / "error_map.png", caption=caption)
        figures.setdefault(_position(check, grid_comparison), []).append(
            (path, f"Signed relative error over the two joint angles (MuJoCo), one colour scale. {caption}.")
        )
    if trajectory_comparison is not None:
        caption = run_conditions(trajectory_comparison, check.settings.get(trajectory_comparison.model))
        path = trajectory_figure(
            trajectory_comparison, trajectory_formulas, out / "trajectory_energy.png", check.rtol, caption
        )
        figures.setdefault(_position(check, trajectory_comparison), []).append(
            (path, f"Kinetic energy along the trajectory and each formula's error. {caption}.")
        )
    written += [path for items in figures.values() for path, _ in items]
    written.append(_write_text(out / "report.html", report_html(check, figures)))
    return written


def _position(check: CrossCheck, comparison: ModelComparison) -> int | None:
    """Where a comparison stands in the check (None when it is not one of them: shown with the whole run)."""
    for k, comp in enumerate(check.comparisons):
        if comp is comparison:
            return k
    return None


def _write_text(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path
