"""The report's figures: error distributions per model (or labelled pooled), the error map, the trajectory.

Conventions: relative errors on a log axis from :data:`~koenig_check.roundoff.ROUNDOFF` up; values below it
(exact to rounding) are drawn in a band of their own at the left, labelled, never as box-plot outliers; the
tolerance is a dashed line; panels that are compared share one colour scale; the conditions of the run
(poses, seed, joint rates, gravity) are in the title.

Text sizes: the per-model figures are shown in report.html in a column of about 580 CSS px at a 1280 px
window, so they are :data:`SIDE_WIDTH` inches wide and no text is smaller than :data:`MIN_FONT` points
(about 10 px there).  Every PNG carries the size of its smallest text in pixels of the PNG (the tEXt key
:data:`MIN_FONT_KEY`), so that the page can be checked at its display size.
"""

from __future__ import annotations

import textwrap
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.figure import Figure
from matplotlib.text import Text
from matplotlib.ticker import MaxNLocator

from koenig_check.engines.specs import reference as reference_engine
from koenig_check.engines.specs import spec
from koenig_check.report.engine_energies import EngineEnergies
from koenig_check.roundoff import ROUNDOFF, fmt
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.stats import QuantileSketch, relative_error


def engine_color(engine: str) -> str:
    """An engine's colour, the same in every figure (declared in its spec, :mod:`koenig_check.engines.specs`).

    Parameters
    ----------
    engine : str

    Returns
    -------
    str
        A Matplotlib colour; grey for a name no engine has.
    """
    try:
        return spec(engine).color
    except KeyError:
        return "tab:gray"


#: Where the rounding band is drawn (log10 units), left of the axis proper.
_BAND = np.log10(ROUNDOFF) - 2.0
#: Width (inches) of the figures shown beside a model's table in report.html.
SIDE_WIDTH = 6.4
#: The smallest font size (points) of any text in a figure.
MIN_FONT = 9.0
#: PNG text key holding the size of the figure's smallest text, in pixels of the PNG.
MIN_FONT_KEY = "koenig-check:min-font-px"


def smallest_text_px(fig: Figure, dpi: float) -> float:
    """The font size of the smallest visible, non-empty text of a figure, in pixels at ``dpi``.

    Parameters
    ----------
    fig : Figure
    dpi : float

    Returns
    -------
    float
    """
    sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    return float(min(sizes)) * dpi / 72.0 if sizes else float("inf")


def _save(fig: Figure, path: Path, dpi: int) -> Path:
    """Write the PNG with the size of its smallest text in its metadata (:data:`MIN_FONT_KEY`)."""
    fig.savefig(path, dpi=dpi, metadata={MIN_FONT_KEY: f"{smallest_text_px(fig, dpi):.3f}"})
    return path


def _sketches(comparisons: Sequence[ModelComparison]) -> dict[tuple[str, str], QuantileSketch]:
    pooled: dict[tuple[str, str], QuantileSketch] = {}
    for comp in comparisons:
        if comp.stats is None:
            continue
        for (formula, source, reference), g in comp.stats.kept_groups().items():
            if source == reference:
                pooled.setdefault((formula, source), QuantileSketch()).merge(g.sketch)
    return pooled


def _position(x: float) -> float:
    """log10 of a relative error, or the rounding band for values below ROUNDOFF."""
    return _BAND if x < ROUNDOFF else float(np.log10(x))


def _draw_boxes(ax: Any, boxes: np.ndarray, color: str, height: float = 0.3) -> None:
    """Horizontal box plots, one per row of ``boxes`` = (y, min, q1, median, q3, max): three collections.

    The same drawing as ``Axes.bxp`` (quartile box, median line, whiskers to min and max with caps),
    as one collection per kind instead of six artists per box: a figure of ~20 boxes draws in half the time.
    """
    y, lo, q1, med, q3, hi = boxes.T
    top, bottom = y - height / 2, y + height / 2
    rects = np.stack([np.c_[q1, top], np.c_[q3, top], np.c_[q3, bottom], np.c_[q1, bottom]], axis=1)
    # matplotlib's stubs ask for a Sequence; an (N, k, 2) array is what its collections take fastest.
    ax.add_collection(
        PolyCollection(rects, facecolors=color, alpha=0.6, edgecolors="black", linewidths=0.8)  # type: ignore[arg-type]
    )
    caps = height / 4
    whiskers = np.concatenate(
        [
            np.stack([np.c_[lo, y], np.c_[q1, y]], axis=1),
            np.stack([np.c_[q3, y], np.c_[hi, y]], axis=1),
            np.stack([np.c_[lo, y - caps], np.c_[lo, y + caps]], axis=1),
            np.stack([np.c_[hi, y - caps], np.c_[hi, y + caps]], axis=1),
        ]
    )
    ax.add_collection(LineCollection(whiskers, colors="black", linewidths=0.8))  # type: ignore[arg-type]  # as above
    medians = np.stack([np.c_[med, top], np.c_[med, bottom]], axis=1)
    ax.add_collection(LineCollection(medians, colors="black", linewidths=1.2))  # type: ignore[arg-type]  # as above


