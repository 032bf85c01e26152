"""Default chunk sizes."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("n_segments", [1, 6, 20, 33, 40, 64, 100, 500])
def test_a_default_chunk_of_random_poses_draws_no_block_twice(n_segments: int) -> None:
    """The seeded sequence is drawn in blocks of RANDOM_BLOCK poses: a default chunk covers whole blocks or lies in
    one, so the chunks of a run draw each block once (Talos's 33 segments gave 992-pose chunks straddling two)."""
    from koenig_check.engines.sampling import RANDOM_BLOCK
    from koenig_check.run.chunk_tasks import CHUNK_MAX, CHUNK_MIN, chunk_size

    size = chunk_size(n_segments)
    assert CHUNK_MIN <= size <= CHUNK_MAX
    assert size % RANDOM_BLOCK == 0 or RANDOM_BLOCK % size == 0
    starts = range(0, 10 * RANDOM_BLOCK, size)
    blocks = [b for s in starts for b in range(s // RANDOM_BLOCK, (s + size - 1) // RANDOM_BLOCK + 1)]
    assert len(blocks) == len(set(blocks)) or size < RANDOM_BLOCK  # several small chunks share a block, never straddle
    assert all(s // RANDOM_BLOCK == (s + size - 1) // RANDOM_BLOCK for s in starts) or size >= RANDOM_BLOCK
