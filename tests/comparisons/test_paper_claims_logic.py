"""The numbers paper_claims.py computes itself, against hand values."""

from __future__ import annotations

import numpy as np
import paper_claims


def test_two_paths_to_one_state_integrate_to_the_hand_values_of_delta_theta() -> None:
    """Outer z by a then inner x by b: ∫ω = (b cos a, b sin a, a); inner first: (b, 0, a) (inner body)."""
    a, b = 1.0, 1.2
    out = paper_claims.path_dependence(paper_claims.gimbal(), final=(a, b))
    first, second = out["outer_z then inner_x"], out["inner_x then outer_z"]
    np.testing.assert_allclose(first[0], [b * np.cos(a), b * np.sin(a), a], atol=1e-9)
    np.testing.assert_allclose(second[0], [b, 0.0, a], atol=1e-9)
    # the same state, two energies: the integrated reading depends on the path
    assert abs(first[1] - second[1]) > 1e-3 * out["exact"]


def test_percentages_keep_their_sign() -> None:
    assert paper_claims.rel_range(np.array([-0.293, 0.899])) == "from -29.3 % to +89.9 %"
    assert paper_claims.rel_range(np.array([0.154, 0.154])) == "+15.4 % throughout"
