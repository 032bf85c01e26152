"""An engine disagreement fails the check: exit status 1 on the command line, ``ok == False`` in the API.

The disagreement is real: Pinocchio loads a twin of the URDF whose ``link5`` is 0.3 kg heavier.
The size of the difference is computed independently here, from each engine's own mass matrix.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from koenig_check.api import compare
from koenig_check.cli import main
from koenig_check.engines import load_model, random_states
from koenig_check.testing import assert_energy_parity

MODELS = Path(__file__).resolve().parents[2] / "models"


@pytest.fixture(scope="module")
def heavier(tmp_path_factory) -> Path:
    text = (MODELS / "serial7.urdf").read_text()
    altered = re.sub(r'(<link name="link5">.*?<mass value=")1.2(")', r"\g<1>1.5\g<2>", text, count=1, flags=re.S)
    assert altered != text
    path = tmp_path_factory.mktemp("twin") / "heavier.urdf"
    path.write_text(altered)
    return path


def test_the_twin_really_changes_the_energy(heavier: Path) -> None:
    pair = load_model(MODELS / "serial7.urdf", pinocchio_model=heavier, check=False)
    qpos, qvel = random_states(pair.mujoco.model, 4, seed=0)
    t_mj = 0.5 * np.einsum("pi,pij,pj->p", qvel, pair.mujoco.mass_matrix(qpos), qvel)
    t_pin = 0.5 * np.einsum("pi,pij,pj->p", qvel, pair.pinocchio.mass_matrix(qpos), qvel)
    assert np.all(np.abs(t_pin - t_mj) > 1e-6 * np.abs(t_mj))


def test_api_engine_disagreement_is_not_ok(heavier: Path) -> None:
    check = compare(MODELS / "serial7.urdf", n_poses=4, pinocchio_model=heavier)
    assert not check.failures and len(check.agreements) == 1
    assert not check.ok
    reason = check.reason()
    assert "MuJoCo and Pinocchio differ by" in reason and "root cause: link link5 (joint j5): mass differs" in reason
    assert "\n" not in reason and len(reason) <= 186
    assert "rigid-body energies differ" in check.agreements[0].reason  # the details: values, pose
    assert compare(MODELS / "serial7.urdf", n_poses=4).ok  # the same file against itself agrees


def test_cli_engine_disagreement_exits_one_with_the_reason(heavier: Path, capsys) -> None:
    status = main(["compare", str(MODELS / "serial7.urdf"), "--poses", "4", "--pinocchio-model", str(heavier)])
    err = capsys.readouterr().err
    assert status == 1
    assert "link link5 (joint j5): mass differs" in err and len(err.strip().splitlines()) == 1
    assert main(["compare", str(MODELS / "serial7.urdf"), "--poses", "4"]) == 0


def test_assert_energy_parity_fails_on_the_disagreement(heavier: Path) -> None:
    with pytest.raises(
        AssertionError, match=r"(?s)root cause: both: link link5 \(joint j5\): mass.*link link5 \(joint j5\) at pose"
    ):
        assert_energy_parity(MODELS / "serial7.urdf", pinocchio_model=heavier, n_poses=4)
    assert_energy_parity(MODELS / "serial7.urdf", n_poses=4)
