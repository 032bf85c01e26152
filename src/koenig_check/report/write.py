"""The report directory: ``summary.md``, ``report.html``, ``records.json``, the record files and the figures."""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from koenig_check.report.content import run_conditions
from koenig_check.report.engine_energies import EngineEnergies, energy_chunks, engine_energies
from koenig_check.report.markdown import summary_markdown
from koenig_check.report.record_files import RecordFiles
from koenig_check.run.comparison import ModelComparison
from koenig_check.run.records import RECORD_FIELDS, RecordTable
from koenig_check.run.summaries import EngineAgreement, FormulaSummary

if TYPE_CHECKING:
    from koenig_check.run.cross_check import CrossCheck


def _jsonable(x: Any) -> Any:
    if isinstance(x, float) and not np.isfinite(x):
        return str(x)
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.generic):
        return _jsonable(x.item())
    return x


def write_json(
    path: Path,
    records: RecordTable | None,
    summaries: Sequence[FormulaSummary],
    agreements: Sequence[EngineAgreement],
    failures: Sequence[tuple[str, str]] = (),
    extra: dict[str, Any] | None = None,
) -> Path:
    """Write records, summaries, parity and failures as one JSON document.

    Records are stored as rows (lists) in the order of ``record_fields``, to keep the
    file small; summaries, parity and failures are objects.  Without records (a large run, whose
    records are in ``records.parquet``) the document has ``"records": null``.

    Parameters
    ----------
    path : Path
    records : RecordTable or None
    summaries : sequence of FormulaSummary
    agreements : sequence of EngineAgreement
    failures : sequence of (model, reason)
    extra : dict, optional
        Anything else to store (e.g. load notes).

    Returns
    -------
    Path
    """
    doc = {
        "record_fields": list(RECORD_FIELDS),
        "records": records.rows() if records is not None else None,
        "summaries": [asdict(s) for s in summaries],
        "parity": [asdict(p) for p in agreements],
        "failures": [{"model": m, "reason": r} for m, r in failures],
        **(extra or {}),
    }
    path.write_text(json.dumps(_jsonable(doc), separators=(",", ":")), encoding="utf-8")
    return path


def figure_name(model: str, kind: str = "error_distribution") -> str:
    """The file name of a model's figure (``error_distribution_<model>.png``, ``engine_gap_<model>.png``)."""
    slug = re.sub(r"[^A-Za-z0-9._-]+", "_", model).strip("_")
    return f"{kind}_{slug}.png"


