"""The catalogue: ids unique, fixtures shipped, each engine's declared reading re-measured on the fixture."""

from __future__ import annotations

import importlib
import importlib.util
import json
from pathlib import Path

import pytest

from koenig_check.causes import applies, catalogue, cause, fixture_path, installed_version, markdown, twin_path
from koenig_check.cli import main
from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement, differences, fields
from koenig_check.engines.specs import names, reference, spec

ROOT = Path(__file__).resolve().parents[2]
CAUSES = catalogue()


def _installed(engine: str) -> bool:
    return importlib.util.find_spec(spec(engine).module) is not None


def _measure(engine: str, path: Path) -> Measurement:
    return importlib.import_module(f"koenig_check.engines.{engine}.causes").measure(path)


def test_ids_are_unique_and_each_cause_is_declared_by_its_engine() -> None:
    ids = [c.id for c in CAUSES]
    assert len(ids) == len(set(ids))
    assert CAUSES, "the catalogue is empty"
    for c in CAUSES:
        assert c.engine in names()
        assert cause(c.id) is c


def test_an_unknown_id_names_the_closest() -> None:
    with pytest.raises(KeyError, match=r"did you mean pinocchio\.mjcf\.class-geom-mass"):
        cause("pinocchio.mjcf.class-geom-mas")


@pytest.mark.parametrize("c", CAUSES, ids=lambda c: c.id)
def test_fixture_is_shipped_and_named(c: Cause) -> None:
    path = fixture_path(c)
    assert path.is_file(), f"{c.id}: fixture {c.fixture} missing from koenig_check/causes/fixtures/"
    text = path.read_text()
    if path.suffix == ".xml":
        assert "<mujoco model=" in text, f"{c.id}: give the fixture a model name (Drake refuses it otherwise)"


READINGS = [(c, r) for c in CAUSES for r in c.readings]


@pytest.mark.parametrize(("c", "reading"), READINGS, ids=[f"{c.id}-{r.engine}" for c, r in READINGS])
def test_each_engine_reads_the_fixture_as_declared(c: Cause, reading: Reading) -> None:
    """The catalogue's claim, re-measured in the installed engine against an engine that reads it as written."""
    if not _installed(reading.engine):
        pytest.skip(f"{reading.engine} is not installed")
    version = installed_version(reading.engine)
    where = f"{c.id}: {spec(reading.engine).label} {version}"
    if not applies(c.id, reading.engine):
        pytest.skip(f"{where}: the declared reading holds for versions {reading.versions} only")
    path = fixture_path(c)
    if reading.reads == "refuses":
        with pytest.raises(Exception):  # noqa: B017 (each engine refuses with its own exception type)
            _measure(reading.engine, path)
        return
    refs = [
        r.engine for r in c.readings if r.reads == "as written" and r.engine != reading.engine and _installed(r.engine)
    ]
    if not refs and c.twin:  # the one engine that reads it as written: checked against the twin instead
        _check_against_the_twin(c, reading, where)
        return
    if not refs:
        pytest.skip(f"{where}: no installed engine reads it as written")
    ref = refs[0]
    measured = _measure(reading.engine, path)
    rtol = max(spec(reading.engine).precision, spec(ref).precision, 1e-9)
    differ = differences(measured, _measure(ref, path), rtol) & fields(c.quantities)
    if reading.reads == "differently":
        assert differ, f"{where} now reads the fixture as {spec(ref).label} does: the cause no longer applies"
        if reading.engine == c.engine and not c.loses_joints:  # other joint names alone: another coordinate choice
            assert differ - {"joints"}, f"{where} departs from {spec(ref).label} in joint names only, not the robot"
    else:
        assert not differ, f"{where} now departs from {spec(ref).label} in {sorted(differ)}"


TWINNED = [c for c in CAUSES if c.twin]


