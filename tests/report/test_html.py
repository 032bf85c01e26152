"""report.html: parsed with the stdlib's html.parser; per-model sections, tables, every figure embedded."""

from __future__ import annotations

import base64
import html
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

import koenig_check
from koenig_check.api import compare_model
from koenig_check.findings import Finding, Kind
from koenig_check.report import figure_name, write_report
from koenig_check.report.html import SHOWN_CAUSES, _causes
from koenig_check.run.comparison import ModelComparison

CAUSES = Path(__file__).parents[1] / "models" / "causes"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


class _Page(HTMLParser):
    """Collects sections, tables, images and every URL-bearing attribute."""

    def __init__(self) -> None:
        super().__init__()
        self.stack: list[str] = []
        self.sections: list[dict] = []
        self.images: list[dict] = []
        self.urls: list[tuple[str, str, str]] = []
        self.h2: list[str] = []
        self._in_h2 = False
        self.tags: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        self.tags.append(tag)
        for name in ("src", "href", "srcset", "data", "action", "poster"):
            if a.get(name):
                self.urls.append((tag, name, a[name] or ""))
        if tag == "section":
            self.sections.append({"id": a.get("id"), "class": a.get("class"), "tables": 0, "images": 0})
        section = self.sections[-1] if self.sections and "section" in [*self.stack, tag] else None
        if tag == "table" and section is not None:
            section["tables"] += 1
        if tag == "img":
            self.images.append({**a, "section": section["id"] if section else None})
            if section is not None:
                section["images"] += 1
        if tag == "h2":
            self._in_h2 = True
            self.h2.append("")
        if tag not in ("img", "meta", "br", "link"):
            self.stack.append(tag)

    def handle_endtag(self, tag: str) -> None:
        if tag == "h2":
            self._in_h2 = False
        if tag in self.stack:
            while self.stack.pop() != tag:
                pass

    def handle_data(self, data: str) -> None:
        if self._in_h2:
            self.h2[-1] += data


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory):
    check = koenig_check.compare(
        ["gimbal.xml", "serial7.urdf", CAUSES / "class_mass.xml", "no_such_robot"], n_poses=4, seed=3
    )
    grid = compare_model("gimbal.xml", pose_kind="grid", grid_joints=("outer_z", "inner_x"), n_poses=5)
    check.add(grid)  # the same label as the random run of gimbal.xml: both keep their section and figures
    out = tmp_path_factory.mktemp("html")
    written = write_report(out, check, grid_comparison=grid)
    page = _Page()
    page.feed((out / "report.html").read_text(encoding="utf-8"))
    page.close()
    return check, out, written, page


def test_one_section_per_model_with_its_table_and_figure(report) -> None:
    check, _, _, page = report
    models = [s for s in page.sections if s["class"] == "model"]
    assert len(models) == len(check.comparisons)
    for section in models:
        assert section["tables"] == 1 and section["images"] >= 1
    assert [h for h in page.h2 if h in {c.model for c in check.comparisons}] == [c.model for c in check.comparisons]


def test_summary_sections_are_on_the_page(report) -> None:
    _, _, _, page = report
    for title in ("What this run found", "Formulas", "How to read the tables", "Notes"):
        assert title in page.h2
    assert "Models that could not be compared" in page.h2


def test_every_figure_is_embedded_as_a_png_data_uri_identical_to_the_file(report) -> None:
    check, out, written, page = report
    pngs = sorted(p for p in written if p.suffix == ".png")
    assert len(page.images) == len(pngs) and all(p.exists() for p in pngs)
    embedded = set()
    for img in page.images:
        src = img["src"]
        assert src.startswith("data:image/png;base64,") and img.get("alt")
        data = base64.b64decode(src.split(",", 1)[1], validate=True)
        assert data.startswith(PNG_MAGIC)
        embedded.add(data)
    assert embedded == {p.read_bytes() for p in pngs}
    for comp in check.comparisons:
        assert (out / figure_name(comp.model)).exists()


