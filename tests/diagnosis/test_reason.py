"""The one-line reason: one sentence within 200 characters, the root causes first, never a file's rounding."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.diagnosis.model_reason import short_reason
from koenig_check.diagnosis.reason import (
    REASON_WIDTH,
    ROUNDING_LEVEL,
    ordered_causes,
    root_cause_groups,
)
from koenig_check.findings import Finding, Kind
from koenig_check.testing import assert_energy_parity

TESTS = Path(__file__).resolve().parents[1]
PROJECT = TESTS.parent / "models"
#: Files of the corpus whose construct changes no energy: the engines agree.
AGREEING = {"childclass_geom_type.xml", "class_joint_pos_explicit.xml", "class_mass_explicit.xml", "posed_root.xml"}
AGREEING |= {"robot_part.xml", "hinge_ref.xml"}
#: Files of the test corpus whose engines disagree (a construct Pinocchio or MuJoCo reads its own way).
DISAGREEING = sorted(
    p
    for p in [*(TESTS / "models" / "causes").glob("*.xml"), *(TESTS / "models" / "tiebreak").glob("*.xml")]
    if p.name not in {"arm_part.xml", "arm_part_mujocoinclude.xml", "tool_part.xml"}  # included fragments
    and p.name not in AGREEING
)


def _symptom(element: str, relative: float) -> Finding:
    return Finding(
        Kind.INERTIA,
        "both",
        element,
        "inertia differs between the engines",
        {"relative difference": relative},
        affects_energy=True,
    )


def test_root_causes_first_then_the_largest_symptom_and_never_a_files_rounding() -> None:
    root = Finding(
        Kind.MASS, "pinocchio", "geom pole", "geom mass from a class not applied", affects_energy=True, root_cause=True
    )
    small, large, rounding = _symptom("link a", 1e-3), _symptom("link b", 0.5), _symptom("link c", ROUNDING_LEVEL / 10)
    assert ordered_causes([small, rounding, large, root]) == [root, large, small]


def test_many_causes_fit_the_line_with_how_many_more() -> None:
    findings = [
        _symptom(f"link number_{k:02d} (joint a_rather_long_joint_name_{k:02d})", 1 - k / 100) for k in range(12)
    ]
    line = short_reason("robot.xml", findings, "MuJoCo and Pinocchio differ by 0.5 relative (pose random-3)")
    assert len(line) <= REASON_WIDTH and "\n" not in line
    assert line.startswith("robot.xml: root cause: link number_00") and " and 11 more" in line


@pytest.mark.parametrize("path", DISAGREEING, ids=lambda p: p.name)
def test_reasons_of_the_corpus_are_one_short_sentence_leading_with_the_root_cause(path: Path) -> None:
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert not check.ok
    for line in check.reasons():
        assert "\n" not in line and (len(line) <= REASON_WIDTH or check.failures), line
    if check.failures:
        return  # a file an engine refuses: its whole reason, on one line
    (line,) = check.reasons()
    assert line.startswith(f"{check.agreements[0].model}: ")
    groups = root_cause_groups(check.comparisons[0].findings)  # the same cause on several elements is one
    if groups and len(groups[0].short()) < 100:
        assert f"root cause: {groups[0].short()}" in line
    rounding = [
        f for f in check.comparisons[0].findings if 0 < float(f.values.get("relative difference", 0)) <= ROUNDING_LEVEL
    ]
    assert not any(f.element in line for f in rounding)


@pytest.fixture(scope="module")
def twin(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """serial7.urdf as MuJoCo's own URDF import saves it: numbers with 6 significant digits."""
    out = tmp_path_factory.mktemp("twin") / "serial7_saved.xml"
    mujoco.mj_saveLastXML(str(out), mujoco.MjModel.from_xml_path(str(PROJECT / "serial7.urdf")))
    return out


