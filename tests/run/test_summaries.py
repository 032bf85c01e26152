"""A formula's summary: its largest error against the reference, and whether that is within ``rtol``.

The model is one body on a hinge through its centre of mass, axis ``n = (1, 1, 0)/√2``, with the central inertia
``α 1 + β n nᵀ`` (symmetric about the axis, so the same in the world at every angle).  By hand: the exact energy is
``½ (α + β) ω²``; eq. (1) read in world axes keeps the diagonal only, ``½ Σ n_i² I_ii ω² = ½ (α + β/2) ω²``, so its
relative error is ``−β / (2 (α + β))`` at every pose and rate.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import koenig_check

ALPHA, BETA = 1.0, 0.02
#: |relative error| of koenig_world on this body, by hand: 0.0098...
KOENIG_WORLD_ERROR = BETA / (2 * (ALPHA + BETA))


@pytest.fixture(scope="module")
def tilted_hinge(tmp_path_factory: pytest.TempPathFactory) -> Path:
    n = np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0)
    inertia = ALPHA * np.eye(3) + BETA * np.outer(n, n)
    full = " ".join(f"{inertia[i, j]:.17g}" for i, j in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)))
    path = tmp_path_factory.mktemp("summaries") / "tilted_hinge.xml"
    path.write_text(
        '<mujoco><worldbody><body name="rotor"><joint name="spin" type="hinge" axis="1 1 0"/>'
        f'<inertial pos="0 0 0" mass="1" fullinertia="{full}"/></body></worldbody></mujoco>'
    )
    model = mujoco.MjModel.from_xml_string(path.read_text())  # MuJoCo's own mass matrix: the hinge sees α + β
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    mass = np.zeros((1, 1))
    mujoco.mj_fullM(model, data, mass)
    assert mass[0, 0] == pytest.approx(ALPHA + BETA, rel=1e-12)
    return path


@pytest.mark.parametrize(
    ("rtol", "agrees"),
    [(KOENIG_WORLD_ERROR / 2, False), (KOENIG_WORLD_ERROR / 1.5, False), (KOENIG_WORLD_ERROR * 1.5, True)],
)
def test_a_formula_agrees_only_when_its_largest_error_is_within_rtol(tilted_hinge: Path, rtol: float, agrees: bool):
    check = koenig_check.compare(tilted_hinge, n_poses=6, formulas=["exact", "koenig_world"], rtol=rtol)
    rows = [s for s in check.summaries if s.formula == "koenig_world"]
    assert len(rows) == 4  # each engine's states against each engine's energy
    for s in rows:
        assert s.max_rel_error == pytest.approx(KOENIG_WORLD_ERROR, rel=1e-9)
        assert s.agrees is agrees, (rtol, s)
        assert s.under_fraction == (0.0 if agrees else 1.0) and s.over_fraction == 0.0  # it always falls short
    assert all(s.agrees and s.max_rel_error < 1e-12 for s in check.summaries if s.formula == "exact")


def test_the_parity_record_carries_the_ids_of_the_causes(tmp_path: Path) -> None:
    """records.json's parity row of a model the engines disagree on names its causes by id, in the reason's order."""
    import json

    from koenig_check.causes import cause, fixture_path
    from koenig_check.cli import main

    path = fixture_path(cause("pinocchio.mjcf.class-geom-mass"))
    assert main(["compare", str(path), "--poses", "3", "--formulas", "exact", "--out", str(tmp_path / "out")]) == 1
    (row,) = json.loads((tmp_path / "out" / "records.json").read_text())["parity"]
    assert not row["agrees"] and row["causes"] == ["pinocchio.mjcf.class-geom-mass"]
    agreeing = koenig_check.compare("double_pendulum", n_poses=3, formulas=["exact"])
    assert agreeing.ok and [p.causes for p in agreeing.agreements] == [()]