def error_distribution_figure(
    comparisons: Sequence[ModelComparison], path: Path, rtol: float, caption: str = "", dpi: int = 110
) -> Path:
    """Distribution of the relative error of each formula's total energy, per engine, on a log axis.

    Boxes span the quartiles, whiskers the minimum and maximum; a formula exact to rounding on every pose
    (maximum below :data:`ROUNDOFF`) is one marker in the rounding band; box parts below ROUNDOFF are drawn
    in the band too.  The dashed line is the tolerance.  With several comparisons the title says the data
    are pooled and names the models.

    Parameters
    ----------
    comparisons : sequence of ModelComparison
        One model, or several pooled.
    path : Path
    rtol : float
    caption : str
        Conditions of the run, printed under the title.
    dpi : int

    Returns
    -------
    Path
    """
    pooled = _sketches(comparisons)
    formulas = list(dict.fromkeys(f for f, _ in pooled))
    engines = list(dict.fromkeys(e for _, e in pooled))
    fig = Figure(figsize=(SIDE_WIDTH, 0.36 * max(len(formulas), 4) + 2.4), layout="constrained")
    ax = fig.add_subplot()
    top = max([_position(s.quantile(1.0)) for s in pooled.values() if s.n] + [np.log10(rtol) + 1, 0.0])
    for k, engine in enumerate(engines):
        color = engine_color(engine)
        offset = (k - (len(engines) - 1) / 2) * 0.36
        boxes, exact = [], []  # boxes: (row, min, q1, median, q3, max) in axis units
        for i, f in enumerate(formulas):
            sketch = pooled.get((f, engine))
            if sketch is None or not sketch.n:
                continue
            q = [_position(sketch.quantile(x)) for x in (0.0, 0.25, 0.5, 0.75, 1.0)]
            if q[4] == _BAND:
                exact.append(i + offset)
                continue
            boxes.append((i + offset, *q))
        if boxes:
            _draw_boxes(ax, np.array(boxes), color)
        if exact:
            ax.plot([_BAND] * len(exact), exact, "o", color=color, markersize=7, markeredgecolor="black")
        ax.plot([], [], "s", color=color, alpha=0.6, markersize=10, label=f"{engine} states vs {engine} energy")
    ax.axvspan(_BAND - 0.6, _BAND + 0.6, color="0.92", zorder=0)
    ax.axvline(np.log10(rtol), color="tab:red", linestyle="--", linewidth=1.2, label=f"tolerance {rtol:g}")
    ax.set_xlim(_BAND - 0.8, top + 0.3)
    ticks = list(range(int(np.ceil(np.log10(ROUNDOFF))), int(np.floor(top)) + 1, 2))
    ax.set_xticks([_BAND, *ticks], [f"< {ROUNDOFF:g}\n(rounding)", *[f"1e{t}" for t in ticks]])
    ax.set_yticks(np.arange(len(formulas)), formulas, fontsize=MIN_FONT)
    ax.tick_params(axis="x", labelsize=MIN_FONT)
    ax.set_ylim(len(formulas) - 0.5, -0.5)
    ax.set_xlabel("relative error of the total energy\n|formula − engine| / engine (log scale)", fontsize=MIN_FONT)
    models = [c.model for c in comparisons]
    if len(models) == 1:
        title = f"{models[0]}: relative error of each formula"
    else:
        title = textwrap.fill(f"Pooled over {len(models)} models ({', '.join(models)}): relative error", 70)
    sub = "boxes: quartiles; whiskers: min and max over the poses;\ndots: exact to rounding on every pose"
    # A figure title (centred on the figure, not on the axes beside the long formula names): it fits the width.
    fig.suptitle(f"{title}\n{sub}" + (f"\n{textwrap.fill(caption, 70)}" if caption else ""), fontsize=MIN_FONT)
    fig.legend(loc="outside lower center", ncol=2, frameon=False, fontsize=MIN_FONT)
    ax.grid(True, axis="x", alpha=0.3)
    return _save(fig, path, dpi)


#: Most points drawn per engine in the engine-gap figure; beyond, each point is the largest gap of a block of poses.
GAP_POINTS = 5000