def test_no_external_resource(report) -> None:
    _, _, _, page = report
    for tag, attr, url in page.urls:
        assert url.startswith(("data:", "#")), (tag, attr, url[:60])
    assert "script" not in page.tags and "link" not in page.tags and "iframe" not in page.tags


def test_parity_causes_of_a_disagreeing_model_are_shown(report) -> None:
    check, out, _, _ = report
    text = (out / "report.html").read_text(encoding="utf-8")
    comp = next(c for c in check.comparisons if c.model == "class_mass.xml")
    root = [f for f in comp.findings if f.root_cause]
    assert root and all(f.element in text for f in root)
    assert text.count("Parity causes") == len(check.comparisons)


def test_figure_of_the_grid_is_in_the_grid_models_section(report) -> None:
    check, _, _, page = report
    k = len(check.comparisons) - 1
    anchor = "model-" + "".join(c if c.isalnum() else "-" for c in check.comparisons[k].model) + f"-{k}"
    # its distribution, its engine gap and the map; the random run of the same label: its own two
    assert sum(1 for img in page.images if img["section"] == anchor) == 3
    assert sum(1 for img in page.images if img["section"] == anchor.replace(f"-{k}", "-0")) == 2


def _finding(element: str, *, root: bool = False, energy: bool = False, kind: str = "inertia") -> Finding:
    return Finding(Kind(kind), "pinocchio", element, f"{element} differs", {"mujoco": 1.0}, energy, root)


def test_a_disagreement_is_a_short_list_of_causes_root_causes_that_change_the_energy_first() -> None:
    """Rounding-level items (no effect on the energy) never come first; at most three, then "and N more"."""
    findings = [
        _finding("joint a1 rounding"),  # does not change the energy
        _finding("joint a2 symptom", energy=True, kind="mass"),
        _finding("include arm.xml", root=True),  # a root cause that does not change the energy
        _finding("joint a3 symptom", energy=True, kind="com"),
        _finding("geom pole", root=True, energy=True, kind="ignored_construct"),
        _finding("joint a4 symptom", energy=True, kind="inertia"),
    ]
    page = _causes(ModelComparison("m.xml", None, findings=findings))
    shown = page.split('<ul class="causes">', 1)[1].split("</ul>", 1)[0]
    items = re.findall(r"<li>(.*?)</li>", shown)
    assert len(items) == SHOWN_CAUSES + 1 and items[-1] == "and 1 more"
    named = [re.search(r"<strong>(.*?)</strong>", i).group(1) for i in items[:-1]]
    assert named == ["geom pole", "joint a2 symptom", "joint a3 symptom"]
    assert "rounding" not in shown and "include arm.xml" not in shown
    folded = page.split("<details>", 1)[1]
    assert all(f"{e}: {e} differs" in folded for e in ("geom pole", "joint a4 symptom"))


def test_the_disagreement_is_not_a_paragraph_of_the_whole_reason(report) -> None:
    check, out, _, _ = report
    text = (out / "report.html").read_text(encoding="utf-8")
    k = next(k for k, c in enumerate(check.comparisons) if c.model == "class_mass.xml")
    section = text.split(f'id="model-class-mass-xml-{k}"', 1)[1].split("</section>", 1)[0]
    parity = next(p for p in check.agreements if p.model == "class_mass.xml")
    assert "DISAGREE" in section and html.escape(parity.reason) not in section
    assert section.count('<ul class="causes">') == 1 and "geom pole" in section.split('<ul class="causes">')[1]


def test_the_engine_gap_figure_is_beside_each_models_table(report) -> None:
    check, out, _, _ = report
    text = (out / "report.html").read_text(encoding="utf-8")
    sections = text.split('<section class="model"')[1:]
    assert len(sections) == len(check.comparisons)
    for section in sections:
        side = section.split('<div class="side">', 1)[1].split('<div class="wide">', 1)[0].split("</section>", 1)[0]
        assert "<table>" in side and "gap between the engines" in side
