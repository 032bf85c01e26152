"""The cause of an engine's refusal, named from the file as written, whichever engine the catalogue says refuses."""

from __future__ import annotations

import pytest

import koenig_check
from koenig_check.engines.catalogue import catalogue, fixture_path, installed_version
from koenig_check.engines.refusals import file_signs, refusal_cause
from koenig_check.findings import Kind

#: Every (cause, engine) whose catalogue reading is "refuses" and whose construct has a declared sign in the file.
REFUSALS = [(c, r.engine) for c in catalogue() if c.id in file_signs() for r in c.readings if r.reads == "refuses"]
MIMIC_FIXED = "newton.urdf.mimic-fixed-joint"


def test_every_sign_belongs_to_a_cause_that_some_engine_refuses() -> None:
    refused = {c.id for c, _ in REFUSALS}
    assert set(file_signs()) == refused, "a sign no engine's refusal can use"
    assert "drake" in {e for c, e in REFUSALS if c.id == MIMIC_FIXED}, "Drake's refusal of a fixed mimic"


@pytest.mark.parametrize(("c", "engine"), REFUSALS, ids=[f"{c.id}-{e}" for c, e in REFUSALS])
def test_the_fixture_of_a_refused_construct_names_its_cause(c, engine: str) -> None:
    fixture = fixture_path(c)
    assert refusal_cause(engine, fixture, c.formats[0]) == c.id
    # The same file read as the other format, or by an engine that reads it as written, names nothing.
    other = "urdf" if c.formats[0] == "mjcf" else "mjcf"
    assert refusal_cause(engine, fixture, other) == ""
    assert refusal_cause("mujoco", fixture, c.formats[0]) == ""


@pytest.mark.parametrize("engine", ["newton", "drake"])
def test_a_file_without_the_construct_names_no_cause(engine: str) -> None:
    ur5 = koenig_check.engines.load_model("ur5").source.path
    assert refusal_cause(engine, ur5, "urdf") == ""
    assert refusal_cause(engine, "/nonexistent/robot.urdf", "urdf") == ""  # unreadable: the engines say why


@pytest.mark.skipif(installed_version("drake") is None, reason="Drake is in [test]; without it there is no refusal")
def test_drakes_refusal_of_a_fixed_mimic_carries_the_id_and_its_hint() -> None:
    fixture = fixture_path(next(c for c in catalogue() if c.id == MIMIC_FIXED))
    check = koenig_check.compare(str(fixture), engines=["mujoco", "pinocchio", "drake"], n_poses=5)
    findings = check.comparisons[0].findings
    refused = [f for f in findings if f.kind is Kind.ENGINE_NOT_USED and f.engine == "drake"]
    unable = [f for f in findings if f.kind is Kind.ENGINE_UNABLE and f.engine == "drake"]
    assert [f.cause for f in refused] == [MIMIC_FIXED]  # the id once, on the refusal (the check not made: no id)
    assert len(unable) == 1 and unable[0].hint.startswith("remove the <mimic> from the fixed joint")
    assert not check.ok


def test_a_file_with_two_refused_constructs_names_the_one_the_engine_meets_first(tmp_path) -> None:
    """Newton reads ``<option>`` before the geoms: a box by ``fromto`` under ``solver="PGS"`` stops at the solver."""
    box = next(c for c in catalogue() if c.id == "newton.mjcf.box-fromto")
    text = fixture_path(box).read_text(encoding="utf-8")
    both = tmp_path / "both.xml"
    both.write_text(text.replace("<worldbody>", '<option solver="PGS"/>\n  <worldbody>', 1), encoding="utf-8")
    assert 'solver="PGS"' in both.read_text(encoding="utf-8")
    assert refusal_cause("newton", both, "mjcf") == "newton.mjcf.solver-pgs"
    assert refusal_cause("newton", fixture_path(box), "mjcf") == box.id


def test_a_sign_of_a_cause_the_catalogue_lacks_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    from koenig_check.engines.newton import causes

    monkeypatch.setattr(causes, "FILE_SIGNS", {**causes.FILE_SIGNS, "newton.urdf.no-such-cause": lambda root: True})
    with pytest.raises(ValueError, match=r"newton\.causes\.FILE_SIGNS names causes .*: newton\.urdf\.no-such-cause"):
        file_signs()
