"""The comparison on synthetic engine runs (no engine needed): records, summaries, the engines' agreement."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS
from koenig_check.formulas.analytic import random_states
from koenig_check.formulas.point_masses import equimomental_points, rigid_point_velocities
from koenig_check.run.comparison import compare_runs
from koenig_check.run.engine_runs import EngineRun
from koenig_check.run.poses import PoseSet
from koenig_check.run.stats import relative_error
from koenig_check.run.summaries import engine_agreement, summarize


def _run(engine: str, states, rigid_scale: float = 1.0, armature: float = 0.0) -> EngineRun:
    offsets, _ = equimomental_points(states.mass, states.inertia_body)
    rigid = FORMULAS["exact"](states).sum(axis=1) * rigid_scale
    return EngineRun(engine, states, rigid, np.full(states.n_poses, armature), rigid_point_velocities(states, offsets))


@pytest.fixture
def synthetic(rng: np.random.Generator):
    states = random_states(rng, 12, 3)
    poses = PoseSet(np.zeros((12, 1)), np.zeros((12, 1)), tuple(f"random-{i}" for i in range(12)), "random")
    return states, poses


def test_records_equal_formulas_on_the_same_states(synthetic) -> None:
    states, poses = synthetic
    comp = compare_runs("toy", poses, {"mujoco": _run("mujoco", states), "pinocchio": _run("pinocchio", states)})
    exact_total = FORMULAS["exact"](states).sum(axis=1)
    for name in ["koenig_world", "alyushin_paper:rotvec", "point_masses"]:
        direct = FORMULAS[name](states)
        rows = [r for r in comp.records if r["formula"] == name and r["source"] == "mujoco"]
        totals = [r for r in rows if r["scope"] == "total" and r["reference"] == "mujoco"]
        # The totals are sums of B segment energies: equal to rounding, whatever order the run adds them in.
        bound = 4 * states.n_segments * np.finfo(float).eps * np.abs(direct).sum(axis=1)
        ref_bound = 4 * states.n_segments * np.finfo(float).eps * np.abs(FORMULAS["exact"](states)).sum(axis=1)
        values = np.array([r["value"] for r in totals])
        references = np.array([r["reference_value"] for r in totals])
        assert np.all(np.abs(values - direct.sum(axis=1)) <= bound)
        assert np.all(np.abs(references - exact_total) <= ref_bound)
        signed = np.array([r["signed_error"] for r in totals])
        assert np.all(np.abs(signed - (direct.sum(axis=1) - exact_total)) <= bound + ref_bound)
        segs = [r for r in rows if r["scope"] == "segment1"]
        np.testing.assert_allclose([r["value"] for r in segs], direct[:, 1], rtol=1e-15)
    assert any("alyushin_paper:integrated: skipped" in n for n in comp.notes)
    assert comp.refusals and comp.refusals[0]["formula"] == "planar"


def test_summaries_report_sign_fractions_and_worst_pose(synthetic) -> None:
    states, poses = synthetic
    comp = compare_runs(
        "toy",
        poses,
        {"mujoco": _run("mujoco", states), "pinocchio": _run("pinocchio", states)},
        formulas=["exact", "koenig_world"],
    )
    summaries = {(s.formula, s.source, s.reference): s for s in summarize(comp, rtol=1e-9)}
    exact = summaries[("exact", "mujoco", "mujoco")]
    assert exact.agrees and exact.max_rel_error < 1e-12 and exact.over_fraction == 0 == exact.under_fraction
    kw = summaries[("koenig_world", "mujoco", "mujoco")]
    rel = relative_error(FORMULAS["koenig_world"](states).sum(axis=1), FORMULAS["exact"](states).sum(axis=1))
    assert kw.max_rel_error == pytest.approx(np.abs(rel).max(), rel=1e-12)
    assert kw.over_fraction == pytest.approx(np.mean(rel > 1e-9))
    assert kw.under_fraction == pytest.approx(np.mean(rel < -1e-9))
    assert kw.worst_pose == poses.ids[int(np.argmax(np.abs(rel)))]
    assert kw.median_rel_error == pytest.approx(np.median(np.abs(rel)), rel=1e-12)
    assert kw.median_rel_error != pytest.approx(np.mean(np.abs(rel)), rel=1e-3)  # the data tell median from mean
    seg_err = np.abs(FORMULAS["koenig_world"](states) - FORMULAS["exact"](states))  # (P, B)
    p, b = np.unravel_index(int(np.argmax(seg_err)), seg_err.shape)
    assert kw.worst_segment == f"{states.names[b]} @ {poses.ids[p]}"
    assert not kw.agrees


def test_a_reference_off_by_one_part_per_million_does_not_agree(synthetic) -> None:
    """rtol 1e-9 means 1e-9: a reference scaled by (1 + 1e-6) is a disagreement, and an underestimate."""
    states, poses = synthetic
    comp = compare_runs(
        "toy",
        poses,
        {"mujoco": _run("mujoco", states), "pinocchio": _run("pinocchio", states, 1 + 1e-6)},
        formulas=["exact"],
    )
    summaries = {(s.formula, s.source, s.reference): s for s in summarize(comp, rtol=1e-9)}
    same = summaries[("exact", "mujoco", "mujoco")]
    assert same.agrees and same.over_fraction == 0 == same.under_fraction
    off = summaries[("exact", "mujoco", "pinocchio")]
    assert not off.agrees
    assert off.max_rel_error == pytest.approx(1e-6 / (1 + 1e-6), rel=1e-6)
    assert off.under_fraction == 1 and off.over_fraction == 0
    loose = {(s.formula, s.source, s.reference): s for s in summarize(comp, rtol=1e-5)}
    assert loose[("exact", "mujoco", "pinocchio")].agrees  # the same data agree at a looser tolerance


def test_engine_parity_detects_disagreement(synthetic) -> None:
    states, poses = synthetic
    same = compare_runs(
        "toy",
        poses,
        {"mujoco": _run("mujoco", states), "pinocchio": _run("pinocchio", states)},
        formulas=["exact"],
    )
    assert engine_agreement(same).agrees
    off = compare_runs(
        "toy",
        poses,
        {"mujoco": _run("mujoco", states), "pinocchio": _run("pinocchio", states, 1.001)},
        formulas=["exact"],
    )
    parity = engine_agreement(off)
    assert not parity.agrees
    assert "rigid-body energies differ by 0.001" in parity.reason and "pinocchio: exact" in parity.reason
    arm = compare_runs(
        "toy",
        poses,
        {"mujoco": _run("mujoco", states, armature=0.5), "pinocchio": _run("pinocchio", states)},
        formulas=["exact"],
    )
    assert "armature energies differ by 0.5 J" in engine_agreement(arm).reason


def test_relative_error_edge_cases() -> None:
    np.testing.assert_array_equal(
        relative_error(np.array([0.0, 1.0, -1.0, 3.0]), np.array([0.0, 0.0, 0.0, 2.0])),
        [0, np.inf, -np.inf, 0.5],
    )


def test_unknown_formula_is_refused(synthetic) -> None:
    states, poses = synthetic
    with pytest.raises(ValueError, match="unknown formulas"):
        compare_runs("toy", poses, {"mujoco": _run("mujoco", states)}, formulas=["koenig"])
