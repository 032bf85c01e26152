"""iDynTree named by ``--engines`` on the command line, the API and the pytest helper; refused on an MJCF."""

from __future__ import annotations

from pathlib import Path

import pytest
from urdf_engine_cli import (
    check_api_every_pose,
    check_compare_column,
    check_dynamics,
    check_mjcf_fails_the_run,
    engines,
)

from koenig_check.testing import assert_energy_parity

pytest.importorskip("idyntree")

ENGINE = "idyntree"
ENGINES = engines(ENGINE)


def test_compare_gives_it_a_column(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    check_compare_column(ENGINE, tmp_path, capsys)


def test_dynamics_compares_its_mass_matrix(capsys: pytest.CaptureFixture[str]) -> None:
    check_dynamics(ENGINE, capsys)


def test_an_mjcf_fails_the_run_with_its_reason(capsys: pytest.CaptureFixture[str]) -> None:
    check_mjcf_fails_the_run(ENGINE, capsys)


def test_the_api_runs_it_on_every_pose() -> None:
    check_api_every_pose(ENGINE)


def test_the_pytest_helper_requires_it_to_check_the_model() -> None:
    assert_energy_parity("serial7.urdf", engines=ENGINES, n_poses=3)
    with pytest.raises(AssertionError):  # the check asked for (iDynTree) cannot be made on an MJCF
        assert_energy_parity("double_pendulum.xml", engines=ENGINES, n_poses=3)
