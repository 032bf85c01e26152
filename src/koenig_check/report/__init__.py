"""Reports of a run: the terminal table, ``summary.md``, ``report.html``, the figures and the record files.

Modules, one job each:

``write``
    The report directory: :func:`write_report` (summary, JSON, record files, figures, HTML).
``record_files``
    The record files a run streams into (:class:`RecordFiles`, :class:`RecordSink`).
``markdown``
    ``summary.md``.
``content``
    What ``summary.md`` and ``report.html`` both say (glossary, per-model findings and tables, notes).
``html``
    ``report.html``: one self-contained page.
``figures``
    The PNG figures (error distributions, the error map, the trajectory energy).
``terminal``
    The table printed in the terminal (100 columns).
``output_dir``
    The ``--out`` directory: checked before any work, earlier own files cleaned, the file list.
``progress``
    The progress bar on stderr.

The names of the former module ``koenig_check.report`` are imported from here as before
(``from koenig_check.report import write_report, RecordFiles, RecordSink``).
"""

from __future__ import annotations

from koenig_check.report.markdown import COLUMN_TITLES, summary_markdown
from koenig_check.report.record_files import SMALL_RUN_ROWS, RecordFiles, RecordSink, write_records_csv
from koenig_check.report.write import figure_name, write_json, write_report

__all__ = [
    "COLUMN_TITLES",
    "SMALL_RUN_ROWS",
    "RecordFiles",
    "RecordSink",
    "figure_name",
    "summary_markdown",
    "write_json",
    "write_records_csv",
    "write_report",
]
