"""summary.md: findings in words first, glossary with equation numbers, every column and pose label defined,
notes once."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import koenig_check
from koenig_check.formulas import FORMULAS
from koenig_check.report import COLUMN_TITLES, summary_markdown
from koenig_check.report.content import COLUMNS, POSE_LABELS

CAUSES = Path(__file__).parents[1] / "models" / "causes"


@pytest.fixture(scope="module")
def check():
    return koenig_check.compare(["gimbal.xml", "gimbal.urdf", CAUSES / "class_mass.xml", "no_such_robot"], n_poses=4)


@pytest.fixture(scope="module")
def text(check) -> str:
    return summary_markdown(check.comparisons, check.summaries, check.agreements, check.failures, check.rtol)


def _sections(text: str) -> list[str]:
    return re.findall(r"^## (.+)$", text, flags=re.M)


def test_sections_in_order(check, text: str) -> None:
    models = [c.model for c in check.comparisons]
    assert _sections(text) == [
        "What this run found",
        "Formulas",
        "How to read the tables",
        *models,
        "Models that could not be compared",
        "Notes",
    ]


def test_findings_in_words_per_model_with_size_and_sign(check, text: str) -> None:
    found = text.split("## What this run found", 1)[1].split("\n## ", 1)[0]
    for comp in check.comparisons:
        assert f"**{comp.model}**" in found
    gimbal = found.split("**gimbal.xml**", 1)[1].split("\n- **", 1)[0]
    assert "agree" in gimbal and "`exact`" in gimbal.split("exact to rounding:", 1)[1].split("\n", 1)[0]
    worst = max(
        s.max_rel_error
        for s in check.summaries
        if s.model == "gimbal.xml" and s.formula == "koenig_world" and s.source == s.reference
    )
    line = next(x for x in gimbal.splitlines() if "`koenig_world`" in x)
    assert f"up to {100 * worst:.3g} %" in line and ("both signs" in line or "always" in line)
    assert "DISAGREE" in found.split("**class_mass.xml**", 1)[1].split("\n- **", 1)[0]
    assert "**no_such_robot**: could not be compared" in found


def test_glossary_names_every_formula_with_its_equations(check, text: str) -> None:
    glossary = text.split("## Formulas", 1)[1].split("\n## ", 1)[0]
    for name in {s.formula for s in check.summaries}:
        assert f"- `{name}` [{FORMULAS[name].equations}]: " in glossary


def test_every_column_and_pose_label_is_defined(text: str) -> None:
    howto = text.split("## How to read the tables", 1)[1].split("\n## ", 1)[0]
    assert set(COLUMN_TITLES) == set(COLUMNS)
    for title in COLUMN_TITLES:
        assert f"- **{title}**: " in howto
    for label in POSE_LABELS:
        assert f"- `{label}`: " in howto
    assert "| " + " | ".join(COLUMN_TITLES) + " |" in text


def test_used_pose_labels_are_the_defined_ones(text: str) -> None:
    used = set(re.findall(r"\b(random|grid|traj)-\d+", text))
    assert used <= {label.split("-")[0] for label in POSE_LABELS}
    assert "pose 0" not in text


def test_notes_said_once(check, text: str) -> None:
    notes = text.split("## Notes", 1)[1].splitlines()
    bullets = [n for n in notes if n.startswith("- ")]
    assert len(bullets) == len(set(bullets))
    everyone = {n for c in check.comparisons for n in c.notes if all(n in d.notes for d in check.comparisons)}
    for note in everyone:
        assert text.count(note) == 1 and f"- {note} (all models)" in text


def test_overview_names_formulas_exact_everywhere_and_nowhere(check, text: str) -> None:
    found = text.split("## What this run found", 1)[1].split("\n- **", 1)[0]
    assert "MuJoCo and Pinocchio agree on 2 of 3" in found
    own = [s for s in check.summaries if s.source == s.reference]
    formulas = {s.formula for s in own}
    never = {f for f in formulas if all(not s.agrees for s in own if s.formula == f)}
    always = {f for f in formulas if all(s.agrees for s in own if s.formula == f)}
    assert never and "exact" in always
    everywhere = found.split("Exact to rounding on every model it applies to:", 1)[1].split(". ", 1)[0]
    nowhere = found.split("Exact on no model:", 1)[1].split(". ", 1)[0]
    assert set(re.findall(r"`([^`]+)`", nowhere)) == never
    assert set(re.findall(r"`([^`]+)`", everywhere)) == always