def test_a_twin_written_at_six_digits_gets_the_rounding_hint(twin: Path, capsys: pytest.CaptureFixture[str]) -> None:
    options = dict(pinocchio_model=PROJECT / "serial7.urdf", n_poses=5, formulas=["exact"])
    check = koenig_check.compare(twin, **options)
    assert not check.ok
    (line,) = check.reasons()  # the API names the keyword as Python spells it
    assert "what a file written with 6 significant digits explains" in line and "rtol=1e-05 accepts it" in line
    assert "--rtol" not in check.reason()
    assert "differs" not in line  # no rounding-level item named as a cause
    assert koenig_check.compare(twin, rtol=ROUNDING_LEVEL, **options).ok  # the option the hint names
    with pytest.raises(AssertionError, match=r"rtol=1e-05 accepts it"):
        assert_energy_parity(twin, pinocchio_model=PROJECT / "serial7.urdf", n_poses=5)
    argv = ["compare", str(twin), "--pinocchio-model", str(PROJECT / "serial7.urdf"), "--poses", "5"]
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert "--rtol 1e-05 accepts it" in err and all(len(x) <= 200 for x in err.splitlines())
    assert main([*argv, "--rtol", "1e-5"]) == 0


def test_a_check_not_made_closes_the_line_after_the_root_cause() -> None:
    summary = "geom mass from a class not applied"
    root = Finding(Kind.MASS, "pinocchio", "geom pole", summary, affects_energy=True, root_cause=True)
    drake = "Drake asked for (--engines) but it could not check the model: " + "an engine's long reason " * 12
    unable = Finding(Kind.ENGINE_UNABLE, "drake", "model", drake.strip())
    line = short_reason("hand.xml", [unable, root], "MuJoCo and Pinocchio differ by 3 relative (pose random-1)")
    assert line.startswith("hand.xml: root cause: geom pole: geom mass from a class not applied")
    # the check not made closes the line at a whole clause, never cut with "…" (issue 28): the lines after the
    # reason give it whole
    assert len(line) <= REASON_WIDTH and not line.endswith("…")
    assert line.endswith("; Drake asked for (--engines) but it could not check the model")
    from koenig_check.diagnosis.message import finding_lines

    # the lines after it give the rest of the reason whole, not what the first line already said
    rest = drake.strip().removeprefix("Drake asked for (--engines) but it could not check the model: ")
    assert " ".join(" ".join(finding_lines([unable, root], line)).split()) == f"drake: …{rest}"
    whole = short_reason("hand.xml", [unable, root], width=1000)
    assert whole.endswith(drake.strip())


def test_the_helper_reports_a_file_it_cannot_load_in_one_line() -> None:
    with pytest.raises(AssertionError) as info:
        assert_energy_parity("no_such_robot.xml")
    assert str(info.value).startswith("no_such_robot.xml: no such file") and "\n" not in str(info.value)
    assert info.value.__cause__ is None and info.value.__suppress_context__  # no library frames chained


def test_a_dynamics_result_has_a_short_repr() -> None:
    text = repr(koenig_check.dynamics("gimbal.xml", n_poses=1, formulas=["exact"]))
    assert text.startswith("<DynamicsResult ") and "ok=True" in text and len(text) < 200


def test_more_root_causes_end_the_last_cause_line_never_a_line_of_their_own() -> None:
    from koenig_check.diagnosis.reason import cause_lines

    roots = [
        Finding(Kind.COMPILER, "mujoco", f"body b{k}", f"option {k} changes it", affects_energy=True, root_cause=True)
        for k in range(5)
    ]
    lines = cause_lines(roots)
    assert len(lines) == 3 and lines[-1].endswith("; and 2 more root causes"), lines
    assert not any(line.startswith("and ") for line in lines)


def _unable(reason_words: str) -> Finding:
    return Finding(Kind.ENGINE_UNABLE, "drake", "model", f"Drake cannot check this model: {reason_words}", hint="")


def _departs() -> Finding:
    values = {"mujoco": 1.0, "pinocchio": 2.0, "drake": 1.0}
    return Finding(Kind.VERDICT, "pinocchio", "rigid-body energy", "Pinocchio departs", values, True)


