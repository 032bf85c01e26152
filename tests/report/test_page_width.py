"""report.html at a 1280 px window, measured in headless Chromium: no horizontal scroll, readable figure text.

A real report (the demo's models at few poses, plus a disagreeing model) is opened in Chromium with a script
that measures the page after it has loaded and writes the measurements into the DOM, which ``--dump-dom``
prints (tests/browser.py: skipped where Chromium is not installed, unless CI requires it).
"""

from __future__ import annotations

import base64
import io
import re
from pathlib import Path

import pytest
from PIL import Image

from browser import WINDOW, measure, require_chromium
from koenig_check.api import compare_model
from koenig_check.demo import run_demo
from koenig_check.report import write_report
from koenig_check.report.figures import MIN_FONT_KEY

CAUSES = Path(__file__).parents[1] / "models" / "causes"
#: The smallest text a reader is asked to read, in CSS px at the page's display size.
MIN_TEXT_PX = 10.0

require_chromium()

#: Run after the page has loaded: the widths, every element that reaches past the window or scrolls
#: sideways, each image's shown and natural width, and the smallest computed font size of the page's text.
_MEASURE = """
<script>
window.addEventListener("load", () => {
  for (const d of document.querySelectorAll("details")) d.open = true;  // as a reader who unfolds every section
  const root = document.documentElement;
  const out = {scrollWidth: root.scrollWidth, clientWidth: root.clientWidth, innerWidth: window.innerWidth,
               outside: [], scrolling: [], images: [], smallestText: Infinity, smallestTextAt: ""};
  for (const el of document.body.querySelectorAll("*")) {
    const box = el.getBoundingClientRect();
    const style = getComputedStyle(el);
    if (box.width > 0 && box.right > root.clientWidth + 0.5) out.outside.push(el.tagName + " " + Math.round(box.right));
    if (el.scrollWidth > el.clientWidth + 1 && ["auto", "scroll"].includes(style.overflowX)) {
      out.scrolling.push(el.tagName + " " + el.scrollWidth + ">" + el.clientWidth);
    }
    const text = [...el.childNodes].some(n => n.nodeType === 3 && n.textContent.trim());
    const shown = style.display !== "none" && style.visibility !== "hidden" && box.width > 0;
    if (text && shown && parseFloat(style.fontSize) < out.smallestText) {
      out.smallestText = parseFloat(style.fontSize);
      out.smallestTextAt = el.tagName + ": " + el.textContent.trim().slice(0, 40);
    }
  }
  for (const img of document.images) {
    out.images.push({shown: img.clientWidth, natural: img.naturalWidth});
  }
  const pre = document.createElement("pre");
  pre.id = "measured";
  pre.hidden = true;
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>
"""


#: The first screen of a laptop: the window the matrices must fit in, unscrolled.
FIRST_SCREEN = (WINDOW, 800)

#: After load, unscrolled: where each matrix ends, and the window's size.
_FIRST_SCREEN = """
<script>
window.addEventListener("load", () => {
  const out = {innerWidth: window.innerWidth, innerHeight: window.innerHeight, matrices: []};
  for (const table of document.querySelectorAll("table.matrix")) {
    const box = table.getBoundingClientRect();
    out.matrices.push({cls: table.className, top: box.top, bottom: box.bottom, right: box.right,
                       rows: table.tBodies[0].rows.length});
  }
  const pre = document.createElement("pre");
  pre.id = "measured";
  pre.hidden = true;
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>
"""


@pytest.fixture(scope="module")
def demo_report(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, object, dict]:
    """The demo's report at few poses (its twelve runs), and the run and figures it was written from."""
    check, figures = run_demo(n_poses=4, grid_samples=5, trajectory_samples=20)
    out = tmp_path_factory.mktemp("demo")
    write_report(out, check, **figures)
    return out / "report.html", check, figures


@pytest.fixture(scope="module")
def report(demo_report: tuple[Path, object, dict], tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The demo, a robot with long joint names and a model whose engines disagree.

    example-robot-data's kinova (joints named like ``j2s7s300_joint_finger_tip_1``) made main's tables scroll
    sideways inside their column at 1280 px; class_mass.xml shows its causes and its engine gap.
    """
    _, check, figures = demo_report
    check.add(compare_model("kinova", n_poses=4))
    check.add(compare_model(CAUSES / "class_mass.xml", n_poses=6))
    assert not check.agreements[-1].agrees  # the page shows a disagreement
    out = tmp_path_factory.mktemp("page")
    write_report(out, check, **figures)
    return out / "report.html"


@pytest.fixture(scope="module")
def measured(report: Path) -> dict:
    return measure(report, _MEASURE)


def test_the_page_has_no_horizontal_scroll_at_1280_px(measured: dict) -> None:
    assert measured["innerWidth"] == WINDOW
    assert measured["scrollWidth"] <= measured["clientWidth"] <= WINDOW
    assert measured["outside"] == []  # nothing reaches past the window (a clipped table, a wide figure)
    assert measured["scrolling"] == []  # and no table scrolls sideways inside its own box


def test_page_text_is_at_least_10_px(measured: dict) -> None:
    assert measured["smallestText"] >= MIN_TEXT_PX, measured["smallestTextAt"]


def _pngs(report: Path) -> list[Image.Image]:
    """The page's images, in document order, decoded from their data: URIs."""
    sources = re.findall(r'<img src="data:image/png;base64,([^"]+)"', report.read_text(encoding="utf-8"))
    return [Image.open(io.BytesIO(base64.b64decode(s))) for s in sources]


def test_figure_text_is_at_least_10_px_at_its_display_size(report: Path, measured: dict) -> None:
    images = _pngs(report)
    assert len(images) == len(measured["images"]) > 0
    for png, shown in zip(images, measured["images"], strict=True):
        assert shown["natural"] == png.width
        smallest = float(png.text[MIN_FONT_KEY]) * shown["shown"] / png.width  # CSS px, as the reader sees it
        assert smallest >= MIN_TEXT_PX, (png.text.get("Title", ""), smallest)


def test_each_model_shows_its_engine_gap_figure(report: Path) -> None:
    text = report.read_text(encoding="utf-8")
    sections = text.split('<section class="model"')[1:]
    assert sections and all("gap between the engines" in s for s in sections)


def test_the_first_screen_of_the_demos_report_holds_both_matrices(demo_report: tuple[Path, object, dict]) -> None:
    page = demo_report[0]
    width, height = FIRST_SCREEN
    screen = measure(page, _FIRST_SCREEN, height=height)
    assert screen["innerWidth"] == width and screen["innerHeight"] <= height
    kinds = {m["cls"].split()[-1]: m for m in screen["matrices"]}
    assert set(kinds) == {"engines", "errors"}
    assert kinds["engines"]["rows"] == 12  # the demo's twelve runs, one row each
    for m in screen["matrices"]:
        assert 0 <= m["top"] and m["bottom"] <= screen["innerHeight"], m  # whole, without scrolling
        assert m["right"] <= width, m
