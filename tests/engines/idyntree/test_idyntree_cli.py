"""iDynTree named by ``--engines`` on the command line, the API and the pytest helper; refused on an MJCF."""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.testing import assert_energy_parity

pytest.importorskip("idyntree")

ENGINES = ("mujoco", "pinocchio", "idyntree")


def test_compare_gives_idyntree_a_column(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["compare", "serial7.urdf", "--poses", "3", "--formulas", "exact", "--engines", ",".join(ENGINES)]
    assert main([*argv, "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Models: do MuJoCo, Pinocchio and iDynTree agree?") and "idyntree gap" in out


def test_dynamics_compares_idyntrees_mass_matrix(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["dynamics", "serial7.urdf", "--floating", "--poses", "2", "--engines", ",".join(ENGINES)]) == 0
    assert "engines (mujoco vs idyntree)" in capsys.readouterr().out


def test_an_mjcf_fails_the_run_with_idyntrees_reason(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["compare", "double_pendulum.xml", "--poses", "2", "--formulas", "exact", "--engines", ",".join(ENGINES)]
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert "iDynTree asked for (--engines) but it could not check the model: iDynTree reads URDF only" in err


def test_the_api_runs_it_on_every_pose() -> None:
    check = koenig_check.compare("gimbal.urdf", n_poses=3, formulas=["exact"], engines=ENGINES, floating=True)
    assert check.ok and check.comparisons[0].engines == ENGINES


def test_the_pytest_helper_requires_it_to_check_the_model() -> None:
    assert_energy_parity("serial7.urdf", engines=ENGINES, n_poses=3)
    with pytest.raises(AssertionError):  # the check asked for (iDynTree) cannot be made on an MJCF
        assert_energy_parity("double_pendulum.xml", engines=ENGINES, n_poses=3)
