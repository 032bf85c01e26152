"""Checks shared by the command-line tests of the engines that read URDF only (PyBullet, iDynTree): each runs them.

The engine named by ``--engines`` on the command line gets a column, ``dynamics`` compares its mass matrix, an MJCF
fails the run with its reason, and the API runs it on every pose.
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


def check_compare_column(name: str, folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """``compare`` on a URDF gives the engine its column and its gap."""
    argv = ["compare", "serial7.urdf", "--poses", "3", "--formulas", "exact", "--engines", ",".join(engines(name))]
    assert main([*argv, "--out", str(folder / "out")]) == 0
    out = capsys.readouterr().out
    label = spec(name).label
    assert out.startswith(f"Models: do MuJoCo, Pinocchio and {label} agree?") and f"{name} gap" in out


def check_dynamics(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    """``dynamics`` compares the engine's mass matrix with MuJoCo's."""
    argv = ["dynamics", "serial7.urdf", "--floating", "--poses", "2", "--engines", ",".join(engines(name))]
    assert main(argv) == 0
    assert f"engines (mujoco vs {name})" in capsys.readouterr().out


def check_mjcf_fails_the_run(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    """An MJCF fails the run with the engine's reason (it reads URDF only)."""
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


def check_api_every_pose(name: str) -> None:
    """The API runs the engine on every pose of a floating model."""
    check = koenig_check.compare("gimbal.urdf", n_poses=3, formulas=["exact"], engines=engines(name), floating=True)
    assert check.ok and check.comparisons[0].engines == engines(name)
