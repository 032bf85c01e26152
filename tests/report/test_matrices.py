"""The two matrices report.html opens on: cells, links, colours derived from verdicts, the log colour scale.

Expected values come from other routes than the matrices' code: which engine departs from the engines' own mass
of the cart-pole's pole (MuJoCo, Pinocchio and, where installed, Drake read directly), each formula's largest
error from the records' values, the colour scale's order from the colours' luminance.
"""

from __future__ import annotations

import itertools
import math
import re
from html.parser import HTMLParser
from pathlib import Path

import mujoco
import numpy as np
import pinocchio
import pytest

import koenig_check
from koenig_check.engines.registry import label
from koenig_check.engines.specs import names
from koenig_check.report import write_report
from koenig_check.report.matrices import EXACT_COLOUR, GRAVITY, SCALE, VERDICTS, error_colour

CAUSES = Path(__file__).parents[1] / "models" / "causes"
MODELS = ["gimbal.xml", "serial7.urdf", CAUSES / "class_mass.xml", "no_such_robot"]


class _Matrices(HTMLParser):
    """Each matrix's header cells and rows (name, cells: class, style, href, value, text), and every id in the page."""

    def __init__(self) -> None:
        super().__init__()
        self.tables: dict[str, dict] = {}
        self.ids: dict[str, str] = {}
        self.sections: dict[str, dict] = {}
        self._table: dict | None = None
        self._thead = False
        self._row: dict | None = None
        self._cell: dict | None = None
        self._head: str | None = None
        self._section: str | None = None
        self._h2 = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: v or "" for k, v in attrs}
        if "id" in a:
            self.ids[a["id"]] = tag
        if tag == "section" and a.get("class") == "model":
            self._section = a["id"]
            self.sections[a["id"]] = {"h2": "", "open": None}
        if tag == "details" and self._section and self.sections[self._section]["open"] is None:
            self.sections[self._section]["open"] = "open" in a
        if tag == "h2" and self._section:
            self._h2 = True
        if tag == "table" and "matrix" in a.get("class", ""):
            self._table = self.tables.setdefault(a["class"].split()[-1], {"head": [], "rows": {}})
        if self._table is None:
            return
        if tag == "thead":
            self._thead = True
        elif tag == "tr" and not self._thead:
            self._row = {"name": None, "cells": []}
        elif tag == "th":
            self._head = ""
        elif tag == "td":
            self._cell = {"class": a.get("class", ""), "style": a.get("style", ""), "value": a.get("data-value")}
            self._cell.update(text="", href="")
        elif tag == "a" and self._cell is not None:
            self._cell["href"] = a.get("href", "")

    def handle_endtag(self, tag: str) -> None:
        if tag == "h2":
            self._h2 = False
        if tag == "section":
            self._section = None
        if self._table is None:
            return
        if tag == "thead":
            self._thead = False
        elif tag == "th" and self._head is not None:
            if self._thead:
                self._table["head"].append(self._head)
            elif self._row is not None:
                self._row["name"] = self._head
            self._head = None
        elif tag == "td" and self._cell is not None and self._row is not None:
            self._row["cells"].append(self._cell)
            self._cell = None
        elif tag == "tr" and self._row is not None:
            self._table["rows"][self._row["name"]] = self._row["cells"]
            self._row = None
        elif tag == "table":
            self._table = None

    def handle_data(self, data: str) -> None:
        if self._h2 and self._section:
            self.sections[self._section]["h2"] += data
        if self._cell is not None:
            self._cell["text"] += data
        elif self._head is not None:
            self._head += data


@pytest.fixture(scope="module")
def page(tmp_path_factory: pytest.TempPathFactory):
    check = koenig_check.compare(MODELS, n_poses=4, seed=3)
    out = tmp_path_factory.mktemp("matrices")
    write_report(out, check)
    parsed = _Matrices()
    parsed.feed((out / "report.html").read_text(encoding="utf-8"))
    parsed.close()
    return check, parsed


