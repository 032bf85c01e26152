"""Drake as tie-breaker: which engine departs, the construct responsible, and when Drake is (not) used."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.diagnosis.reason import REASON_WIDTH
from koenig_check.engines.errors import EngineUnavailableError
from koenig_check.findings import Kind
from koenig_check.testing import assert_energy_parity

HERE = Path(__file__).resolve().parents[1]
TIEBREAK = HERE / "models" / "tiebreak"
HAS_DRAKE = importlib.util.find_spec("pydrake") is not None
needs_drake = pytest.mark.skipif(not HAS_DRAKE, reason="Drake (the optional extra [drake]) is not installed")
ALL = ("mujoco", "pinocchio", "drake")

#: (file, engines, quantity, engine that departs, construct named)
WHO_DEPARTS = [
    (HERE / "models" / "causes" / "class_mass.xml", None, "rigid-body energy", "pinocchio", "geom pole"),
    (TIEBREAK / "rotor_inertia.urdf", ALL, "armature energy", "drake", "actuators of joints spin"),
]
#: Files whose settotalmass Drake ignores as Pinocchio does (the catalogue's reading): Drake abstains, no verdict.
SETTOTALMASS = [
    TIEBREAK / "settotalmass.xml",
    TIEBREAK / "settotalmass_inertiafromgeom.xml",
    TIEBREAK / "all_differ.xml",
]


def _verdicts(check: koenig_check.api.CrossCheck) -> list:
    return [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]


@needs_drake
@pytest.mark.parametrize(("path", "engines", "quantity", "engine", "construct"), WHO_DEPARTS, ids=lambda x: str(x))
def test_the_engine_that_departs_is_named_with_its_construct(path, engines, quantity, engine, construct) -> None:
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"], engines=engines)
    verdict = {f.element: f for f in _verdicts(check)}[quantity]
    assert verdict.engine == engine
    if construct is None:
        assert verdict.summary.startswith("all three engines differ")
    else:
        assert f"construct responsible: {construct}" in verdict.summary
    assert not check.ok
    departs = verdict.summary.split("; ")[0].split(" (")[0]  # "MuJoCo departs", "all three engines differ"
    assert check.reason().startswith(f"{path.name}: {departs}")  # the reason leads with it
    assert f"three engines: {verdict.message()}" in check.comparisons[0].notes  # whole in summary.md, the report
    assert "\n" not in check.reason()


@needs_drake
@pytest.mark.parametrize("path", SETTOTALMASS, ids=lambda p: p.name)
@pytest.mark.parametrize("engines", [None, ALL], ids=["tie-breaker", "asked"])
def test_an_engine_that_misreads_the_option_too_is_named_and_abstains(path: Path, engines) -> None:
    """settotalmass, which the catalogue says Drake ignores as Pinocchio does: Drake's finding carries the id and
    Drake casts no vote (formerly "MuJoCo departs (Pinocchio and Drake agree)", two engines sharing one misreading
    taken for a majority); asked for, it could not check the model, and says which cause and quantities."""
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=engines)
    findings = check.comparisons[0].findings
    assert not [f.message() for f in findings if f.kind is Kind.VERDICT]
    (drake,) = [f for f in findings if f.engine == "drake" and f.cause == "pinocchio.mjcf.settotalmass"]
    assert drake.root_cause and drake.affects_energy and drake.element == "compiler settotalmass"
    unable = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    if engines is None:  # consulted as tie-breaker only: no check was asked of it
        assert not unable
    else:
        (one,) = unable
        assert one.engine == "drake" and "pinocchio.mjcf.settotalmass" in one.values["causes"]
        assert {"mass", "inertia"} <= set(one.values["quantities"])
    assert check.reason().startswith(f"{path.name}: root cause: compiler settotalmass")


@needs_drake
def test_import_verdict_per_segment_names_the_segment() -> None:
    check = koenig_check.compare(HERE / "models" / "causes" / "class_mass.xml", n_poses=2, formulas=["exact"])
    mass = [f for f in _verdicts(check) if f.element == "body pole (joint hinge) mass"]
    assert [f.engine for f in mass] == ["pinocchio"]
    assert mass[0].values["mujoco"] == pytest.approx(0.1) and mass[0].values["drake"] == pytest.approx(0.1)
    assert mass[0].segments == ("hinge",)
    moments = [f for f in _verdicts(check) if f.element == "body pole (joint hinge) principal moments"]
    assert [f.engine for f in moments] == ["pinocchio"]
    assert moments[0].values["mujoco"] == pytest.approx(moments[0].values["drake"], rel=1e-12)


@needs_drake
def test_agreeing_models_do_not_load_drake_by_default() -> None:
    check = koenig_check.compare("gimbal.xml", n_poses=2, formulas=["exact"])
    assert set(check.comparisons[0].engines) == {"mujoco", "pinocchio"}
    assert any(
        f.kind is Kind.ENGINE_NOT_USED and f.summary.startswith("Drake not used: not needed")
        for f in check.comparisons[0].findings
    )
    asked = koenig_check.compare("gimbal.xml", n_poses=2, formulas=["exact"], engines=ALL)
    assert set(asked.comparisons[0].engines) == set(ALL)
    assert asked.ok and not _verdicts(asked)


@needs_drake
def test_assert_energy_parity_leads_with_the_root_cause_then_the_departing_engine() -> None:
    with pytest.raises(AssertionError) as info:
        assert_energy_parity(TIEBREAK / "settotalmass.xml", n_poses=3)
    text = " ".join(str(info.value).split())  # folded lines joined
    assert "energy parity fails (rtol 1e-09): root cause: pinocchio: compiler settotalmass" in text  # first
    assert "three engines:" not in text  # Drake ignores settotalmass too: no vote (no "MuJoCo departs")
    with pytest.raises(AssertionError, match="Drake cannot check this model: its MJCF parser ignores armature"):
        assert_energy_parity(HERE / "engines" / "models" / "hinge_armature.xml", n_poses=3, engines=ALL)
    assert_energy_parity("gimbal.urdf", n_poses=3, engines=ALL)


@needs_drake
def test_cli_engines_option_on_compare_and_parity(capsys: pytest.CaptureFixture[str]) -> None:
    assert (
        main(["compare", "gimbal.xml", "--poses", "2", "--formulas", "exact", "--engines", "mujoco,pinocchio,drake"])
        == 0
    )
    assert main(["parity", str(TIEBREAK / "settotalmass.xml")]) == 1
    out, err = capsys.readouterr()
    assert "three engines:" not in out and "departs" not in err  # Drake ignores settotalmass too: no vote
    assert err.startswith("koenig-check: settotalmass.xml: root cause: compiler settotalmass")
    assert len(err.splitlines()) == 1 and len(err.rstrip("\n")) <= 200


@needs_drake
@pytest.mark.parametrize(
    ("model", "text"),
    [
        (
            "talos",
            "talos_reduced.urdf: Drake cannot load the file: line 1386: Joint 'gripper_left_inner_double_joint' "
            "which has 0 DOF cannot mimic joint 'gripper_left_joint' which has 1 DOF.",
        ),
    ],
)
def test_drake_refusal_reaches_the_user_whole_on_one_line(model: str, text: str) -> None:
    from koenig_check.engines import load_model
    from koenig_check.engines.drake.building import load_drake_engine
    from koenig_check.engines.drake.loader import DrakeLoadError

    pair = load_model(model, check=False)
    with pytest.raises(DrakeLoadError) as info:
        load_drake_engine(pair.source, pair.mujoco.model)
    message = str(info.value)
    assert "\n" not in message and message.startswith(str(pair.source.path)) and message.endswith(text)
    reason = message.removeprefix(f"{pair.source.path}: ")  # the model's row and label name the file already
    check = koenig_check.compare(model, n_poses=1, formulas=["exact"], engines=ALL)
    findings = check.comparisons[0].findings
    found = [f.summary for f in findings if f.kind is Kind.ENGINE_NOT_USED and f.engine == "drake"]
    assert found == [f"Drake not used: {reason}"]  # the other optional engines: "not asked for"
    # Drake was asked for and could not check the model: the check asked for was not made, and says why: whole
    # in its finding (the verdict table's row), and first in the one-line reason, cut to fit its line.
    (unable,) = [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
    assert unable.summary.endswith(reason)
    line = check.reason()
    assert not check.ok and len(line) <= REASON_WIDTH
    assert line.removesuffix("…") in f"{check.comparisons[0].model}: {unable.summary}"


@needs_drake
def test_drake_limits_are_findings_naming_the_element() -> None:
    from koenig_check.engines.drake.loader import load_drake
    from koenig_check.sources.catalogue import resolve_model

    _, findings = load_drake(resolve_model("anymal_b_simple/anymal"))
    negative = [f for f in findings if "negative" in f.summary]
    assert [f.element for f in negative] == ["link base"] and "\n" not in negative[0].message()
    _, findings = load_drake(resolve_model(HERE / "models" / "causes" / "class_mass.xml"))
    assert [f.element for f in findings if "model name" in f.summary] == ["mujoco model"]
    check = koenig_check.compare(HERE / "engines" / "models" / "hinge_armature.xml", n_poses=1, engines=ALL)
    armature = [f for f in check.comparisons[0].findings if f.kind is Kind.IGNORED_CONSTRUCT and f.engine == "drake"]
    assert armature and armature[0].values["joints"] == ["spin"]
    plant, findings = load_drake(resolve_model("gimbal.urdf"))  # Drake alone would float the root link (nq 9)
    assert plant.num_positions() == 2
    assert [f.element for f in findings if "welded" in f.summary] == ["links base"]


def test_without_drake_two_engines_and_the_report_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    import koenig_check.engines.registry as registry

    monkeypatch.setattr(registry, "installed", lambda name: name != "drake")
    check = koenig_check.compare(HERE / "models" / "causes" / "class_mass.xml", n_poses=2, formulas=["exact"])
    assert set(check.comparisons[0].engines) == {"mujoco", "pinocchio"}
    assert any("Drake not used: not installed" in note for note in check.comparisons[0].notes)
    with pytest.raises(EngineUnavailableError, match="pydrake is not installed"):
        koenig_check.compare("gimbal.xml", engines=ALL)
    with pytest.raises(SystemExit) as usage:  # a usage error, before any work (like argparse's)
        main(["compare", "gimbal.xml", "--engines", "mujoco,pinocchio,drake"])
    assert usage.value.code == 2


def test_drake_reason_is_one_line_without_repeating_the_path() -> None:
    from koenig_check.engines.drake.loader import one_line_reason

    path = Path("/models/robot.urdf")
    text = f"{path}:12: error: first line\n  second line\n\n{path}:14: error: ERROR: third"
    assert one_line_reason(text, path) == "line 12: first line; second line; line 14: third"


@needs_drake
def test_an_inertia_drake_replaces_takes_drake_out_of_the_vote() -> None:
    """A + B < C: MuJoCo repairs it (asked), Pinocchio keeps it, Drake's parser replaces it (its own warning).

    Drake was given another link than the file's: it casts no vote (no "all three engines differ"); MuJoCo's
    repair, the pair's cause, is the root cause, and Drake's replaced inertia stays a finding, with its values.
    """
    check = koenig_check.compare(
        TIEBREAK / "unbalanced_inertia.urdf", n_poses=2, formulas=["exact"], repair_inertia=True
    )
    assert not _verdicts(check)  # Drake consulted (its finding below), and no vote
    assert check.reason().startswith(
        "unbalanced_inertia.urdf: root cause: link arm: inertia changed so that MuJoCo accepts"
    )
    replaced = [f for f in check.comparisons[0].findings if f.engine == "drake" and f.kind is Kind.INERTIA]
    assert [f.element for f in replaced] == ["link arm"] and replaced[0].segments == ("swing",)
    assert replaced[0].values["moments in the file"] == pytest.approx([0.1, 0.1, 0.25], rel=1e-12)
    assert replaced[0].values["moments in Drake"] != pytest.approx([0.1, 0.1, 0.25], rel=1e-3)


@needs_drake
@pytest.mark.parametrize("engines", [None, ALL], ids=["consulted", "named"])
def test_a_construct_both_other_engines_skip_is_named_not_blamed_on_mujoco(engines) -> None:
    """Pinocchio and Drake both skip the <frame>'s geom and agree: MuJoCo reads the file as written.

    Drake skips it through a known limit of its parser: its agreement with Pinocchio is no vote, so MuJoCo is not
    said to depart; the <frame> Pinocchio does not read is the root cause, and named Drake could not check it.
    """
    from koenig_check.engines import load_model
    from koenig_check.engines.sampling import random_states

    path = HERE / "models" / "causes" / "frame_geom.xml"
    model = load_model(path, engines=ALL)
    model.attach("drake")
    qpos, qvel = random_states(model.mujoco.model, 3, 0)
    energy = {name: e.kinetic_energy(qpos, qvel).rigid for name, e in model.engines.items()}
    assert energy["drake"] == pytest.approx(energy["pinocchio"], rel=1e-12)  # the premise: a 2-of-3 "majority"
    assert energy["drake"] != pytest.approx(energy["mujoco"], rel=1e-3)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=engines)
    drake = [f for f in check.comparisons[0].findings if f.engine == "drake" and f.kind is Kind.IGNORED_CONSTRUCT]
    assert drake and not _verdicts(check) and not check.ok  # Drake used (its finding), and no vote
    assert [f.cause for f in drake] == ["drake.mjcf.frame"]
    frames = [f.engine for f in check.comparisons[0].findings if f.cause.endswith(".mjcf.frame")]
    assert sorted(frames) == ["drake", "pinocchio"]
    reason = check.reason()
    assert reason.startswith("frame_geom.xml: root cause: frame #1 in body base: <frame> not read by Pinocchio's")
    assert "departs" not in reason and "engines differ" not in reason
    unable = [f for f in check.comparisons[0].findings if f.kind is Kind.ENGINE_UNABLE]
    assert [f.summary for f in unable] == (
        []
        if engines is None
        else ["Drake cannot check this model: its MJCF parser ignores <frame> (elements: frame #1 in body base)"]
    )


@needs_drake
@pytest.mark.parametrize("path", [TIEBREAK / "settotalmass.xml", "dm:suite/cheetah.xml"], ids=str)
def test_the_cause_list_blames_the_engines_that_ignore_the_option(path, capsys: pytest.CaptureFixture[str]) -> None:
    """settotalmass: the pair's cause says "Pinocchio does not rescale"; with Drake, MuJoCo alone applies it.

    Expected from each engine's own total mass: MuJoCo's is the file's settotalmass (the file as written),
    Pinocchio's and Drake's are equal to each other and not to it (the catalogue's reading of Drake, measured on
    real files).  The parity's root cause is Pinocchio's, the engine of the id, which departs from the file (never
    MuJoCo, which applies the option); Drake's own finding carries the id, and Drake does not vote.
    """
    import numpy as np

    from koenig_check.diagnosis.diagnose import diagnose
    from koenig_check.engines import load_model

    if str(path).startswith("dm:"):
        dm_control = pytest.importorskip("dm_control")
        path = Path(dm_control.__file__).parent / str(path)[3:]
    from koenig_check.modelfile.validate import parse_xml

    written = float(parse_xml(path).getroot().find("compiler").get("settotalmass"))
    model = load_model(path, engines=ALL)
    model.attach("drake")
    q0, zero = np.asarray(model.mujoco.model.qpos0)[None], np.zeros((1, model.mujoco.nv))
    mass = {n: float(np.sum(e.segment_states(q0, zero).mass)) for n, e in model.engines.items()}
    assert mass["mujoco"] == pytest.approx(written, rel=1e-12)  # MuJoCo rescaled to the option's total
    assert mass["drake"] == pytest.approx(mass["pinocchio"], rel=1e-12)
    assert mass["pinocchio"] != pytest.approx(mass["mujoco"], rel=1e-3)
    diagnosis = diagnose(model)
    assert not diagnosis.verdicts
    (cause,) = [c for c in diagnosis.parity.causes if c.element == "compiler settotalmass"]
    assert cause.engine == "pinocchio"
    named = [(f.engine, f.cause) for f in diagnosis.findings if f.element == "compiler settotalmass"]
    assert named == [("pinocchio", "pinocchio.mjcf.settotalmass"), ("drake", "pinocchio.mjcf.settotalmass")]
    assert main(["parity", str(path)]) == 1
    out, err = capsys.readouterr()
    assert "changes the kinetic energy] pinocchio: compiler settotalmass: " in out
    assert err.startswith(f"koenig-check: {Path(path).name}: root cause: compiler settotalmass")


@needs_drake
def test_a_root_pose_pinocchio_drops_is_no_departure() -> None:
    """posed_root.xml: a jointless posed base, whose pose Pinocchio's MJCF parser drops (a constant transform of the
    world, no effect on the energy).  MuJoCo and Pinocchio agree on it (tests/test_causes.py); with Drake, whose world
    is MuJoCo's, the three engines must agree too: each segment's mass, COM and inertia compared in one world.
    """
    path = HERE / "models" / "causes" / "posed_root.xml"
    assert_energy_parity(path, n_poses=3, engines=ALL, gravity=False)  # the energies agree, segment by segment
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=ALL)
    assert set(check.comparisons[0].engines) == set(ALL)
    assert not _verdicts(check), [f.message() for f in _verdicts(check)]
    assert all(p.agrees for p in check.agreements), check.reasons()
    gravity = check.comparisons[0].gravity  # only gravity sees the dropped pose (issue 27): Pinocchio alone departs
    assert gravity is not None and {g.engine for g in gravity.gaps if g.relative > check.rtol} == {"pinocchio"}
    with pytest.raises(AssertionError, match="welded-root-pose"):
        assert_energy_parity(path, n_poses=3, engines=ALL)