def _block_maxima(values: np.ndarray, block: int) -> np.ndarray:
    """Index of the largest value in each run of ``block`` consecutive values (every index when ``block`` is 1)."""
    if block <= 1:
        return np.arange(values.size)
    padded = np.full(-(-values.size // block) * block, -np.inf)
    padded[: values.size] = values
    return padded.reshape(-1, block).argmax(axis=1) + np.arange(padded.size // block) * block


def engine_gap_figure(
    model: str, energies: EngineEnergies, path: Path, rtol: float, caption: str = "", dpi: int = 110
) -> Path:
    """The gap between the engines at each pose: ``|E_engine − E_MuJoCo| / |E_MuJoCo|`` on a log axis.

    One series of points per engine other than MuJoCo, in pose order; gaps below :data:`ROUNDOFF` (the
    engines agree to rounding) are drawn in a band of their own at the bottom; the tolerance is a dashed line.

    Parameters
    ----------
    model : str
        The model's label (in the title).
    energies : EngineEnergies
        Each engine's rigid-body energy per pose.
    path : Path
    rtol : float
    caption : str
        Conditions of the run, printed under the title.
    dpi : int

    Returns
    -------
    Path
    """
    others = [e for e in energies.energy if e != reference_engine()]  # each engine's gap to the reference (MuJoCo)
    gaps = {e: energies.gap(e) for e in others}
    n = len(energies.poses)
    fig = Figure(figsize=(SIDE_WIDTH, 3.6), layout="constrained")
    ax = fig.add_subplot()
    shown = [g[np.isfinite(g) & (g >= ROUNDOFF)] for g in gaps.values()]
    top = max([float(np.log10(g).max()) for g in shown if g.size] + [np.log10(rtol) + 1, 0.0])
    block = -(-n // GAP_POINTS)  # poses per point: 1 up to GAP_POINTS poses
    size = 4.0 if n <= 200 else 1.5
    for engine, gap in gaps.items():
        x = _block_maxima(np.nan_to_num(gap, nan=np.inf), block)
        y = np.where(gap[x] < ROUNDOFF, _BAND, np.log10(np.clip(gap[x], ROUNDOFF, 10.0**top)))
        worst = int(np.argmax(np.nan_to_num(gap, nan=np.inf)))
        largest = fmt(float(gap[worst]), ".2g") if n else ""  # below ROUNDOFF: 0, as everywhere in the report
        label = f"{engine} vs mujoco: largest {largest} at {energies.poses[worst]}" if n else engine
        color = engine_color(engine)
        ax.plot(x, y, "o", color=color, markersize=size, markeredgewidth=0, label=label, rasterized=n > 2000)
    ax.axhspan(_BAND - 0.6, _BAND + 0.6, color="0.92", zorder=0)
    ax.axhline(np.log10(rtol), color="tab:red", linestyle="--", linewidth=1.2, label=f"tolerance {rtol:g}")
    ax.set_ylim(_BAND - 0.8, top + 0.3)
    ticks = list(range(int(np.ceil(np.log10(ROUNDOFF))), int(np.floor(top)) + 1, 2))
    ax.set_yticks([_BAND, *ticks], [f"< {ROUNDOFF:g}\n(rounding)", *[f"1e{t}" for t in ticks]])
    ax.tick_params(labelsize=MIN_FONT)
    ax.set_xlim(-0.5, max(n, 1) - 0.5)
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    first, last = (energies.poses[0], energies.poses[-1]) if n else ("", "")
    each = f"; each point: the largest of {block} consecutive poses" if block > 1 else ""
    ax.set_xlabel(f"pose, in run order ({first} … {last}){each}", fontsize=MIN_FONT)
    ax.set_ylabel("|E − E_mujoco| / |E_mujoco|\n(log scale)", fontsize=MIN_FONT)
    title = f"{model}: gap between the engines' rigid-body energies per pose"
    ax.set_title(title + (f"\n{textwrap.fill(caption, 70)}" if caption else ""), fontsize=MIN_FONT)
    fig.legend(loc="outside lower center", ncol=1, frameon=False, fontsize=MIN_FONT)
    ax.grid(True, axis="y", alpha=0.3)
    return _save(fig, path, dpi)


def error_map_figure(
    comparison: ModelComparison,
    formulas: Sequence[str],
    path: Path,
    engine: str | None = None,
    caption: str = "",
    dpi: int = 110,
) -> Path:
    """Signed relative error of formulas over a two-joint grid sweep, one colour scale for every panel.

    Parameters
    ----------
    comparison : ModelComparison
        Built on a grid :class:`~koenig_check.run.poses.PoseSet`.
    formulas : sequence of str
    path : Path
    engine : str, optional
        Whose states and energy are used; default: the reference engine (MuJoCo).
    caption : str
        Conditions of the run (joint rates), printed in the title.
    dpi : int

    Returns
    -------
    Path
    """
    engine = engine or reference_engine()
    grid = comparison.poses.grid if comparison.poses is not None else None
    if grid is None:
        raise ValueError(f"{comparison.model}: the poses are not a grid sweep")
    shape = grid["shape"]
    va, vb = grid["values"]
    ja, jb = grid["joints"]
    signed = {}
    for formula in formulas:
        rows = comparison.records.where(formula=formula, scope="total", source=engine, reference=engine)
        signed[formula] = relative_error(rows["value"], rows["reference_value"]).reshape(shape)
    lim = max([float(np.abs(v).max()) for v in signed.values()] + [ROUNDOFF])
    fig = Figure(figsize=(4.0 * len(formulas) + 1.2, 4.6), layout="constrained")
    axes = [fig.add_subplot(1, len(formulas), k + 1) for k in range(len(formulas))]
    mesh = None
    for ax, formula in zip(axes, formulas, strict=True):
        mesh = ax.pcolormesh(
            np.degrees(vb), np.degrees(va), signed[formula], cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto"
        )
        ax.set_xlabel(f"{jb} angle (deg)")
        ax.set_title(formula, fontsize=10)
    axes[0].set_ylabel(f"{ja} angle (deg)")
    if mesh is not None:
        fig.colorbar(mesh, ax=axes, label="signed relative error\n(formula − engine) / engine")
    title = (
        f"{comparison.model}: signed relative error over the two joint angles ({engine} states and energy; "
        "one colour scale for all panels)"
    )
    fig.suptitle(title + (f"\n{textwrap.fill(caption, 130)}" if caption else ""), fontsize=10)
    return _save(fig, path, dpi)


def trajectory_figure(
    comparison: ModelComparison, formulas: Sequence[str], path: Path, rtol: float, caption: str = "", dpi: int = 110
) -> Path:
    """Kinetic energy along a simulated trajectory for each formula against both engines.

    Parameters
    ----------
    comparison : ModelComparison
        Built on a trajectory :class:`~koenig_check.run.poses.PoseSet`.
    formulas : sequence of str
    path : Path
    rtol : float
        Drawn as a band around zero in the error panel.
    caption : str
        Conditions of the run (duration, gravity off, seed).
    dpi : int

    Returns
    -------
    Path
    """
    times = comparison.poses.times if comparison.poses is not None else None
    if times is None:
        raise ValueError(f"{comparison.model}: the poses are not a trajectory")
    fig = Figure(figsize=(10, 7), layout="constrained")
    ax, ax_err = fig.add_subplot(2, 1, 1), fig.add_subplot(2, 1, 2)
    energy = {
        engine: comparison.records.where(formula="exact", scope="total", source=engine, reference=engine)[
            "reference_value"
        ]
        for engine in comparison.engines
    }
    for engine, rigid in energy.items():
        if len(rigid):
            ax.plot(times, rigid, linewidth=4, alpha=0.4, color=engine_color(engine), label=f"{engine} energy")
    first = reference_engine()  # the formulas are evaluated on its states, against its energy
    mj = energy.get(first, np.empty(0))
    palette = dict(zip(formulas, (f"C{k + 2}" for k in range(10)), strict=False))
    for formula in formulas:
        rows = comparison.records.where(formula=formula, scope="total", source=first, reference=first)
        if not len(rows):
            continue
        value = rows["value"]
        ax.plot(times, value, linewidth=1.2, color=palette.get(formula), label=formula)
        ax_err.plot(times, relative_error(value, mj), linewidth=1.2, color=palette.get(formula), label=formula)
    ax_err.axhspan(-rtol, rtol, color="tab:red", alpha=0.3, label=f"tolerance ±{rtol:g}")
    ax.set_ylabel("kinetic energy (J)")
    title = f"{comparison.model}: kinetic energy along a torque-free MuJoCo trajectory, gravity off"
    ax.set_title(title + (f"\n{textwrap.fill(caption, 120)}" if caption else ""), fontsize=10)
    ax.legend(fontsize=MIN_FONT, ncol=2)
    ax.grid(True, alpha=0.3)
    ax_err.set_xlabel("time (s)")
    ax_err.set_ylabel("signed relative error vs MuJoCo")
    ax_err.set_title("(formula − engine) / engine, on MuJoCo's states", fontsize=9)
    ax_err.legend(fontsize=MIN_FONT, ncol=2)
    ax_err.grid(True, alpha=0.3)
    return _save(fig, path, dpi)
