"""The statistics' fast path: |relative error| from the difference at hand, values handed over to the sketch."""

from __future__ import annotations

import numpy as np

from koenig_check.run.stats import GroupStats, QuantileSketch, absolute_relative_error, relative_error

EDGES = [
    (1.0, 1.0),
    (1.0 + 1e-12, 1.0),
    (-3.0, 2.0),
    (2.0, -3.0),
    (0.0, 0.0),
    (-0.0, 0.0),
    (0.0, -0.0),
    (1.0, 0.0),
    (-1.0, 0.0),
    (np.nan, 1.0),
    (1.0, np.nan),
    (np.nan, np.nan),
    (np.inf, 1.0),
    (1.0, np.inf),
    (np.inf, np.inf),
    (1e-300, 1e-310),
]


def test_absolute_relative_error_equals_the_absolute_of_relative_error() -> None:
    value = np.array([v for v, _ in EDGES] + list(np.random.default_rng(3).standard_normal(50)))
    reference = np.array([r for _, r in EDGES] + list(np.random.default_rng(4).standard_normal(50)))
    with np.errstate(invalid="ignore"):  # inf - inf
        expected = np.abs(relative_error(value, reference))
        got = absolute_relative_error(value - reference, np.abs(reference))
    np.testing.assert_array_equal(got, expected)
    # by hand: 0/0 is 0, x/0 is inf, a NaN reference gives inf (nothing to be relative to)
    assert got[4] == 0.0 and got[7] == np.inf and got[8] == np.inf and got[10] == np.inf
    assert np.signbit(got).sum() == 0


def test_group_add_counts_and_worst_by_hand() -> None:
    value = np.array([1.0, 2.0 + 1e-6, 0.5, 0.0, 3.0])
    reference = np.array([1.0, 2.0, 1.0, 0.0, 0.0])
    g = GroupStats()
    g.add(value, reference, 1e-9, [f"p{k}" for k in range(5)])
    assert (g.n, g.over, g.under) == (5, 2, 1)  # 2 + 1e-6 > 2 and 3 > 0 over; 0.5 < 1 under
    assert g.worst.value == np.inf and g.worst.where == "p4"
    assert g.sketch.median() == ((2.0 + 1e-6) - 2.0) / 2.0  # sorted: 0, 0, this, 0.5, inf


def test_sketch_keeps_its_own_copy_unless_handed_over() -> None:
    values = np.array([1.0, 2.0, 3.0])
    kept = QuantileSketch()
    kept.add(values)
    values[:] = 100.0
    assert kept.median() == 2.0


def test_add_rows_gives_what_add_gives_group_by_group() -> None:
    """The chunk's groups added at once equal each added alone: counts, worst and its pose, every quantile."""
    import numpy as np

    from koenig_check.run.chunks import add_rows
    from koenig_check.run.stats import GroupStats

    rng = np.random.default_rng(5)
    references = rng.normal(1.0, 1e-6, (4, 300))
    values = references * (1.0 + rng.uniform(-3e-9, 3e-9, (4, 300)))  # over, under and within rtol = 1e-9
    references[1, 7] = 0.0  # x/0: inf
    values[2, 9] = references[2, 9] = 0.0  # 0/0: 0
    values[3, 11] = np.nan
    labels = [f"p{i}" for i in range(300)]
    alone = [GroupStats() for _ in range(4)]
    for g, group in enumerate(alone):
        group.add(values[g], references[g], 1e-9, labels)
    together = [GroupStats() for _ in range(4)]
    add_rows(together, values, references, 1e-9, labels)
    for a, b in zip(alone, together, strict=True):
        assert (a.n, a.over, a.under) == (b.n, b.over, b.under)
        assert (a.worst.value, a.worst.where) == (b.worst.value, b.worst.where) or (
            np.isnan(a.worst.value) and np.isnan(b.worst.value) and a.worst.where == b.worst.where
        )
        assert a.sketch.nan == b.sketch.nan
        for q in (0.0, 0.25, 0.5, 0.9, 1.0):
            np.testing.assert_array_equal(a.sketch.quantile(q), b.sketch.quantile(q))
