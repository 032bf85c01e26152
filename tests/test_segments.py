from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas.analytic import random_states
from koenig_check.segments import (
    SegmentStates,
    check_physical_inertia,
    inertia_from_second_moments,
    second_moments,
)


def _fields(states: SegmentStates) -> dict:
    return {name: np.array(getattr(states, name)) for name in SegmentStates.__dataclass_fields__}


def test_valid_states_are_frozen_and_read_only(random_batch: SegmentStates) -> None:
    assert random_batch.n_poses == 64 and random_batch.n_segments == 7
    with pytest.raises(AttributeError):
        random_batch.mass = np.ones(7)  # type: ignore[misc]
    with pytest.raises(ValueError, match="read-only"):
        random_batch.com[0, 0, 0] = 1.0


@pytest.mark.parametrize(
    ("field", "mutate", "message"),
    [
        ("mass", lambda a: a[:-1], r"SegmentStates\.mass: shape"),
        ("com", lambda a: a[:, :, :2], r"SegmentStates\.com: shape"),
        (
            "omega",
            lambda a: np.where(np.arange(a.shape[1])[None, :, None] == 3, np.nan, a),
            r"omega.*'segment3'",
        ),
        (
            "mass",
            lambda a: a * np.where(np.arange(a.size) == 2, -1.0, 1.0),
            r"'segment2' has non-positive mass",
        ),
        (
            "mass",
            lambda a: np.where(np.arange(a.size) == 4, 0.0, a),
            r"'segment4' has non-positive mass 0",
        ),
        (
            "inertia_body",
            lambda a: a + np.where(np.arange(a.shape[0])[:, None, None] == 5, np.triu(np.ones((3, 3)), 1), 0.0),
            r"'segment5' is not symmetric",
        ),
        (
            "rotation",
            lambda a: a * 1.01,
            r"SegmentStates\.rotation: segment 'segment0' at pose 0 is not a proper",
        ),
        ("rotation_ref", lambda a: -a, r"rotation_ref: segment 'segment0' is not a proper rotation"),
    ],
)
def test_invalid_states_name_field_and_segment(random_batch: SegmentStates, field: str, mutate, message: str) -> None:
    kwargs = _fields(random_batch)
    kwargs["names"] = random_batch.names
    kwargs[field] = mutate(kwargs[field])
    with pytest.raises(ValueError, match=message):
        SegmentStates(**kwargs)


def test_duplicate_names_rejected(random_batch: SegmentStates) -> None:
    kwargs = _fields(random_batch)
    kwargs["names"] = ("a",) * random_batch.n_segments
    with pytest.raises(ValueError, match="duplicate segment names"):
        SegmentStates(**kwargs)


def test_select_keeps_named_segments_in_order(random_batch: SegmentStates) -> None:
    sub = random_batch.select(poses=slice(2, 5), segments=["segment4", "segment1"])
    assert sub.names == ("segment4", "segment1")
    np.testing.assert_array_equal(sub.omega, random_batch.omega[2:5][:, [4, 1]])
    np.testing.assert_array_equal(sub.mass, random_batch.mass[[4, 1]])
    single = random_batch.select(poses=3)
    assert single.n_poses == 1
    with pytest.raises(KeyError, match="unknown segments"):
        random_batch.select(segments=["nope"])


def test_inertia_world_is_rotated_body_inertia(random_batch: SegmentStates) -> None:
    R = random_batch.rotation[5, 2]
    np.testing.assert_allclose(
        random_batch.inertia_world()[5, 2], R @ random_batch.inertia_body[2] @ R.T, rtol=1e-13, atol=1e-15
    )


def test_second_moments_round_trip(rng: np.random.Generator) -> None:
    I = random_states(rng, 1, 5).inertia_body
    np.testing.assert_allclose(inertia_from_second_moments(second_moments(I)), I, rtol=1e-14, atol=1e-16)


@pytest.mark.parametrize(
    ("inertia", "reason"),
    [
        (np.diag([1.0, 2.0, 3.0]), None),
        (np.diag([1.0, 1.0, 3.0]), "triangle inequality"),
        (np.diag([1.0, -2.0, 3.0]), "not positive semi-definite"),
        (np.array([[1.0, 0.1, 0], [0, 1, 0], [0, 0, 1]]), "not symmetric"),
    ],
)
def test_check_physical_inertia(inertia: np.ndarray, reason: str | None) -> None:
    result = check_physical_inertia(1.0, inertia)
    if reason is None:
        assert result is None
    else:
        assert reason in result


def test_inertia_about_anchor_by_hand(random_batch: SegmentStates) -> None:
    """Largest central moment in world axes plus m |com - pole|², at the first pose, for each segment."""
    states = random_batch
    expected = []
    for b in range(states.n_segments):
        R = states.rotation[0, b]
        central = R @ states.inertia_body[b] @ R.T
        lever = states.com[0, b] - states.pole[0, b]
        expected.append(max(np.linalg.eigvalsh(central)) + states.mass[b] * float(lever @ lever))
    np.testing.assert_allclose(states.inertia_about_anchor(), expected, rtol=1e-12)
    # a point mass of 2 kg on a 0.5 m lever: 0.5 kg m² whatever its (zero) central moments
    point = dict(_fields(states.select(segments=[states.names[0]])))
    point.update(mass=np.array([2.0]), inertia_body=np.zeros((1, 3, 3)))
    point.update(pole=np.zeros_like(point["pole"]), com=np.tile([0.0, 0.3, 0.4], (*point["com"].shape[:2], 1)))
    np.testing.assert_allclose(SegmentStates(**point).inertia_about_anchor(), [0.5], rtol=1e-12)
