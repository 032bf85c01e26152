"""One gap, one number: export's note on an engine that misreads the original gives the engines' gap as
``compare`` measures it (rigid energies relative to MuJoCo's), at the same states."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pinocchio
import pytest

import koenig_check
from koenig_check.engines.sampling import random_states

CARTPOLE = Path(__import__("dm_control").__file__).parent / "suite" / "cartpole.xml"


def _engines_own_gap(qpos: np.ndarray, qvel: np.ndarray) -> float:
    """Independent route: MuJoCo's ½ q̇ᵀ M q̇ and Pinocchio's computeKineticEnergy, each from its own reading."""
    m = mujoco.MjModel.from_xml_path(str(CARTPOLE))
    assert not m.dof_armature.any()  # the energies are rigid-body energies
    d = mujoco.MjData(m)
    pm = pinocchio.buildModelFromMJCF(str(CARTPOLE))
    pd = pm.createData()
    assert [pm.names[j] for j in range(1, pm.njoints)] == [m.joint(j).name for j in range(m.njnt)]
    gap = 0.0
    for q, v in zip(qpos, qvel, strict=True):
        d.qpos[:], d.qvel[:] = q, v
        mujoco.mj_forward(m, d)
        full = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, full)
        t_mujoco = 0.5 * v @ full @ v
        t_pinocchio = pinocchio.computeKineticEnergy(pm, pd, q, v)
        gap = max(gap, abs(t_pinocchio - t_mujoco) / abs(t_mujoco))
    return gap


def test_export_and_compare_give_one_number_for_one_gap(tmp_path: Path) -> None:
    result = koenig_check.export(CARTPOLE, to="urdf", out=tmp_path / "cartpole.urdf", poses=10, seed=0)
    pinocchio_proof = next(e for e in result.proof.engines if e.engine == "pinocchio")
    qpos, qvel = random_states(mujoco.MjModel.from_xml_path(str(CARTPOLE)), 10, 0)
    expected = _engines_own_gap(qpos, qvel)
    assert expected > 10  # Pinocchio ignores the pole's class mass: a gap of tens, not "1"
    assert pinocchio_proof.own_reading == pytest.approx(expected, rel=1e-9)
    (note,) = [n for n in result.proof.notes() if n.startswith("pinocchio")]
    assert f"up to {expected:.2g} relative to MuJoCo's" in note
    np.savez(tmp_path / "poses.npz", qpos=qpos, qvel=qvel)  # compare at the same states says the same
    check = koenig_check.compare(CARTPOLE, pose_file=tmp_path / "poses.npz", formulas=["exact"])
    assert check.agreements[0].rigid_max_rel == pytest.approx(expected, rel=1e-9)
