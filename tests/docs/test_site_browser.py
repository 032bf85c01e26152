"""The built site in headless Chromium at 1280 px, opened from ``site/index.html`` (file://, no server).

Each page fits the window (no horizontal scroll), its figures load, and the search finds a page, offline.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from browser import WINDOW, measure, require_chromium

require_chromium()
pytest.importorskip("mkdocs", reason="the docs extra: pip install '.[docs]'")
from test_site import build_site  # noqa: E402

#: After load: the widths, elements reaching past the window; then a search typed into the box and its results.
_MEASURE = """
<script>
window.addEventListener("load", () => {
  const root = document.documentElement;
  const out = {scrollWidth: root.scrollWidth, clientWidth: root.clientWidth, innerWidth: window.innerWidth,
               outside: [], results: [],
               images: [...document.images].map(i => [i.getAttribute("src"), i.naturalWidth])};
  for (const el of document.body.querySelectorAll("*")) {
    const box = el.getBoundingClientRect();
    if (box.width > 0 && box.right > root.clientWidth + 0.5 && !el.closest(".md-search, .md-sidebar")) {
      out.outside.push(el.tagName + "." + el.className + " " + Math.round(box.right));
    }
  }
  const query = document.querySelector("[data-md-component=search-query]");
  setTimeout(() => {
    query.focus();
    query.value = "QUERY";
    query.dispatchEvent(new Event("focus"));
    query.dispatchEvent(new KeyboardEvent("keyup", {key: "e"}));
    query.dispatchEvent(new Event("input", {bubbles: true}));
    setTimeout(() => {
      out.results = [...document.querySelectorAll(".md-search-result__item a")].map(a => a.getAttribute("href"));
      const pre = document.createElement("pre");
      pre.id = "measured";
      pre.hidden = true;
      pre.textContent = JSON.stringify(out);
      document.body.appendChild(pre);
    }, 4000);
  }, 3000);
});
</script>
"""


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build_site(tmp_path_factory.mktemp("site"))


@pytest.mark.parametrize("page", ["index.html", "cli.html", "paper.html", "causes.html"])
def test_page_fits_1280_px_and_search_works_offline(site: Path, page: str) -> None:
    measured = measure(site / page, _MEASURE.replace("QUERY", "armature"), budget_ms=20000)
    assert measured["innerWidth"] == WINDOW
    assert measured["scrollWidth"] <= measured["clientWidth"] <= WINDOW
    assert measured["outside"] == []
    assert any("engines.html" in href for href in measured["results"]), measured["results"]
    assert all(width > 0 for _, width in measured["images"]), measured["images"]  # every figure loads from file://
    if page == "paper.html":  # the paper's figures, taken from comparisons/ at build time
        assert sum("comparisons/paper_claims_" in src for src, _ in measured["images"]) == 8
