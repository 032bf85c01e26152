"""``koenig_check.compare(..., engines=...)``: each new engine named, an engine that cannot read the format, ``all``."""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check
from koenig_check.engines.registry import installed, label, optional
from koenig_check.findings import Kind
from named_engines import NEW_ENGINES, URDF_ONLY, installed_reading, named


@pytest.mark.parametrize("engine", [named(e) for e in NEW_ENGINES])
def test_compare_runs_a_named_engine_on_every_pose(engine: str) -> None:
    engines = ("mujoco", "pinocchio", engine)
    check = koenig_check.compare("serial7.urdf", n_poses=2, formulas=["exact"], engines=engines)
    comparison = check.comparisons[0]
    assert check.ok and comparison.engines == engines
    assert check.not_named == tuple(e for e in optional() if e != engine and installed(e))  # said once, for the run
    assert not [f for f in comparison.findings if f.kind is Kind.ENGINE_NOT_USED]  # nothing on the model


@pytest.mark.parametrize("engine", [named(e) for e in URDF_ONLY])
def test_an_engine_that_cannot_read_mjcf_fails_the_model_with_its_reason(engine: str) -> None:
    check = koenig_check.compare(
        "double_pendulum.xml", n_poses=2, formulas=["exact"], engines=f"mujoco,pinocchio,{engine}"
    )
    (unable,) = [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
    assert not check.ok and unable.engine == engine
    assert unable.summary.startswith(f"{label(engine)} asked for (--engines) but it could not check the model: ")
    assert f"{label(engine)} reads URDF only" in unable.summary  # the engine's own reason


def test_all_resolves_per_model_and_says_what_it_left_out() -> None:
    models = {"arm.xml": "serial7.xml", "arm.urdf": "serial7.urdf"}
    check = koenig_check.compare(models, n_poses=2, formulas=["exact"], engines="all")
    assert check.ok and check.not_named == ()
    by_model = {c.model: c for c in check.comparisons}
    for model, fmt in (("arm.xml", "mjcf"), ("arm.urdf", "urdf")):
        comparison = by_model[model]
        assert comparison.engines == installed_reading(fmt)
        left = {f.engine: dict(f.values) for f in comparison.findings if f.kind is Kind.ENGINE_NOT_USED}
        expected = {
            e: {"format": fmt, "reads": "urdf"} for e in installed_reading("urdf") if e not in installed_reading(fmt)
        }
        assert left == expected
        assert not [f for f in comparison.findings if f.kind is Kind.ENGINE_UNABLE]
    assert by_model["arm.xml"].engines != by_model["arm.urdf"].engines


@pytest.mark.parametrize("value", ["all", ("all",), ["ALL"], " all "])
def test_all_is_spelled_as_a_string_or_a_one_element_list(value: object) -> None:
    from koenig_check.engines.load_options import LoadOptions

    assert LoadOptions(engines=value).engines == ("all",)  # type: ignore[arg-type]


@pytest.mark.parametrize("value", [("all", "drake"), "mujoco,pinocchio,all", "everything"])
def test_all_in_a_list_or_a_misspelling_is_refused_before_any_model_loads(value: object) -> None:
    with pytest.raises(ValueError, match=r"engines: .*'all'"):
        koenig_check.compare("no_such_model_is_loaded.xml", engines=value)  # type: ignore[arg-type]


def test_the_export_proof_with_all_asks_for_every_engine_that_reads_both_files(tmp_path: Path) -> None:
    result = koenig_check.export("serial7.xml", to="urdf", out=tmp_path / "s.urdf", engines="all")
    mjcf = installed_reading("mjcf")
    assert result.equivalent and result.proof.asked == mjcf
    assert [e.engine for e in result.proof.engines if e.compared] == list(mjcf)
    left = [e for e in installed_reading("urdf") if e not in mjcf]
    assert result.proof.skipped() == [f"{e}: its parser does not read MJCF (--engines all)" for e in left]
