"""Mergeable statistics: exact while small, a bounded sketch beyond, independent of chunking and merge order."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.run import stats
from koenig_check.run.stats import Extreme, QuantileSketch


def _sketch(chunks) -> QuantileSketch:
    total = QuantileSketch()
    for c in chunks:
        part = QuantileSketch()
        part.add(c)
        total.merge(part)
    return total


def test_ties_keep_the_first_location_across_chunks() -> None:
    first = Extreme()
    first.offer(np.array([1.0, 3.0, 3.0]), ["a", "b", "c"])
    later = Extreme()
    later.offer(np.array([3.0, 2.0]), ["d", "e"])
    first.merge(later)
    assert (first.value, first.where) == (3.0, "b")
    whole = Extreme()
    whole.offer(np.array([1.0, 3.0, 3.0, 3.0, 2.0]), list("abcde"))
    assert whole.where == first.where
    again = Extreme()
    again.offer(np.array([3.0]), ["x"])
    again.offer(np.array([3.0]), ["y"])
    assert again.where == "x"


def test_exact_median_while_small(rng: np.random.Generator) -> None:
    values = np.abs(rng.standard_cauchy(1001)) * 1e-6
    values[::7] = 0.0
    values[5] = np.inf
    s = _sketch(np.array_split(values, 13))
    assert s.exact and s.median() == np.median(values) and s.n == values.size


@pytest.mark.parametrize("n", [5000, 5001])
def test_binned_median_within_the_stated_bound_and_independent_of_chunking(
    rng: np.random.Generator, monkeypatch: pytest.MonkeyPatch, n: int
) -> None:
    monkeypatch.setattr(stats, "EXACT_LIMIT", 1000)
    values = 10.0 ** rng.uniform(-17, 1, size=n)
    a = _sketch(np.array_split(values, 3))
    b = _sketch(np.array_split(values[::-1], 11))
    assert not a.exact and not b.exact
    assert a.median() == b.median()
    bound = 10 ** (0.5 / stats.BINS_PER_DECADE) - 1
    assert abs(a.median() / np.median(values) - 1) <= bound * 1.0001
    assert abs(a.quantile(0.9) / np.quantile(values, 0.9) - 1) <= 2 * bound
    assert a.quantile(1.0) == pytest.approx(values.max(), rel=2 * bound)


def test_zero_and_infinite_errors_have_their_own_bins(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(stats, "EXACT_LIMIT", 4)
    s = _sketch([np.zeros(6), np.full(3, np.inf)])
    assert s.median() == 0.0 and s.quantile(1.0) == np.inf


def test_a_compacted_sketch_answers_and_merges_the_same(rng: np.random.Generator, monkeypatch) -> None:
    monkeypatch.setattr(stats, "EXACT_LIMIT", 100)
    values = 10.0 ** rng.uniform(-16, -2, size=3000)
    s = _sketch(np.array_split(values, 7))
    before = [s.quantile(q) for q in (0.0, 0.25, 0.5, 0.9, 1.0)]
    s.compact()
    assert isinstance(s._counts, tuple) and s._counts[0].size < 3000
    assert [s.quantile(q) for q in (0.0, 0.25, 0.5, 0.9, 1.0)] == before
    pooled = QuantileSketch()
    pooled.merge(s)
    pooled.merge(_sketch([values[:50]]))
    assert pooled.n == 3050
    assert pooled.median() == _sketch([values, values[:50]]).median()


@pytest.mark.parametrize("chunk_poses", [1, 2, None])
def test_an_armature_difference_in_an_early_chunk_survives_the_merge(chunk_poses: int | None) -> None:
    """armature_chain.xml (armature 0.02, 0.015, 0.01, 0.005 on j1..j4) against its URDF twin (no armature): the
    rigid-body energies agree, the armature energies differ by ``½ Σ a_i q̇_i²`` (by hand).  Only the first pose
    moves, the last ones are at rest: however the poses are cut into chunks, the model's engines disagree.
    """
    import koenig_check
    from koenig_check.run.poses import PoseSet

    armature = np.array([0.02, 0.015, 0.01, 0.005])
    qvel = np.zeros((3, 4))
    qvel[0] = [1.0, -2.0, 0.5, 3.0]
    poses = PoseSet(np.zeros((3, 4)), qvel, ("moving", "rest-1", "rest-2"), "file")
    check = koenig_check.compare(
        "armature_chain.xml",
        pinocchio_model="armature_chain.urdf",
        pose_set=poses,
        formulas=["exact"],
        chunk_poses=chunk_poses,
    )
    (parity,) = check.agreements
    assert parity.armature_max_abs == pytest.approx(0.5 * armature @ qvel[0] ** 2, rel=1e-12)
    assert not parity.agrees and "armature energies differ" in parity.reason
    assert parity.rigid_max_rel < 1e-12 and not check.ok
