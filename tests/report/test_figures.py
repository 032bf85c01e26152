"""Figures: per model or labelled pooled, exact values in the rounding band, tolerance drawn, one colour scale,
run conditions in the titles."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from matplotlib.figure import Figure

import koenig_check
from koenig_check.api import compare_model
from koenig_check.report import figures
from koenig_check.roundoff import ROUNDOFF


@pytest.fixture
def drawn(monkeypatch: pytest.MonkeyPatch) -> list[Figure]:
    """Capture every figure instead of writing it."""
    kept: list[Figure] = []
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: kept.append(self))
    return kept


@pytest.fixture(scope="module")
def two_models():
    return koenig_check.compare(["gimbal.xml", "serial7.urdf"], n_poses=6, seed=2)


def _title(fig: Figure) -> str:
    return " ".join(ax.get_title() for ax in fig.axes) + (fig._suptitle.get_text() if fig._suptitle else "")


def test_one_model_figure_is_titled_with_the_model_and_not_pooled(two_models, drawn, tmp_path: Path) -> None:
    comp = two_models.comparisons[0]
    figures.error_distribution_figure([comp], tmp_path / "a.png", rtol=1e-9, caption="6 random poses; seed 2")
    title = _title(drawn[0])
    assert title.startswith("gimbal.xml:") and "ooled" not in title and "seed 2" in title


def test_pooled_figure_says_so_and_names_every_model(two_models, drawn, tmp_path: Path) -> None:
    figures.error_distribution_figure(two_models.comparisons, tmp_path / "a.png", rtol=1e-9)
    title = _title(drawn[0])
    assert "Pooled over 2 models" in title and "gimbal.xml" in title and "serial7.urdf" in title


def test_exact_formulas_are_dots_in_the_rounding_band_and_tolerance_is_drawn(two_models, drawn, tmp_path: Path) -> None:
    comp = two_models.comparisons[0]
    figures.error_distribution_figure([comp], tmp_path / "a.png", rtol=1e-9)
    ax = drawn[0].axes[0]
    labels = [t.get_text() for t in ax.get_yticklabels()]
    dots = [line for line in ax.get_lines() if line.get_marker() == "o" and len(line.get_xdata())]
    band = np.log10(ROUNDOFF) - 2.0
    exact_rows = {labels.index("exact"), labels.index("koenig_principal")}
    dot_rows = {round(y) for line in dots for y in line.get_ydata()}
    assert exact_rows <= dot_rows and all(np.allclose(line.get_xdata(), band) for line in dots)
    assert labels.index("koenig_world") not in dot_rows  # an inexact formula is a box, not a dot
    tolerance = [line for line in ax.get_lines() if line.get_linestyle() == "--"]
    assert tolerance and np.allclose(tolerance[0].get_xdata(), np.log10(1e-9))
    assert min(ax.get_xlim()) < band < np.log10(ROUNDOFF)  # the band is left of the axis proper


def test_error_map_panels_share_one_colour_scale_and_state_the_joint_rates(drawn, tmp_path: Path) -> None:
    comp = compare_model("gimbal.xml", pose_kind="grid", grid_joints=("outer_z", "inner_x"), n_poses=7)
    from koenig_check.report.content import run_conditions

    caption = run_conditions(comp)
    forms = ("koenig_world", "alyushin_paper:rotvec")
    figures.error_map_figure(comp, forms, tmp_path / "m.png", caption=caption)
    from matplotlib.collections import QuadMesh

    meshes = [c for ax in drawn[0].axes[: len(forms)] for c in ax.collections if isinstance(c, QuadMesh)]
    limits = {(m.norm.vmin, m.norm.vmax) for m in meshes}
    assert len(meshes) == 2 and len(limits) == 1
    vmin, vmax = limits.pop()
    largest = max(float(np.abs(m.get_array()).max()) for m in meshes)
    assert vmax == pytest.approx(largest) and vmin == -vmax
    assert "1 rad/s" in _title(drawn[0]) and "outer_z × inner_x" in _title(drawn[0])


def test_trajectory_title_says_gravity_off(drawn, tmp_path: Path) -> None:
    comp = compare_model("gimbal.xml", pose_kind="trajectory", n_poses=20, duration=0.5)
    figures.trajectory_figure(comp, ("exact", "koenig_world"), tmp_path / "t.png", rtol=1e-9)
    assert "gravity off" in _title(drawn[0])


def test_boxes_span_the_quartiles_and_whiskers_reach_min_and_max(two_models, drawn, tmp_path: Path) -> None:
    from matplotlib.collections import LineCollection, PolyCollection

    comp = two_models.comparisons[0]
    figures.error_distribution_figure([comp], tmp_path / "a.png", rtol=1e-9)
    ax = drawn[0].axes[0]
    labels = [t.get_text() for t in ax.get_yticklabels()]
    row = labels.index("koenig_world")
    # Independent route: the relative errors of the records, not the sketch the figure reads.
    rows = comp.records.where(formula="koenig_world", source="mujoco", reference="mujoco", scope="total")
    err = np.abs(rows["value"] - rows["reference_value"]) / np.abs(rows["reference_value"])
    lo, q1, med, q3, hi = np.log10(np.quantile(err, [0, 0.25, 0.5, 0.75, 1]))
    polys = [c for c in ax.collections if isinstance(c, PolyCollection)]
    boxes = [p.vertices for c in polys for p in c.get_paths()]
    middle = [(v[:, 1].min() + v[:, 1].max()) / 2 for v in boxes]
    box = boxes[int(np.argmin(np.abs(np.array(middle) - (row - 0.18))))]  # mujoco's box sits above the row
    assert abs((box[:, 1].min() + box[:, 1].max()) / 2 - (row - 0.18)) < 1e-9
    np.testing.assert_allclose([box[:, 0].min(), box[:, 0].max()], [q1, q3], atol=1e-9)
    segments = [s for c in ax.collections if isinstance(c, LineCollection) for s in c.get_segments()]
    at_row = [s for s in segments if np.allclose(s[:, 1].mean(), row - 0.18)]
    xs = np.concatenate([s[:, 0] for s in at_row])
    np.testing.assert_allclose([xs.min(), xs.max()], [lo, hi], atol=1e-9)
    assert any(np.allclose(s[:, 0], med, atol=1e-9) for s in at_row)  # the median line


def test_report_pooled_figure_names_each_model_once(
    two_models, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    from koenig_check.report import write_report

    drawn: list[Figure] = []
    save = Figure.savefig
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: (drawn.append(self), save(self, *a, **k))[1])
    write_report(tmp_path / "r", two_models)
    pooled = [fig for fig in drawn if "Pooled over" in _title(fig)]
    assert len(pooled) == 1
    assert _title(pooled[0]).count("serial7.urdf") == 1 and "own figure" in _title(pooled[0])
