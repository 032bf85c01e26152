"""comparisons/gravity_energy.py: T + V along a MuJoCo trajectory under gravity, each formula in place of T."""

from __future__ import annotations

from pathlib import Path

import pytest
from gravity_energy import drifts

COMMITTED = Path(__file__).resolve().parents[2] / "comparisons" / "gravity_energy.md"


@pytest.mark.parametrize("model", ["gimbal.xml", "double_pendulum.xml"])
def test_exact_conserves_t_plus_v_to_the_integrators_error(model: str) -> None:
    drift, _, _, swing = drifts(model, duration=0.3, samples=60)
    assert swing > 1e-3  # gravity does work along the path: V changes
    assert drift["exact"] < 1e-9 and abs(drift["exact"] - drift["mujoco"]) < 1e-9  # as MuJoCo's own energy


def test_the_papers_recipe_drifts_on_the_gimbal() -> None:
    drift, _, _, _ = drifts("gimbal.xml", duration=0.3, samples=60)
    assert drift["alyushin_paper:rotvec"] > 1e3 * max(drift["exact"], 1e-12)
    assert drift["koenig_world"] > 1e-3


def test_the_committed_table_has_every_formula_row() -> None:
    text = COMMITTED.read_text()
    assert "| `exact` |" in text and "| `alyushin_paper:rotvec` |" in text and "| `mujoco` |" in text
