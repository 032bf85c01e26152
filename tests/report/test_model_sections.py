"""Each model's section of summary.md and report.html shows that model's own numbers and verdicts.

A run of several models must tell each model's story as a run of that model alone would: the engine parity verdict
and the table's values (max rel. error per engine, verdict) of the model the section is titled with.  Expected values
come from a run of each model alone, and the engine parity verdict from the engines' own masses (MuJoCo's
``body_mass``, Pinocchio's ``inertias``): a model whose moving masses differ between them cannot agree.
"""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

import koenig_check
from koenig_check.engines import load_model
from koenig_check.report import summary_markdown, write_report

CAUSES = Path(__file__).parents[1] / "models" / "causes"
MODELS = ["gimbal.xml", str(CAUSES / "class_mass.xml")]
RUN = {"n_poses": 4, "seed": 3}
#: Below this a relative error is the CPU's round-off: a run alone may print another digit of it.
ROUND_OFF = 1e-12


@pytest.fixture(scope="module")
def check():
    return koenig_check.compare(MODELS, **RUN)


@pytest.fixture(scope="module")
def alone(check):
    """Per label, the summaries of a run of that model alone (same poses: pose i depends on the seed and i only)."""
    return {c.model: koenig_check.compare({c.model: m}, **RUN) for c, m in zip(check.comparisons, MODELS, strict=True)}


def _moving_masses_differ(model: str) -> bool:
    loaded = load_model(model)
    mj, pin = loaded.mujoco.model, loaded.pinocchio.model
    m_mj = sum(float(mj.body_mass[b]) for b in range(1, mj.nbody) if mj.body_weldid[b] != 0)
    m_pin = sum(float(pin.inertias[i].mass) for i in range(1, pin.njoints))
    return abs(m_mj - m_pin) > 1e-6 * max(m_mj, m_pin)


def _expected_rows(run) -> dict[str, tuple[str, list[float]]]:
    """formula -> (verdict, max rel. error per engine in the model's engine order), from a run of it alone."""
    (comp,) = run.comparisons
    out: dict[str, tuple[str, list[float]]] = {}
    for formula in dict.fromkeys(s.formula for s in run.summaries):
        # the table compares each engine's formula with that engine's own energy (COLUMNS: "max rel. error")
        group = [s for s in run.summaries if s.formula == formula and s.source == s.reference]
        by_engine = {s.source: s.max_rel_error for s in group}
        verdict = "exact" if all(s.agrees for s in group) else "differs"
        out[formula] = (verdict, [by_engine[e] for e in comp.engines])
    return out


def _close(shown: str, value: float) -> bool:
    """The printed number is the value to its 3 significant digits; round-off (under 1e-12) is round-off either way."""
    number = float(shown)
    if abs(value) < ROUND_OFF:
        return abs(number) < ROUND_OFF
    return abs(number - value) <= 6e-3 * abs(value)


def test_the_models_of_the_run_disagree_differently(check) -> None:
    """The test below can only tell sections apart when the models' verdicts differ (one agrees, one not)."""
    assert [_moving_masses_differ(m) for m in MODELS] == [False, True]


def _md_section(text: str, model: str) -> str:
    return text.split(f"\n## {model}\n", 1)[1].split("\n## ", 1)[0]


def test_markdown_sections_show_their_own_models_parity_verdict_and_table(check, alone) -> None:
    text = summary_markdown(check.comparisons, check.summaries, check.agreements, check.failures, check.rtol)
    for comp, model in zip(check.comparisons, MODELS, strict=True):
        section = _md_section(text, comp.model)
        verdict = re.search(r"Engine parity: the engines (agree|DISAGREE)", section)
        assert verdict is not None
        assert (verdict.group(1) == "DISAGREE") == _moving_masses_differ(model), comp.model
        expected = _expected_rows(alone[comp.model])
        rows = re.findall(r"^\| `([^`]+)` \[[^\]]*\] \| (\w+) \| ([^|]+) \|", section, flags=re.M)
        assert [r[0] for r in rows] == list(expected)
        for formula, shown_verdict, maxima in rows:
            want_verdict, want = expected[formula]
            assert shown_verdict == want_verdict, (comp.model, formula)
            shown = [x.strip() for x in maxima.split(" / ")]
            assert all(map(_close, shown, want)), (comp.model, formula, shown, want)


@pytest.fixture(scope="module")
def page(check, tmp_path_factory: pytest.TempPathFactory) -> str:
    out = tmp_path_factory.mktemp("sections")
    write_report(out, check)
    return (out / "report.html").read_text(encoding="utf-8")


def test_html_sections_show_their_own_models_parity_verdict_and_table(check, alone, page: str) -> None:
    for k, (comp, model) in enumerate(zip(check.comparisons, MODELS, strict=True)):
        anchor = "model-" + "".join(c if c.isalnum() else "-" for c in comp.model)
        section = page.split(f'id="{anchor}-{k}"', 1)[1].split("</section>", 1)[0]
        disagrees = "the engines DISAGREE" in section
        assert disagrees != ("the engines agree" in section)
        assert disagrees == _moving_masses_differ(model), comp.model
        expected = _expected_rows(alone[comp.model])
        rows = re.findall(
            r'<tr class="(\w+)"><td><code>(.*?)</code>.*?<td class="verdict">\w+</td><td class="num">(.*?)</td>',
            section,
        )
        assert [re.sub(r"<wbr>", "", r[1]) for r in rows] == list(expected)
        for verdict, name, maxima in rows:
            formula = html.unescape(name.replace("<wbr>", ""))
            want_verdict, want = expected[formula]
            assert verdict == want_verdict, (comp.model, formula)
            shown = [html.unescape(x) for x in maxima.split("<br>")]
            assert all(map(_close, shown, want)), (comp.model, formula, shown, want)


def _parity_numbers(section: str) -> tuple[float, str, float]:
    """(largest relative difference, its pose, largest armature difference in J) of an Engine parity line."""
    found = re.search(
        r"largest relative difference (\S+) \(pose ([^)]*)\); armature energy, largest difference (\S+) J", section
    )
    assert found is not None, section
    return float(found.group(1)), found.group(2), float(found.group(3))


def test_parity_lines_give_the_models_own_largest_difference_its_pose_and_the_armature_gap(check, alone, page) -> None:
    """class_mass: MuJoCo and Pinocchio differ by several times the energy (6 kg of pole in Pinocchio) at some
    pose, and no joint has armature in either engine (0 J), as in a run of the model alone."""
    text = summary_markdown(check.comparisons, check.summaries, check.agreements, check.failures, check.rtol)
    for k, comp in enumerate(check.comparisons):
        (own,) = alone[comp.model].agreements
        anchor = "model-" + "".join(c if c.isalnum() else "-" for c in comp.model)
        html_section = html.unescape(page.split(f'id="{anchor}-{k}"', 1)[1].split("</section>", 1)[0])
        for section in (_md_section(text, comp.model), re.sub(r"<[^>]+>", "", html_section)):
            rigid, pose, armature = _parity_numbers(section)
            assert _close(str(rigid), own.rigid_max_rel) and pose == own.worst_pose, (comp.model, section[:300])
            assert armature == own.armature_max_abs == 0.0, comp.model
    (class_mass,) = alone[check.comparisons[1].model].agreements
    assert class_mass.rigid_max_rel > 1.0  # the test can tell the rigid gap from the armature gap
