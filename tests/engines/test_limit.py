"""A parser limit (engines/limit.py) matches an engine's finding by the cause id it carries or by its kind and a
test on its values, never by its text; Drake's limits are declared in its subpackage."""

from __future__ import annotations

import pytest

from koenig_check.engines.limit import ParserLimit, limits, none_where_reference_has
from koenig_check.findings import Finding, Kind


def _armature(values: dict, cause: str = "") -> Finding:
    return Finding(Kind.ARMATURE, "drake", "joint spin", "any words at all", values, cause=cause)


def test_a_limit_declares_what_shows_it() -> None:
    with pytest.raises(ValueError, match="declare the kind or the cause"):
        ParserLimit("ignores armature")


def test_by_kind_and_values_whatever_the_words() -> None:
    limit = ParserLimit("ignores armature", kind=Kind.ARMATURE, when=none_where_reference_has)
    assert limit.shown_by(_armature({"drake": [0.0], "mujoco": [0.05]}), None)
    assert not limit.shown_by(_armature({"drake": [0.05], "mujoco": [0.0]}), None)  # it reads more: a departure
    assert not limit.shown_by(_armature({"drake": [0.0]}), None)  # no reference value: nothing known
    other = Finding(Kind.ANCHOR, "drake", "joint spin", "x", {"drake": [0.0], "mujoco": [0.05]})
    assert not limit.shown_by(other, None)


def test_by_the_cause_id_it_carries() -> None:
    limit = ParserLimit("ignores armature", cause="pinocchio.mjcf.class-geom-mass")
    carried = Finding(Kind.MASS, "pinocchio", "body b", "x", cause="pinocchio.mjcf.class-geom-mass")
    assert limit.shown_by(carried, None)
    assert not limit.shown_by(Finding(Kind.MASS, "pinocchio", "body b", "x"), None)


def test_drake_declares_its_limits_and_the_others_none() -> None:
    pytest.importorskip("pydrake")
    says = {limit.says for limit in limits("drake")}
    assert says == {
        "drops the pos of multi-joint bodies",
        "ignores armature",
        "replaces inertias it judges unphysical",
    }
    assert limits("mujoco") == () and limits("pinocchio") == ()