def test_one_row_per_model_and_one_column_per_engine_that_ran(page) -> None:
    check, parsed = page
    table = parsed.tables["engines"]
    labels = [label(e) for e in names()]
    columns = table["head"][1:]
    assert columns[-1] == GRAVITY  # the gravity verdict closes the row
    columns = columns[:-1]
    assert set(columns) <= set(labels) and columns == [c for c in labels if c in columns]  # registry order
    assert columns[:2] == [label(e) for e in check.comparisons[0].engines]  # the engines every model loads
    rows = table["rows"]
    assert list(rows) == [c.model for c in check.comparisons] + [m for m, _ in check.failures]
    assert all(len(cells) == len(columns) + 1 for cells in rows.values())


def _pole_masses() -> dict[str, float]:
    """The cart-pole's pole mass as each engine reads it, from the engines' own loaders."""
    path = str(CAUSES / "class_mass.xml")
    m = mujoco.MjModel.from_xml_path(path)
    masses = {"mujoco": float(m.body("pole").mass[0])}
    pm = pinocchio.buildModelFromMJCF(path)
    masses["pinocchio"] = float(pm.inertias[pm.getJointId("hinge")].mass)
    try:
        from pydrake.multibody.parsing import Parser
        from pydrake.multibody.plant import MultibodyPlant
    except ImportError:
        return masses
    plant = MultibodyPlant(0.0)
    text = Path(path).read_text().replace("<mujoco>", '<mujoco model="class_mass">')  # Drake asks for a name
    Parser(plant).AddModelsFromString(text, "xml")
    plant.Finalize()
    masses["drake"] = float(plant.GetBodyByName("pole").default_mass())
    return masses


def test_the_engine_that_departs_is_the_one_whose_mass_differs(page) -> None:
    _check, parsed = page
    masses = _pole_masses()
    table = parsed.tables["engines"]
    cells = dict(zip(table["head"][1:], table["rows"]["class_mass.xml"], strict=True))
    odd = [e for e in masses if sum(math.isclose(masses[e], v, rel_tol=1e-9) for v in masses.values()) == 1]
    if len(masses) >= 3:  # a third engine tells which one reads the file differently
        assert odd == ["pinocchio"]
        assert "departs" in cells[label("pinocchio")]["class"]
        assert all("agree" in cells[label(e)]["class"] for e in masses if e != "pinocchio")
    else:  # two engines: they differ, neither is named
        assert all("differs" in cells[label(e)]["class"] for e in masses)
    for e in ("gimbal.xml", "serial7.urdf"):
        assert all("agree" in c["class"] for c in table["rows"][e] if "not-run" not in c["class"])


def test_every_cell_links_to_its_models_section(page) -> None:
    check, parsed = page
    for name in ("engines", "errors"):
        table = parsed.tables[name]
        for row in table["rows"].values():
            for cell in row:
                target = cell["href"].removeprefix("#")
                assert parsed.ids.get(target) == "section", cell
    rows = parsed.tables["engines"]["rows"]
    for _k, comp in enumerate(check.comparisons):
        target = rows[comp.model][0]["href"].removeprefix("#")
        assert parsed.sections[target]["h2"] == comp.model
    assert rows["no_such_robot"][0]["href"] == "#failures" and "failures" in parsed.ids


def test_each_cell_has_its_verdicts_colour(page) -> None:
    _, parsed = page
    for row in parsed.tables["engines"]["rows"].values():
        for cell in row:
            verdict = cell["class"].removeprefix("cell ").replace("-", " ")
            assert f"background:{VERDICTS[verdict][0]}" in cell["style"], cell


