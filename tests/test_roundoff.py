"""Numbers as printed: round-off zeros relative to the largest of a set, values side by side with equal digits."""

from __future__ import annotations

import pytest

from koenig_check.roundoff import ROUNDOFF, relative_zeros, side_by_side


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ([-1.99283e-22, 8.51804e-23, 3e-06], "0, 0, 3e-06"),  # an URDF's rotated inertia: two round-off zeros
        ([2.30064e-06, 3.48527e-06, 7.2659e-06], "2.30064e-06, 3.48527e-06, 7.2659e-06"),  # small, not round-off
        ([-0.5, 1.0, 2.0], "-0.5, 1, 2"),  # a real negative moment is kept
        ([0.0, 0.0, 0.0], "0, 0, 0"),
    ],
)
def test_relative_zeros(values: list[float], expected: str) -> None:
    assert relative_zeros(values) == expected


def test_relative_zeros_threshold_is_the_projects() -> None:
    largest = 3.0
    below, above = 0.9 * ROUNDOFF * largest, 1.1 * ROUNDOFF * largest
    assert relative_zeros([below, largest]).startswith("0, ")
    assert not relative_zeros([above, largest]).startswith("0, ")


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ([2.928662, 5.53996438], ["2.92866", "5.53996"]),  # the same digits for both
        ([0.0096, 0.0096000001], ["0.0096", "0.0096000001"]),  # equal to 6 digits: as many as make them differ
        ([0.0096, 0.0096], ["0.0096", "0.0096"]),
        ([1.0, 1.0 + 1e-15], ["1", "1"]),  # beyond 12 digits: round-off, not shown
        ([1.0, 1.0 + 1e-11], ["1", "1.00000000001"]),
    ],
)
def test_side_by_side(values: list[float], expected: list[str]) -> None:
    assert side_by_side(values) == expected


def test_rotated_inertia_prints_its_round_off_moments_as_zero() -> None:
    """A flat inertia written rotated: its two zero moments come back at 1e-22 (numpy's eigenvalues)."""
    import numpy as np

    from koenig_check.segments import check_physical_inertia

    c, s = np.cos(0.3), np.sin(0.3)
    rotation = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    inertia = rotation @ np.diag([0.0, 0.0, 3e-6]) @ rotation.T
    reason = check_physical_inertia(1.0, inertia)
    assert reason is not None and "principal moments 0, 0, 3e-06" in reason, reason


@pytest.mark.parametrize("name", ["b1", "anymal-kinova"])
def test_real_refusal_prints_round_off_moments_as_zero(name: str) -> None:
    """example-robot-data's base links whose inertia MuJoCo refuses (was ``-1.99283e-22, 8.51804e-23, 3e-06``)."""
    from koenig_check.engines import InertiaError, load_model

    with pytest.raises(InertiaError, match=r"principal moments 0, 0, 3e-06"):
        load_model(name)


def test_before_and_after_print_the_digits_that_differ() -> None:
    from koenig_check.findings import Finding, Kind

    f = Finding(
        Kind.REPAIR,
        "mujoco",
        "link l",
        "raised",
        {
            "mass before": 0.0096,
            "mass after": 0.0096000001,
            "moments before": [1e-6, 2.0],
            "moments after": [1.0000001e-6, 2.0],
        },
    )
    text = f.message()
    assert "mass before 0.0096, mass after 0.0096000001" in text, text  # at 6 digits both read 0.0096
    assert "moments before [1e-06, 2], moments after [1.0000001e-06, 2]" in text, text


def test_moving_mass_has_the_same_digits_for_each_engine(capsys: pytest.CaptureFixture[str]) -> None:
    """jaco_arm: Pinocchio reads no mass from the meshes (was ``MuJoCo 2.928662 kg, Pinocchio 5.53996438 kg``)."""
    import re
    from pathlib import Path

    from koenig_check.cli import main

    dm_control = pytest.importorskip("dm_control")
    main(["parity", str(Path(dm_control.__file__).parent / "third_party/kinova/jaco_arm.xml")])
    (line,) = [x for x in capsys.readouterr().out.splitlines() if x.startswith("moving mass:")]
    numbers = re.findall(r"([0-9.]+) kg", line)
    assert numbers == ["2.92866", "5.53996", "6.53996"], line  # 6 digits each: they differ there
