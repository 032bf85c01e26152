"""engines/measurement.py: which fields two readings of a file differ in, the whole M's spectrum among them."""

from __future__ import annotations

import numpy as np
import pytest

from koenig_check.engines.measurement import Measurement, differences, fields

#: A puck of 1 kg (COM 0.1 m from the joint origin along x, ixx 0.01, izz 0.03) on a planar joint.  In the plane
#: normal to x (MuJoCo's three joints, as the URDF axis says) M = diag(1, 1, 0.01); about z (Pinocchio's reading)
#: M = [[1, 0, 0], [0, 1, 0.1], [0, 0.1, 0.03 + 0.1²]] in (vx, vy, ω).
NORMAL_TO_X = np.diag([1.0, 1.0, 0.01])
ABOUT_Z = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.1], [0.0, 0.1, 0.04]])


def _reading(joints: tuple[str, ...], m: np.ndarray) -> Measurement:
    return Measurement(joints=joints, mass=1.0, spectrum=tuple(np.linalg.eigvalsh(m)))


def test_one_joint_split_in_three_alike_differs_in_joint_names_only() -> None:
    three, one = _reading(("p_RZ", "p_TX", "p_TY"), NORMAL_TO_X), _reading(("p",), NORMAL_TO_X[[2, 0, 1]][:, [2, 0, 1]])
    assert differences(three, one, 1e-9) == {"joints"}


def test_another_plane_differs_in_the_spectrum() -> None:
    assert differences(_reading(("p",), NORMAL_TO_X), _reading(("p",), ABOUT_Z), 1e-9) == {"spectrum"}
    fewer = _reading(("p",), NORMAL_TO_X[:2, :2])  # a degree of freedom missing
    assert "spectrum" in differences(_reading(("p",), NORMAL_TO_X), fewer, 1e-9)


def test_round_off_is_no_difference_and_an_unmeasured_spectrum_is_not_compared() -> None:
    a = _reading(("p",), NORMAL_TO_X)
    b = _reading(("p",), NORMAL_TO_X * (1 + 1e-12))
    assert differences(a, b, 1e-9) == set()
    assert differences(a, Measurement(joints=("p",), mass=1.0), 1e-9) == set()


@pytest.mark.parametrize(("quantity", "expected"), [("kinematics", {"mass_matrix", "spectrum"}), ("mass", {"mass"})])
def test_kinematics_stands_for_the_spectrum_too(quantity: str, expected: set[str]) -> None:
    assert fields((quantity,)) == expected


@pytest.mark.parametrize(("engine", "m"), [("mujoco", NORMAL_TO_X), ("pinocchio", ABOUT_Z), ("drake", NORMAL_TO_X)])
def test_the_planar_fixture_spectra_are_the_hand_values(engine: str, m: np.ndarray) -> None:
    """pinocchio.urdf.planar-axis's fixture: MuJoCo and Drake move the puck in the plane normal to x, Pinocchio
    about z (the reading the catalogue declares), each measured with the engine's own M."""
    import importlib

    from koenig_check.causes import cause, fixture_path

    pytest.importorskip({"drake": "pydrake"}.get(engine, engine))
    measure = importlib.import_module(f"koenig_check.engines.{engine}.causes").measure
    measured = measure(fixture_path(cause("pinocchio.urdf.planar-axis")))
    assert measured.spectrum == pytest.approx(tuple(np.linalg.eigvalsh(m)), rel=1e-12, abs=1e-15)