def test_a_reason_is_built_once_and_shown_whole_or_within_a_line() -> None:
    """One Reason: the row shows every part whole, the line keeps the check not made's clauses that fit, never
    half of one (the lines below the first give it whole)."""
    from koenig_check.diagnosis.model_reason import model_reason
    from koenig_check.diagnosis.reason import REASON_WIDTH

    long = "its parser " + " ".join(f"word{k}" for k in range(60))  # an engine's own reason, 400 characters
    gap = "MuJoCo and Pinocchio differ by 1 relative (pose p)"
    why = model_reason("m.xml", [_departs(), _unable(long)], gap)
    assert why.whole() == f"m.xml: Pinocchio departs; {gap}; Drake cannot check this model: {long}"  # never cut
    line = why.line()
    assert len(line) <= REASON_WIDTH and not line.endswith("…")
    assert line == f"m.xml: Pinocchio departs; {gap}; Drake cannot check this model"  # cut at the clause
    short = model_reason("m.xml", [_departs(), _unable("its parser ignores armature")])
    assert (
        short.line()
        == short.whole()
        == "m.xml: Pinocchio departs; Drake cannot check this model: its parser ignores armature"
    )


def test_the_table_row_and_the_error_line_show_the_same_reason() -> None:
    """A disagreeing model whose named Drake cannot check it: the row holds the reason whole, the line its first 186."""
    pytest.importorskip("pydrake")
    from koenig_check.report.terminal import terminal_table

    path = Path(__file__).resolve().parents[1] / "models" / "causes" / "class_joint_pos_explicit.xml"
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"])
    why = check.model_reason(check.comparisons[0], check.agreements[0], cli=True)
    assert why is not None and why.unmade.startswith("Drake cannot check this model")
    assert check.reasons(cli=True) == [why.line()]
    row = " ".join(terminal_table(check).split())  # folded under its column: the words in order
    assert " ".join(why.whole().removeprefix(f"{path.name}: ").split()) in row


def test_an_engines_own_text_is_said_once_under_the_first_line() -> None:
    """A refusal with the engine's own text (Newton's, two lines here): the one-line reason ends at the refusal, the
    lines under it give the engine's text once, as written, and the table's row holds it whole on one line."""
    from koenig_check.diagnosis.message import finding_lines
    from koenig_check.diagnosis.model_reason import model_reason
    from koenig_check.engines.registry import ENGINE_TEXT

    words = "ValueError: Mimic followers and references only support PRISMATIC, REVOLUTE, D6 joints.\n  " + "x" * 120
    summary = "Newton asked for (--engines) but it could not check the model: Newton's add_urdf refuses the file"
    unable = Finding(
        Kind.ENGINE_UNABLE, "newton", "model", summary, {ENGINE_TEXT: words}, hint="check it without Newton"
    )
    reason = model_reason("talos", [unable])
    line = reason.line()
    assert line == f"talos: {summary}; check it without Newton" and "\n" not in line
    below = finding_lines([unable], line, width=1000)
    assert below == ["    " + w for w in words.splitlines()]  # once, whole, indented; the summary and hint not again
    assert reason.whole() == f"talos: {summary}: {' '.join(words.split())}; check it without Newton"


def test_two_engines_refusing_one_construct_give_its_hint_once() -> None:
    """Newton and Drake both refuse a <mimic> in a fixed joint: each says why, the cause's hint is said once."""
    from koenig_check.diagnosis.model_reason import model_reason

    hint = "remove the <mimic> from the fixed joint; or check the model without it (--engines mujoco,pinocchio)"
    unable = [
        Finding(
            Kind.ENGINE_UNABLE, engine, "model", f"{engine} asked for (--engines) but it could not check it", hint=hint
        )
        for engine in ("drake", "newton")
    ]
    whole = model_reason("talos", unable).whole()
    assert whole.count(hint) == 1 and whole.count("could not check it") == 2
    other = Finding(
        Kind.ENGINE_UNABLE, "pybullet", "model", "pybullet asked for (--engines) but no", hint="another hint"
    )
    assert model_reason("talos", [*unable, other]).whole().endswith(f"{hint}; another hint")
