"""The engine-gap figure: the engines' energy difference at each pose, on a log axis, with the tolerance.

Expected values come from another route than the figure's: the figure reads each engine's own energy
(``reference_value`` of the records); the tests recompute the gap from ``exact`` evaluated on each engine's
segment states (the records' ``value``), which equals that engine's energy to rounding on these models, and
from the parity statistics, computed from the engine runs before any record is written.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from matplotlib.figure import Figure
from PIL import Image

import koenig_check
from koenig_check.api import CrossCheck, compare_model
from koenig_check.report import RecordFiles, write_report
from koenig_check.report import figures as figure_module
from koenig_check.report.engine_energies import EngineEnergies, energy_chunks, engine_energies
from koenig_check.roundoff import ROUNDOFF

CAUSES = Path(__file__).parents[1] / "models" / "causes"
BAND = np.log10(ROUNDOFF) - 2.0
RTOL = 1e-9


@pytest.fixture
def drawn(monkeypatch: pytest.MonkeyPatch) -> list[Figure]:
    kept: list[Figure] = []
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: kept.append(self))
    return kept


def _exact_gap(comp, engine: str) -> np.ndarray:
    """|exact on the engine's states − exact on MuJoCo's| / |exact on MuJoCo's|, per pose (the records' values)."""
    rows = {
        e: comp.records.where(formula="exact", scope="total", source=e, reference=e)["value"]
        for e in ("mujoco", engine)
    }
    return np.abs(rows[engine] - rows["mujoco"]) / np.abs(rows["mujoco"])


def _series(fig: Figure, engine: str):
    ax = fig.axes[0]
    return next(line for line in ax.get_lines() if line.get_label().startswith(f"{engine} vs mujoco"))


@pytest.mark.parametrize("model", [CAUSES / "class_mass.xml", "serial7.urdf"])
def test_one_point_per_pose_at_the_engines_gap(model, drawn, tmp_path: Path) -> None:
    comp = compare_model(model, n_poses=8, seed=4, engines=("mujoco", "pinocchio"))
    energies = engine_energies(energy_chunks(comp.records), comp.model, comp.engines, comp.n_poses)
    assert energies is not None
    figure_module.engine_gap_figure(comp.model, energies, tmp_path / "g.png", RTOL)
    line = _series(drawn[0], "pinocchio")
    expected = _exact_gap(comp, "pinocchio")
    np.testing.assert_array_equal(line.get_xdata(), np.arange(8))
    y = np.asarray(line.get_ydata())
    real = expected >= 1e-6  # a real gap: its position on the log axis; round-off: the band
    np.testing.assert_allclose(y[real], np.log10(expected[real]), atol=1e-6)
    assert np.all(y[expected < 1e-13] == BAND)
    if np.all(expected < 1e-13):  # the largest gap is round-off: printed 0, as everywhere in the report
        assert "largest 0 at" in line.get_label()
    tolerance = [line for line in drawn[0].axes[0].get_lines() if line.get_linestyle() == "--"]
    assert tolerance and np.allclose(tolerance[0].get_ydata(), np.log10(RTOL))


def test_the_largest_gap_and_its_pose_are_the_parity_statistics(drawn, tmp_path: Path) -> None:
    check = koenig_check.compare([CAUSES / "class_mass.xml"], n_poses=12, seed=1)
    comp, parity = check.comparisons[0], check.agreements[0]
    energies = engine_energies(energy_chunks(comp.records), comp.model, comp.engines, comp.n_poses)
    assert energies is not None
    figure_module.engine_gap_figure(comp.model, energies, tmp_path / "g.png", RTOL)
    line = _series(drawn[0], "pinocchio")
    assert max(line.get_ydata()) == pytest.approx(np.log10(parity.rigid_max_rel), abs=1e-12)
    assert f"at {parity.worst_pose}" in line.get_label() and parity.rigid_max_rel > 1


def _captured(monkeypatch: pytest.MonkeyPatch) -> list[tuple[str, EngineEnergies]]:
    seen: list[tuple[str, EngineEnergies]] = []
    draw = figure_module.engine_gap_figure

    def capture(model, energies, *args, **kwargs):
        seen.append((model, energies))
        return draw(model, energies, *args, **kwargs)

    monkeypatch.setattr(figure_module, "engine_gap_figure", capture)
    return seen


def test_records_streamed_to_a_file_give_the_same_figures(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """A run that streams its records (the CLI's compare --out) keeps each engine's energies for the figure.

    Two runs under one label (seeds 1 and 2) each get their own poses.
    """
    runs = [("gimbal.xml", 1), (CAUSES / "class_mass.xml", 1), ("gimbal.xml", 2)]
    in_memory = CrossCheck(rtol=RTOL)
    for model, seed in runs:
        in_memory.add(compare_model(model, n_poses=5, seed=seed, label=str(Path(model).name)))
    sink = RecordFiles(tmp_path / "streamed")
    streamed = CrossCheck(rtol=RTOL)
    for model, seed in runs:
        comp = compare_model(model, n_poses=5, seed=seed, label=str(Path(model).name), sink=sink, keep_records=False)
        assert not len(comp.records)
        streamed.add(comp)
    seen = _captured(monkeypatch)
    write_report(tmp_path / "memory", in_memory)
    write_report(tmp_path / "streamed", streamed, records=sink)
    assert len(seen) == 2 * len(runs)
    for (label_a, a), (label_b, b) in zip(seen[: len(runs)], seen[len(runs) :], strict=True):
        assert label_a == label_b and a.poses.to_pylist() == b.poses.to_pylist()
        for engine in a.energy:
            np.testing.assert_array_equal(a.energy[engine], b.energy[engine])
    assert not np.array_equal(seen[0][1].energy["mujoco"], seen[2][1].energy["mujoco"])  # seeds 1 and 2
    assert (tmp_path / "streamed" / "engine_gap_class_mass.xml.png").exists()


def test_drake_on_every_pose_is_a_series_of_its_own(drawn, tmp_path: Path) -> None:
    from koenig_check.engines.registry import installed

    if not installed("drake"):
        pytest.skip("Drake is not installed (pip install 'koenig-check[drake]')")
    comp = compare_model(CAUSES / "class_mass.xml", n_poses=6, engines=("mujoco", "pinocchio", "drake"))
    energies = engine_energies(energy_chunks(comp.records), comp.model, comp.engines, comp.n_poses)
    assert energies is not None and set(energies.energy) == {"mujoco", "pinocchio", "drake"}
    figure_module.engine_gap_figure(comp.model, energies, tmp_path / "g.png", RTOL)
    drake = np.asarray(_series(drawn[0], "drake").get_ydata())
    expected = _exact_gap(comp, "drake")
    assert np.all(expected < 1e-9)  # Drake reads the class's mass as MuJoCo does: its gap stays under the line
    assert np.all(drake < np.log10(RTOL))


def test_every_figure_records_its_smallest_text_and_none_is_below_9_points(tmp_path: Path) -> None:
    check = koenig_check.compare([CAUSES / "class_mass.xml", "gimbal.xml"], n_poses=4)
    grid = compare_model("gimbal.xml", pose_kind="grid", grid_joints=("outer_z", "inner_x"), n_poses=4)
    trajectory = compare_model("gimbal.xml", pose_kind="trajectory", n_poses=10, duration=0.5)
    written = write_report(tmp_path, check, grid_comparison=grid, trajectory_comparison=trajectory)
    pngs = [p for p in written if p.suffix == ".png"]
    assert {p.name.split("_")[0] for p in pngs} >= {"engine", "error", "trajectory"}
    for png in pngs:
        with Image.open(png) as image:
            dpi = 110  # every figure of the report is written at 110 dpi
            assert float(image.text[figure_module.MIN_FONT_KEY]) >= 9 * dpi / 72, png.name


def test_a_long_run_draws_the_largest_gap_of_each_block_of_poses(drawn, tmp_path: Path) -> None:
    import pyarrow as pa

    n = 12_001  # three poses per point, the last block a single pose
    rng = np.random.default_rng(0)
    mujoco = 1.0 + rng.random(n)
    pinocchio = mujoco * (1.0 + 10.0 ** rng.uniform(-8, -2, n))
    labels = pa.chunked_array([pa.array([f"random-{i}" for i in range(n)]).dictionary_encode()])
    energies = EngineEnergies(labels, {"mujoco": mujoco, "pinocchio": pinocchio})
    figure_module.engine_gap_figure("long", energies, tmp_path / "g.png", RTOL)
    line = _series(drawn[0], "pinocchio")
    gap = np.abs(pinocchio - mujoco) / mujoco
    block = -(-n // figure_module.GAP_POINTS)
    expected = [gap[k : k + block].max() for k in range(0, n, block)]
    assert len(line.get_xdata()) == len(expected) <= figure_module.GAP_POINTS
    np.testing.assert_allclose(10.0 ** np.asarray(line.get_ydata()), expected, rtol=1e-12)
    assert f"largest of {block} consecutive poses" in drawn[0].axes[0].get_xlabel()
    assert f"at random-{int(np.argmax(gap))}" in line.get_label()
