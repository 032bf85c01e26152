"""The documents that quote the tool's outputs and figures: the README and the documentation site's pages.

Tests that check a quoted output or figure find it in whichever document holds it, so that a passage moved from
the README into a page of ``docs/`` (or back) stays checked.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
#: The README first, then the site's pages (``docs/*.md``), in name order.
DOCUMENTS = [README, *sorted((ROOT / "docs").glob("*.md"))]


def document_with(marker: str) -> str:
    """The text of the one document that holds ``marker`` (an assertion error when none or several do)."""
    holding = [p for p in DOCUMENTS if marker in p.read_text(encoding="utf-8")]
    assert len(holding) == 1, f"{marker!r} is in {[p.name for p in holding]}: expected in exactly one document"
    return holding[0].read_text(encoding="utf-8")


def all_documents() -> str:
    """Every document's text, one after the other."""
    return "\n".join(p.read_text(encoding="utf-8") for p in DOCUMENTS)