def test_the_error_matrix_holds_each_formulas_largest_error_from_the_records(page) -> None:
    check, parsed = page
    table = parsed.tables["errors"]
    models = [c.model for c in check.comparisons]
    assert table["head"][1:] == models
    formulas = list(table["rows"])
    assert set(formulas) == {s.formula for s in check.summaries}
    r = check.records
    own = (r["scope"] == "total") & (r["source"] == r["reference"])
    for formula, row in table["rows"].items():
        for model, cell in zip(models, row, strict=True):
            mask = own & (r["formula"] == formula) & (r["model"] == model)
            if not mask.any():
                assert cell["value"] is None and cell["text"] == "—"
                continue
            value, ref = r["value"][mask], r["reference_value"][mask]
            expected = float(np.max(np.abs(value - ref) / np.abs(ref)))
            assert math.isclose(float(cell["value"]), expected, rel_tol=1e-9, abs_tol=1e-15), (formula, model)
            exact = expected <= check.rtol
            assert ("exact" in cell["class"]) == exact
            assert (f"background:{EXACT_COLOUR}" in cell["style"]) == exact


def _luminance(colour: str) -> float:
    r, g, b = (int(colour[i : i + 2], 16) for i in (1, 3, 5))
    return 0.299 * r + 0.587 * g + 0.114 * b


def test_the_colour_scale_darkens_with_the_logarithm_of_the_error() -> None:
    errors = np.logspace(math.log10(SCALE[0]), math.log10(SCALE[1]), 49)
    shades = [_luminance(error_colour(float(e))) for e in errors]
    assert all(a > b for a, b in itertools.pairwise(shades))  # strictly darker as the error grows
    assert error_colour(SCALE[0] / 10) == error_colour(SCALE[0]) and error_colour(10.0) == error_colour(1.0)
    # a decade costs about the same change of shade at 1e-11 and at 1e-7 (log scale), not a thousandth of it
    low = shades[0] - shades[4]
    mid = shades[16] - shades[20]
    assert 0.2 < low / mid < 5


def test_cells_of_the_error_matrix_are_ordered_like_their_errors(page) -> None:
    _, parsed = page
    cells = [
        c for row in parsed.tables["errors"]["rows"].values() for c in row if c["value"] and "exact" not in c["class"]
    ]
    assert len(cells) >= 5
    shade = {float(c["value"]): _luminance(re.search(r"background:(#\w{6})", c["style"]).group(1)) for c in cells}
    ordered = [shade[v] for v in sorted(shade)]
    assert all(a >= b for a, b in itertools.pairwise(ordered))


def test_models_that_agree_are_folded_and_the_others_open(page) -> None:
    check, parsed = page
    for k, comp in enumerate(check.comparisons):
        section = next(s for s in parsed.sections.values() if s["h2"] == comp.model)
        agrees = check.agreements[k].agrees and comp.model != "class_mass.xml"
        assert section["open"] is (not agrees), comp.model


def test_the_gravity_column_says_whether_the_engines_read_the_same_gravity(tmp_path: Path) -> None:
    """On the moon fixture MuJoCo reads the file's gravity and Pinocchio its default (each read directly): the
    gravity cell differs and names the cause; on gimbal.xml (the default gravity, written by nobody) it agrees."""
    from koenig_check.causes import cause, fixture_path

    moon = fixture_path(cause("pinocchio.mjcf.option-gravity"))
    read = {
        "mujoco": mujoco.MjModel.from_xml_path(str(moon)).opt.gravity,
        "pinocchio": pinocchio.buildModelFromMJCF(str(moon)).gravity.linear,
    }
    assert not np.allclose(read["mujoco"], read["pinocchio"])  # an independent reading: the engines differ
    check = koenig_check.compare([str(moon), "gimbal.xml"], n_poses=4, seed=3)
    write_report(tmp_path, check)
    parsed = _Matrices()
    parsed.feed((tmp_path / "report.html").read_text(encoding="utf-8"))
    table = parsed.tables["engines"]
    gravity = {model: cells[table["head"][1:].index(GRAVITY)] for model, cells in table["rows"].items()}
    moon_cell, gimbal_cell = gravity[check.comparisons[0].model], gravity["gimbal.xml"]
    assert "differs" in moon_cell["class"] and moon_cell["style"] == f"background:{VERDICTS['differs'][0]}"
    assert "agree" in gimbal_cell["class"] and gimbal_cell["text"].strip() == "0"
    assert "causes pinocchio.mjcf.option-gravity" in (tmp_path / "report.html").read_text(encoding="utf-8")
