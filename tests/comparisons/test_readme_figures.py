"""Every figure the README and the documentation pages give in their findings is in the committed output quoted.

A findings line of a document (the README, ``docs/*.md``: tests/documents.py)
ends with ``<!-- from comparisons/NAME.md -->``; every number on it (a
percentage, a decimal, a power of ten, a count) must appear, as written, in that file.  Equation numbers in
parentheses, such as ``(38)``, are references, not figures.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from documents import DOCUMENTS

ROOT = Path(__file__).resolve().parents[2]
MARK = re.compile(r"<!-- from (comparisons/[\w.]+\.md) -->")
NUMBER = re.compile(r"(?<![\w.^])[+-]?\d+(?:\.\d+)?(?:e[+-]\d+)?(?: ?%)?(?![\w])")
EQUATION = re.compile(r"\(\d+\)")


def marked_lines() -> list[tuple[str, str, str]]:
    """Each marked line of every document: where (``README.md:243``), its text without the mark, its source."""
    out = []
    for document in DOCUMENTS:
        lines = document.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines, 1):
            m = MARK.search(line)
            if m:
                out.append((f"{document.name}:{i}", MARK.sub("", line), m.group(1)))
    return out


def figures(text: str) -> list[str]:
    return [n.strip() for n in NUMBER.findall(EQUATION.sub("", text))]


def test_readme_findings_are_marked() -> None:
    sources = {src for _, _, src in marked_lines()}
    assert {
        "comparisons/paper_claims.md",
        "comparisons/engine_parity.md",
        "comparisons/inertia_forces.md",
        "comparisons/benchmark.md",
    } <= sources
    assert sum(len(figures(t)) for _, t, _ in marked_lines()) >= 20


@pytest.mark.parametrize(("line", "text", "source"), marked_lines(), ids=[n for n, _, _ in marked_lines()])
def test_every_figure_of_a_findings_line_is_in_its_source(line: str, text: str, source: str) -> None:
    committed = (ROOT / source).read_text(encoding="utf-8")
    missing = [f for f in figures(text) if f not in committed]
    assert not missing, f"{line}: {missing} not in {source}"


def test_figures_are_extracted_with_their_sign_and_unit() -> None:
    assert figures("from -29.3 % to +89.9 %, 7.9e-01 on 66 models (2.2e-16), eq. (38), eqs. (39)–(41)") == [
        "-29.3 %",
        "+89.9 %",
        "7.9e-01",
        "66",
        "2.2e-16",
    ]
