"""Another engine's catalogued reading acted on: a cause found on the file that an attached engine misreads too.

Each case runs the tool on a fixture with Drake attached and asserts Drake's finding carries the cause's id and
that Drake abstains (no verdict; asked for, an ``ENGINE_UNABLE`` naming the cause and its quantities).  That the
declared reading is true in the installed Drake is re-measured by ``tests/causes/test_cause_catalogue.py``.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

import koenig_check
from koenig_check.causes import catalogue, cause, fixture_path
from koenig_check.engines.cross_readings import cross_readings
from koenig_check.findings import Finding, Kind

pytest.importorskip("pydrake")
ALL = ("mujoco", "pinocchio", "drake")

#: (cause whose fixture is compared, the id Drake's finding carries)
ABSTAINS = [
    ("pinocchio.mjcf.settotalmass", "pinocchio.mjcf.settotalmass"),
    ("pinocchio.mjcf.inertiagrouprange", "pinocchio.mjcf.inertiagrouprange"),
    ("drake.mjcf.inline-mesh", "drake.mjcf.inline-mesh"),
]

#: <replicate> holding geoms only: Pinocchio and Drake load the file without them, the model is compared.
REPLICATED_GEOMS = """<mujoco model="replicated_geoms">
  <worldbody>
    <body name="a"><joint name="j1" axis="0 1 0"/><geom type="box" size="0.1 0.2 0.3" pos="0.3 0 0"/>
      <replicate count="3" offset="0.5 0 0"><geom type="sphere" size="0.1" pos="0 0 -1"/></replicate>
    </body>
  </worldbody>
</mujoco>
"""


def _drake_findings(check: koenig_check.api.CrossCheck) -> tuple[list[Finding], list[Finding]]:
    findings = check.comparisons[0].findings
    verdicts = [f for f in findings if f.kind is Kind.VERDICT]
    return [f for f in findings if f.engine == "drake"], verdicts


@pytest.mark.parametrize(("fixture_of", "cause_id"), ABSTAINS)
def test_drake_is_named_with_the_cause_and_abstains(fixture_of: str, cause_id: str) -> None:
    check = koenig_check.compare(str(fixture_path(cause(fixture_of))), n_poses=3, formulas=["exact"], engines=ALL)
    drake, verdicts = _drake_findings(check)
    assert not verdicts, [v.message() for v in verdicts]
    (named,) = [f for f in drake if f.cause == cause_id]
    assert named.root_cause and named.affects_energy
    (unable,) = [f for f in drake if f.kind is Kind.ENGINE_UNABLE]
    assert cause_id in unable.values["causes"]
    assert set(cause(cause_id).quantities) <= set(unable.values["quantities"])


def test_replicate_in_drake_on_its_fixture_and_on_a_file_that_loads(tmp_path: Path) -> None:
    """The fixture's copies hold joints: Pinocchio fails on it, and the failure names Drake's reading too; copies of
    geoms only: the model is compared and Drake, which skips them too, abstains."""
    c = cause("pinocchio.mjcf.replicate")
    failed = koenig_check.compare(str(fixture_path(c)), n_poses=2, engines=ALL)
    (causes,) = failed.failure_causes.values()
    assert {(f.engine, f.cause) for f in causes} == {("pinocchio", c.id), ("drake", c.id)}
    alone = koenig_check.compare(str(fixture_path(c)), n_poses=2)  # Drake not asked for: its reading not said
    assert {f.engine for causes in alone.failure_causes.values() for f in causes} == {"pinocchio"}
    path = tmp_path / "replicated_geoms.xml"
    path.write_text(REPLICATED_GEOMS)
    check = koenig_check.compare(str(path), n_poses=3, formulas=["exact"], engines=ALL)
    drake, verdicts = _drake_findings(check)
    assert not verdicts, [v.message() for v in verdicts]
    assert [f.cause for f in drake if f.root_cause] == [c.id]
    (unable,) = [f for f in drake if f.kind is Kind.ENGINE_UNABLE]
    assert unable.values["causes"] == (c.id,)


def test_a_mesh_file_drake_reads_as_written_keeps_its_vote() -> None:
    """pinocchio.mjcf.mesh-mass on a mesh file: Drake reads it as MuJoCo does, votes, and Pinocchio departs."""
    c = cause("pinocchio.mjcf.mesh-mass")
    check = koenig_check.compare(str(fixture_path(c)), n_poses=3, formulas=["exact"], engines=ALL)
    drake, verdicts = _drake_findings(check)
    assert not [f for f in drake if f.cause or f.kind is Kind.ENGINE_UNABLE]
    assert verdicts and {v.engine for v in verdicts} == {"pinocchio"}


def test_a_reading_declared_for_other_drake_versions_is_not_acted_on(monkeypatch: pytest.MonkeyPatch) -> None:
    from koenig_check.engines import catalogue as module
    from koenig_check.engines.catalogue import installed_version

    c = cause("pinocchio.mjcf.settotalmass")
    version = installed_version("drake")
    assert version is not None
    older = tuple(dataclasses.replace(r, versions=f"<{version}") if r.engine == "drake" else r for r in c.readings)
    changed = dataclasses.replace(c, readings=older)
    every = catalogue()
    monkeypatch.setattr(module, "catalogue", lambda: tuple(changed if x.id == c.id else x for x in every))
    check = koenig_check.compare(str(fixture_path(c)), n_poses=3, formulas=["exact"], engines=ALL)
    drake, verdicts = _drake_findings(check)
    assert not [f for f in drake if f.cause == c.id or f.kind is Kind.ENGINE_UNABLE]
    assert verdicts  # Drake votes again (it agrees with Pinocchio: MuJoCo departs)


def test_only_attached_optional_engines_misreading_it_get_a_finding() -> None:
    found = Finding(
        Kind.COMPILER,
        "mujoco",
        "compiler settotalmass",
        "rescaled",
        {"mujoco": 5.0, "pinocchio": 48.0},
        affects_energy=True,
        root_cause=True,
        segments=("spin",),
        cause="pinocchio.mjcf.settotalmass",
        tag="compiler",
    )
    (drake,) = cross_readings([found], ["mujoco", "pinocchio", "drake"], "mjcf")
    assert (drake.engine, drake.cause, drake.segments, dict(drake.values)) == ("drake", found.cause, ("spin",), {})
    assert cross_readings([found], ["mujoco", "pinocchio"], "mjcf") == []  # Drake not attached
    assert cross_readings([found], ["drake"], "urdf") == []  # a cause of another format
    assert cross_readings([found, drake], ["drake"], "mjcf") == []  # Drake's own finding already there
    assert cross_readings([dataclasses.replace(found, root_cause=False)], ["drake"], "mjcf") == []
    second = dataclasses.replace(found, element="compiler settotalmass2")  # the same cause on two elements
    assert [f.element for f in cross_readings([found, second], ["drake"], "mjcf")] == [found.element, second.element]