def write_report(
    out: Path,
    check: CrossCheck,
    grid_comparison: ModelComparison | None = None,
    trajectory_comparison: ModelComparison | None = None,
    map_formulas: Sequence[str] = ("koenig_world", "alyushin_paper:rotvec", "alyushin_paper:euler_xyz"),
    trajectory_formulas: Sequence[str] = (
        "exact",
        "koenig_world",
        "alyushin_paper:rotvec",
        "alyushin_paper:euler_xyz",
        "alyushin_paper:integrated",
    ),
    records: RecordFiles | None = None,
) -> list[Path]:
    """Write the report directory: summary.md, report.html, records.json, the record files and the figures.

    Figures: ``error_distribution_<model>.png`` and ``engine_gap_<model>.png`` (the engines' energy difference
    at each pose; from the records kept, else from the record files) per model, ``error_distribution.png`` pooled
    over the models (labelled so, with the models named) when there are several, ``error_map.png`` for a grid sweep and
    ``trajectory_energy.png`` for a trajectory.  ``report.html`` embeds them all.

    Parameters
    ----------
    out : Path
        Created if missing.
    check : CrossCheck
    grid_comparison : ModelComparison, optional
        A two-joint grid sweep: adds ``error_map.png``.
    trajectory_comparison : ModelComparison, optional
        A simulated trajectory: adds ``trajectory_energy.png``.
    map_formulas, trajectory_formulas : sequence of str
        Formulas drawn in those figures.
    records : RecordFiles, optional
        The record files the run streamed into (closed here).  Without it, the records the
        check holds in memory are written to ``records.parquet`` (and ``records.csv`` for a small run).

    Returns
    -------
    list of Path
        Every file written.
    """
    from koenig_check.report.figures import (
        engine_gap_figure,
        error_distribution_figure,
        error_map_figure,
        trajectory_figure,
    )
    from koenig_check.report.html import report_html

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if records is None:
        records = RecordFiles(out)
        for comp in check.comparisons:
            records.write(comp.records.table)
    written = [
        _write_text(
            out / "summary.md",
            summary_markdown(
                check.comparisons, check.summaries, check.agreements, check.failures, check.rtol, check.settings
            ),
        ),
        *records.close(),
    ]
    written.append(
        write_json(
            out / "records.json",
            records.small,
            check.summaries,
            check.agreements,
            check.failures,
            extra={
                "rtol": check.rtol,
                "records_file": records.parquet.name,
                "record_count": records.rows,
                "notes": {c.model: c.notes for c in check.comparisons},
                "refusals": [r for c in check.comparisons for r in c.refusals],
                "settings": check.settings,
            },
        )
    )
    figures: dict[int | None, list[tuple[Path, str]]] = {}  # by position in check.comparisons; None: the run
    with_stats = [c for c in check.comparisons if c.stats is not None and c.stats.kept_groups()]
    names: set[str] = set()
    for k, comp in enumerate(check.comparisons):
        if comp not in with_stats:
            continue
        name = figure_name(comp.model)
        while name in names:  # two comparisons with one label: both figures kept
            name = name.replace(".png", "_.png")
        names.add(name)
        caption = run_conditions(comp, check.settings.get(comp.model))
        path = error_distribution_figure([comp], out / name, check.rtol, caption)
        figures.setdefault(k, []).append(
            (path, f"{comp.model}: relative error of each formula's total energy. {caption}.")
        )
        energies = _energies(check, k, records)
        if energies is not None and len(energies.energy) > 1:
            path = engine_gap_figure(
                comp.model, energies, out / name.replace("error_distribution", "engine_gap", 1), check.rtol, caption
            )
            figures[k].append(
                (path, f"{comp.model}: gap between the engines' rigid-body energies at each pose. {caption}.")
            )
    if len(with_stats) > 1:
        pooled = ", ".join(c.model for c in with_stats)
        caption = f"pooled over {len(with_stats)} models ({pooled}); each model's own figure is in its section"
        # The figure's own title names the pooled models; its caption only points to the per-model figures.
        path = error_distribution_figure(
            with_stats, out / "error_distribution.png", check.rtol, "each model's own figure is in its section"
        )
        figures.setdefault(None, []).append((path, f"Relative error of each formula, {caption}."))
    if grid_comparison is not None:
        caption = run_conditions(grid_comparison, check.settings.get(grid_comparison.model))
        path = error_map_figure(grid_comparison, map_formulas, out / "error_map.png", caption=caption)
        figures.setdefault(_position(check, grid_comparison), []).append(
            (path, f"Signed relative error over the two joint angles (MuJoCo), one colour scale. {caption}.")
        )
    if trajectory_comparison is not None:
        caption = run_conditions(trajectory_comparison, check.settings.get(trajectory_comparison.model))
        path = trajectory_figure(
            trajectory_comparison, trajectory_formulas, out / "trajectory_energy.png", check.rtol, caption
        )
        figures.setdefault(_position(check, trajectory_comparison), []).append(
            (path, f"Kinetic energy along the trajectory and each formula's error. {caption}.")
        )
    written += [path for items in figures.values() for path, _ in items]
    written.append(_write_text(out / "report.html", report_html(check, figures)))
    return written


def _energies(check: CrossCheck, k: int, records: RecordFiles) -> EngineEnergies | None:
    """Each engine's energy per pose for comparison ``k``: from its own records, else from the record files."""
    comp = check.comparisons[k]
    if len(comp.records):
        return engine_energies(energy_chunks(comp.records), comp.model, comp.engines, comp.n_poses)
    earlier = sum(c.n_poses for c in check.comparisons[:k] if c.model == comp.model)  # same label, run before
    return engine_energies(records.energies, comp.model, comp.engines, comp.n_poses, skip=earlier)


def _position(check: CrossCheck, comparison: ModelComparison) -> int | None:
    """Where a comparison stands in the check (None when it is not one of them: shown with the whole run)."""
    for k, comp in enumerate(check.comparisons):
        if comp is comparison:
            return k
    return None


def _write_text(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path
