"""koenig_check.report is a package: the names of the former module ``koenig_check.report`` still import from it."""

from __future__ import annotations

import importlib

import pytest

import koenig_check.report

#: Name of the former module koenig_check.report -> the module of the package that defines it now.
FORMER_NAMES = {
    "COLUMN_TITLES": "markdown",
    "summary_markdown": "markdown",
    "SMALL_RUN_ROWS": "record_files",
    "RecordFiles": "record_files",
    "RecordSink": "record_files",
    "write_records_csv": "record_files",
    "figure_name": "write",
    "write_json": "write",
    "write_report": "write",
}


@pytest.mark.parametrize("name", sorted(FORMER_NAMES))
def test_a_name_of_the_former_module_is_the_new_modules_object(name: str) -> None:
    home = importlib.import_module(f"koenig_check.report.{FORMER_NAMES[name]}")
    assert getattr(koenig_check.report, name) is getattr(home, name)


def test_the_package_exports_exactly_the_former_names() -> None:
    assert sorted(koenig_check.report.__all__) == sorted(FORMER_NAMES)
