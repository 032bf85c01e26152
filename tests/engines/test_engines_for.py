"""Which engines read a format (``registry.reading``), and what ``--engines all`` resolves to per model."""

from __future__ import annotations

import pytest

from koenig_check.engines import load_model
from koenig_check.engines.load_options import LoadOptions, parse_engines
from koenig_check.engines.registry import engines_for, installed, reading
from koenig_check.findings import Kind
from named_engines import READS, installed_reading


@pytest.mark.parametrize("fmt", ["mjcf", "urdf"])
def test_reading_lists_the_engines_whose_parser_reads_the_format(fmt: str) -> None:
    assert reading(fmt) == READS[fmt]
    assert reading(fmt, installed_only=True) == installed_reading(fmt)


@pytest.mark.parametrize("fmt", ["mjcf", "urdf"])
def test_all_resolves_to_the_installed_engines_that_read_the_format(fmt: str) -> None:
    engines, left_out = engines_for(("all",), fmt)
    assert engines == installed_reading(fmt)
    assert [f.engine for f in left_out] == [e for e in installed_reading("urdf") if e not in READS[fmt]]
    assert all(f.kind is Kind.ENGINE_NOT_USED and f.values["format"] == fmt for f in left_out)


@pytest.mark.parametrize("engines", [None, ("mujoco", "pinocchio"), ("mujoco", "pinocchio", "drake")])
def test_a_named_list_or_the_default_is_left_as_it_is(engines: tuple[str, ...] | None) -> None:
    assert engines_for(engines, "mjcf") == (engines, [])


@pytest.mark.parametrize(("model", "fmt"), [("gimbal.xml", "mjcf"), ("gimbal.urdf", "urdf")])
def test_a_model_loaded_with_all_carries_its_formats_engines(model: str, fmt: str) -> None:
    pair = load_model(model, LoadOptions(engines="all"), check=False)
    assert pair.options.engines == installed_reading(fmt)
    left = [f.engine for f in pair.optional_findings if f.kind is Kind.ENGINE_NOT_USED]
    assert left == [e for e in installed_reading("urdf") if e not in READS[fmt]]
    assert not [f for f in pair.findings if f.kind is Kind.ENGINE_NOT_USED]  # said once, with the engines'


@pytest.mark.parametrize("text", ["all", "ALL", " all ", "all,"])
def test_all_is_read_alone(text: str) -> None:
    assert parse_engines(text) == ("all",)


@pytest.mark.parametrize("text", ["all,drake", "mujoco,pinocchio,all", "all,all"])
def test_all_in_a_list_is_refused(text: str) -> None:
    with pytest.raises(ValueError, match="'all' stands alone"):
        parse_engines(text)


def test_installed_reading_is_what_the_registry_finds_installed() -> None:
    assert all(installed(e) for e in installed_reading("urdf"))
