"""The finding record: validated at construction, rendered on one line, complete in JSON."""

from __future__ import annotations

import pytest

from koenig_check.findings import Finding, Kind, root_causes

GEOMS = tuple(f"g{i}" for i in range(85))


def test_message_names_engine_element_summary_values_and_hint() -> None:
    f = Finding(Kind.MASS, "pinocchio", "geom pole", "mass from class not applied", {"mujoco": 0.1}, hint="do X")
    assert f.message() == "pinocchio: geom pole: mass from class not applied (mujoco 0.1); do X"


def test_round_off_values_print_as_zero_and_stay_whole_in_json() -> None:
    import numpy as np

    f = Finding(Kind.MASS, "both", "body arm", "gap", {"rel": -3.3e-17, "np": np.float64(2e-13), "kg": 1.5e-12})
    assert f.message() == "both: body arm: gap (rel 0, np 0, kg 1.5e-12)"
    assert f.as_dict()["values"]["rel"] == -3.3e-17


def test_long_sequences_are_shown_by_their_first_items_and_a_count_but_kept_whole() -> None:
    f = Finding(Kind.MASS, "pinocchio", "geom g0", "meshes", {"geoms": GEOMS, "mujoco": 1552.71})
    assert f.message() == "pinocchio: geom g0: meshes (geoms g0, g1, g2, g3 (+81 more), mujoco 1552.71)"
    assert f.as_dict()["values"]["geoms"] == list(GEOMS)
    short = Finding(Kind.MASS, "pinocchio", "geom g0", "meshes", {"geoms": GEOMS[:6]})
    assert "more" not in short.message() and "g4, g5)" in short.message() and "'" not in short.message()


@pytest.mark.parametrize(
    ("kwargs", "error"),
    [
        ({"engine": "bullet"}, "engine must be one of"),
        ({"element": ""}, "needs an element"),
        ({"summary": ""}, "needs an element and a summary"),
        ({"kind": "no_such_kind"}, "is not a valid Kind"),
    ],
)
def test_invalid_records_are_refused(kwargs, error) -> None:
    base = {"kind": Kind.MASS, "engine": "mujoco", "element": "body b", "summary": "s"}
    with pytest.raises(ValueError, match=error):
        Finding(**{**base, **kwargs})


def test_records_are_read_only() -> None:
    f = Finding(Kind.MASS, "mujoco", "body b", "s", {"a": 1})
    with pytest.raises(TypeError):
        f.values["a"] = 2  # type: ignore[index]


def test_root_causes_that_change_the_energy_come_first() -> None:
    note = Finding(Kind.FRAME, "pinocchio", "body base", "pose dropped", root_cause=True)
    mass = Finding(Kind.MASS, "pinocchio", "geom pole", "mass", affects_energy=True, root_cause=True)
    symptom = Finding(Kind.MASS, "both", "segment s", "mass differs", affects_energy=True)
    assert root_causes([note, symptom, mass]) == [mass, note]