def _twin_readers(c: Cause) -> list[str]:
    """The installed engines of the cause's readings, but those that depart on a cause its twin is subject to."""
    departs = {r.engine for t in c.twin_causes for r in cause(t).readings if r.reads != "as written"}
    return [r.engine for r in c.readings if _installed(r.engine) and r.engine not in departs]


def _rtol(*engines: str) -> float:
    return max([spec(e).precision for e in engines] + [1e-9])


def _same_robot(a: Measurement, b: Measurement, rtol: float) -> set[str]:
    """Where two readings of one robot differ: joint names alone do not count when the whole M's spectrum agrees
    (Pinocchio composes one body's joints into one, named after the first: another coordinate choice)."""
    differ = differences(a, b, rtol)
    return differ - {"joints"} if a.spectrum and b.spectrum and "spectrum" not in differ else differ


def _check_against_the_twin(c: Cause, reading: Reading, where: str) -> None:
    """An engine's reading of the fixture against every installed engine's reading of the twin (its own included):
    the same robot where it reads the fixture as written, another in the cause's quantities where differently."""
    twin = twin_path(c)
    assert twin is not None
    measured = _measure(reading.engine, fixture_path(c))
    for engine in _twin_readers(c):
        rtol = _rtol(reading.engine, engine)
        theirs = _measure(engine, twin)
        if reading.reads == "as written":
            differ = _same_robot(measured, theirs, rtol)
            assert not differ, f"{where} departs from {spec(engine).label}'s reading of the twin in {sorted(differ)}"
            continue
        differ = differences(measured, theirs, rtol) & fields(c.quantities)
        assert differ, f"{where} reads the fixture as {spec(engine).label} reads the twin: the cause no longer applies"
        if reading.engine == c.engine and not c.loses_joints:
            assert differ - {"joints"}, f"{where} departs from the twin in joint names only, not the robot"


def test_twin_causes_name_declared_causes() -> None:
    """A twin subject to a cause names it by id; an id the catalogue lacks is refused when the catalogue is built."""
    from koenig_check.engines import catalogue as module

    for c in TWINNED:
        assert all(cause(t).id == t for t in c.twin_causes)
    bad = Cause(
        "mujoco.mjcf.x",
        "c",
        ("mjcf",),
        (Reading("mujoco", "refuses", "x"),),
        ("mass",),
        "b",
        "",
        "f.xml",
        twin="t.xml",
        twin_causes=("pinocchio.mjcf.no-such-cause",),
    )
    fake = type("M", (), {"CAUSES": (bad,)})
    real = importlib.import_module
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(
            module.importlib, "import_module", lambda name: fake if name.endswith("mujoco.causes") else real(name)
        )
        with pytest.raises(ValueError, match=r"twin_causes name unknown causes: pinocchio\.mjcf\.no-such-cause"):
            module._collected.__wrapped__(module.specs())


@pytest.mark.parametrize("c", TWINNED, ids=lambda c: c.id)
def test_the_twin_is_the_robot_as_written(c: Cause) -> None:
    """The twin is plain: the engines that read it agree on it; those that read the fixture as written read the robot
    of the twin, those that read it differently depart from it in the cause's quantities (from the robot as
    written, not from one engine's reading)."""
    twin = twin_path(c)
    assert twin is not None and twin.is_file(), f"{c.id}: twin {c.twin} missing from koenig_check/causes/fixtures/"
    readers = _twin_readers(c)
    if len(readers) < 2:
        pytest.skip(f"{c.id}: fewer than two installed engines read the twin {c.twin}")
    readings = {e: _measure(e, twin) for e in readers}
    first = readers[0]
    for engine in readers[1:]:
        differ = _same_robot(readings[first], readings[engine], _rtol(first, engine))
        assert not differ, (
            f"{c.id}: {spec(engine).label} and {spec(first).label} read the twin apart in {sorted(differ)}"
        )
    for r in c.readings:
        if r.reads != "refuses" and _installed(r.engine) and applies(c.id, r.engine):
            _check_against_the_twin(c, r, f"{c.id}: {spec(r.engine).label} {installed_version(r.engine)}")


