"""boundmass and boundinertia: MuJoCo raises a body's mass or moments to the bound, and so does Pinocchio 4's
MJCF parser; settotalmass rescales every body, which Pinocchio does not.  The finding on an altered body says
which, and is a root cause only where the engines read different robots (measured here with each engine's own
parser, not with koenig-check's loaders)."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.findings import Kind

ARM = """<mujoco model="{name}">
  <compiler {option}/>
  <worldbody>
    <body name="arm">
      <joint name="shoulder" type="hinge" axis="0 1 0"/>
      <inertial pos="0.2 0 0" mass="2" diaginertia="0.01 0.02 0.025"/>
      <body name="hand" pos="0.4 0 0">
        <joint name="wrist" type="hinge" axis="0 0 1"/>
        <inertial pos="0.05 0 0" mass="0.1" diaginertia="0.001 0.002 0.0025"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
#: option -> whether Pinocchio 4 reads the body as MuJoCo compiles it
OPTIONS = {'boundmass="0.5"': True, 'boundinertia="0.005"': True, 'settotalmass="4.2"': False}


def _engines_own(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Masses and sorted principal moments of the two bodies, by MuJoCo's and by Pinocchio's own parser."""
    mj = mujoco.MjModel.from_xml_path(str(path))
    pn = pin.buildModelFromMJCF(str(path))
    mj_moments = np.sort(mj.body_inertia[1:], axis=1)
    pn_moments = np.array([np.linalg.eigvalsh(i.inertia) for i in pn.inertias[1:]])
    return mj.body_mass[1:], np.array([i.mass for i in pn.inertias[1:]]), mj_moments, pn_moments


@pytest.mark.parametrize("option", list(OPTIONS))
def test_the_finding_on_an_altered_body_says_whether_pinocchio_reads_it_alike(tmp_path: Path, option: str) -> None:
    path = tmp_path / "arm.xml"
    path.write_text(ARM.format(name=option.split("=")[0], option=option), encoding="utf-8")
    mj_mass, pn_mass, mj_moments, pn_moments = _engines_own(path)
    alike = np.allclose(mj_mass, pn_mass, rtol=1e-12) and np.allclose(mj_moments, pn_moments, rtol=1e-12, atol=0)
    assert alike == OPTIONS[option]  # what the engines do, measured (Pinocchio 4.1)
    assert not np.isclose(mj_mass[1], 0.1) or not np.allclose(mj_moments[1], [0.001, 0.002, 0.0025])  # altered
    check = koenig_check.compare(path, n_poses=4, formulas=["exact"])
    compiled = [f for f in check.comparisons[0].findings if f.kind is Kind.COMPILER and f.element == "body hand"]
    (found,) = [f for f in compiled if f.engine in ("mujoco", "pinocchio")]  # the pair's (Drake's own is its copy)
    assert found.root_cause is not alike and found.affects_energy is not alike
    assert ("Pinocchio's MJCF parser applies the same bounds" in found.summary) is alike
    assert ("Pinocchio keeps the file's values" in found.summary) is not alike
    assert check.ok is alike, check.reason()
