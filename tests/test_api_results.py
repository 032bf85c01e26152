"""Short reprs, and results looked up by model and formula."""

from __future__ import annotations

import pytest

import koenig_check
from koenig_check.run.records import RECORD_FIELDS


@pytest.fixture(scope="module")
def check():
    return koenig_check.compare(["gimbal.xml", "ur5", "no_such_model.xml"], n_poses=3)


def test_repr_is_short_and_names_the_models(check):
    text = repr(check)
    assert len(text) < 200, text
    for part in ("gimbal.xml", "ur5", "no_such_model.xml", f"summaries={len(check.summaries)}", "failures=1"):
        assert part in text
    assert f"ok={check.ok}" in text
    assert len(repr(check["ur5"])) < 200


def test_record_table_repr_shows_size_and_columns(check):
    text = repr(check.records)
    assert f"{len(check.records)} rows" in text and len(check.records) > 0
    assert all(name in text for name in RECORD_FIELDS)
    assert "object at 0x" not in text


def test_index_by_model(check):
    assert check["ur5"] is check.comparisons[1]
    assert check["ur5"].model == "ur5"
    with pytest.raises(KeyError, match="failed"):
        check["no_such_model.xml"]
    with pytest.raises(KeyError, match=r"gimbal\.xml"):
        check["ur10"]


@pytest.mark.parametrize("source", ["mujoco", "pinocchio"])
@pytest.mark.parametrize("reference", ["mujoco", "pinocchio"])
def test_summary_by_model_and_formula(check, source, reference):
    found = check.summary("ur5", "koenig_world", source=source, reference=reference)
    expected = [
        s
        for s in check.summaries
        if (s.model, s.formula, s.source, s.reference) == ("ur5", "koenig_world", source, reference)
    ]
    assert len(expected) == 1 and found is expected[0]


def test_summary_defaults_and_misses(check):
    assert check.summary("ur5", "exact").source == check.summary("ur5", "exact").reference == "mujoco"
    with pytest.raises(KeyError, match="koenig_world"):
        check.summary("ur5", "koenig_wrld")


def test_to_pandas(check):
    pytest.importorskip("pandas")
    frame = check.to_pandas()
    assert len(frame) == len(check.summaries)
    row = frame[(frame.model == "gimbal.xml") & (frame.formula == "koenig_world") & (frame.source == "mujoco")]
    row = row[row.reference == "mujoco"]
    assert row.max_rel_error.item() == check.summary("gimbal.xml", "koenig_world").max_rel_error