@pytest.mark.parametrize("c", CAUSES, ids=lambda c: c.id)
def test_the_tool_names_the_cause_on_its_fixture(c: Cause) -> None:
    """Compared in every installed engine that reads the fixture, the finding carries the cause's id."""
    import koenig_check

    if not _installed(c.engine):
        pytest.skip(f"{c.engine} is not installed")
    engines = [r.engine for r in c.readings if _installed(r.engine)]
    refused = any(r.engine == reference() and r.reads == "refuses" for r in c.readings)  # its hint: --repair-inertia
    check = koenig_check.compare(str(fixture_path(c)), n_poses=4, engines=engines, repair_inertia=refused)
    found = {f.cause for comp in check.comparisons for f in comp.findings}
    found |= {f.cause for causes in check.failure_causes.values() for f in causes}  # joints lost: not compared
    assert c.id in found, f"{c.id} not named on its fixture (named: {sorted(found - {''})})"


def test_the_documentation_page_is_current() -> None:
    page = ROOT / "docs" / "causes.md"
    assert page.read_text() == markdown(), "docs/causes.md is stale: python -m koenig_check.causes > docs/causes.md"


def test_causes_json_lists_every_cause(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["causes", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert [c["id"] for c in listed] == [c.id for c in CAUSES]
    for entry in listed:
        assert {"id", "engines", "formats", "summary", "fixture", "twin", "twin_causes"} <= set(entry)
        assert entry["engines"][entry["id"].split(".")[0]]["reads"] in ("differently", "refuses")


def test_causes_filters_by_engine_and_format(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["causes", "--engine", "pinocchio", "--format", "urdf", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert all("urdf" in c["formats"] and "pinocchio" in c["engines"] for c in listed)
    assert main(["causes", "--format", "mjcf"]) == 0
    text = capsys.readouterr().out
    assert "pinocchio.mjcf.class-geom-mass" in text and "fixture: class_geom_mass.xml" in text


def test_a_misdeclared_cause_is_refused() -> None:
    with pytest.raises(ValueError, match="must read it differently"):
        Cause("mujoco.mjcf.x", "c", ("mjcf",), (Reading("mujoco", "as written"),), ("mass",), "b", "", "f.xml")
    with pytest.raises(ValueError, match="expected <engine>"):
        Cause("Bad Id", "c", ("mjcf",), (Reading("mujoco", "refuses", "x"),), ("mass",), "b", "", "f.xml")
    with pytest.raises(ValueError, match="without a twin"):
        Cause(
            "mujoco.mjcf.x",
            "c",
            ("mjcf",),
            (Reading("mujoco", "refuses", "x"),),
            ("mass",),
            "b",
            "",
            "f.xml",
            twin_causes=("pinocchio.mjcf.option-gravity",),
        )


def test_a_cause_fires_only_for_the_engine_versions_it_declares(monkeypatch: pytest.MonkeyPatch) -> None:
    """A release of Pinocchio outside the declared versions: the cause is not named (its reading says nothing)."""
    import dataclasses

    import koenig_check
    from koenig_check.engines import catalogue as module

    c = cause("pinocchio.mjcf.class-geom-mass")
    version = installed_version("pinocchio")
    assert version is not None
    older = tuple(dataclasses.replace(r, versions=f"<{version}") if r.engine == "pinocchio" else r for r in c.readings)
    changed = dataclasses.replace(c, readings=older)
    monkeypatch.setattr(module, "catalogue", lambda: tuple(changed if x.id == c.id else x for x in CAUSES))
    assert not applies(c.id)
    check = koenig_check.compare(str(fixture_path(c)), n_poses=4, engines=["mujoco", "pinocchio"])
    assert c.id not in {f.cause for comp in check.comparisons for f in comp.findings}
