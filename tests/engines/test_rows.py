"""``rows``: an index taken as a slice where it can be, the same values as fancy indexing."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.engines.base import rows


@pytest.mark.parametrize(
    "index, kind",
    [
        ([1, 2, 3, 4, 5, 6], slice),
        ([0], slice),
        ([4, 4, 4], slice),
        ([1, 1, 1, 1, 21, 21, 27], np.ndarray),
        ([13, 14, 31, 1, 2], np.ndarray),
        ([2, 3, 5], np.ndarray),
        ([3, 2, 1], np.ndarray),
    ],
)
def test_rows_selects_what_fancy_indexing_selects(index: list[int], kind: type) -> None:
    arr = np.random.default_rng(1).standard_normal((5, 33, 3))
    index = np.array(index)
    taken = rows(index)
    assert isinstance(taken, kind)
    expected = arr[:, index]
    got = np.broadcast_to(arr[:, taken], expected.shape)  # a repeated single row comes as one row, broadcast
    np.testing.assert_array_equal(got, expected)
    if kind is slice:
        assert np.shares_memory(arr[:, taken], arr), "a slice is a view, not a copy"
