"""Tests shared by the command-line tests of the engines that read URDF only (PyBullet, iDynTree).

The engine named by ``--engines`` on the command line gets a column, ``dynamics`` compares its mass matrix, an MJCF
fails the run with its reason, and the API runs it on every pose.  Each engine's test module imports these tests
(pytest collects them there) and gives the fixture ``engine_name``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import koenig_check
from koenig_check.cli import main
from koenig_check.engines.specs import spec


def engines(name: str) -> tuple[str, ...]:
    """MuJoCo, Pinocchio and the engine, as ``--engines`` names them.

    Parameters
    ----------
    name : str

    Returns
    -------
    tuple of str
    """
    return ("mujoco", "pinocchio", name)


def test_compare_gives_it_a_column(engine_name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """``compare`` on a URDF gives the engine its column and its gap."""
    name = engine_name
    argv = ["compare", "serial7.urdf", "--poses", "3", "--formulas", "exact", "--engines", ",".join(engines(name))]
    assert main([*argv, "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    label = spec(name).label
    assert out.startswith(f"Models: do MuJoCo, Pinocchio and {label} agree?") and f"{name} gap" in out


def test_dynamics_compares_its_mass_matrix(engine_name: str, capsys: pytest.CaptureFixture[str]) -> None:
    """``dynamics`` compares the engine's mass matrix with MuJoCo's."""
    name = engine_name
    argv = ["dynamics", "serial7.urdf", "--floating", "--poses", "2", "--engines", ",".join(engines(name))]
    assert main(argv) == 0
    assert f"engines (mujoco vs {name})" in capsys.readouterr().out


def test_an_mjcf_fails_the_run_with_its_reason(engine_name: str, capsys: pytest.CaptureFixture[str]) -> None:
    """An MJCF fails the run with the engine's reason (it reads URDF only)."""
    name = engine_name
    argv = [
        "compare",
        "double_pendulum.xml",
        "--poses",
        "2",
        "--formulas",
        "exact",
        "--engines",
        ",".join(engines(name)),
    ]
    assert main(argv) == 1
    label = spec(name).label
    assert f"{label} asked for (--engines) but it could not check the model: {label} reads URDF only" in (
        capsys.readouterr().err
    )


def test_the_api_runs_it_on_every_pose(engine_name: str) -> None:
    """The API runs the engine on every pose of a floating model."""
    name = engine_name
    check = koenig_check.compare("gimbal.urdf", n_poses=3, formulas=["exact"], engines=engines(name), floating=True)
    assert check.ok and check.comparisons[0].engines == engines(name)
