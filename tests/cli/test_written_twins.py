"""A twin written at 6 significant digits (MuJoCo's own writer, from a real robot): the README's advice holds,
and every command names the option when a file's rounding explains the gap."""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import numpy as np
import pinocchio
import pytest

import koenig_check
from documents import document_with
from koenig_check.cli import main
from koenig_check.testing import assert_energy_parity
from koenig_check.testing.failure_text import verdict_lines
from written_twins import written_twin

ROBOTS = ["ur5", "panda"]


@pytest.fixture(scope="module", params=ROBOTS)
def twin(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    return written_twin(request.param, tmp_path_factory.mktemp(request.param))


def _readme_twin_rtol() -> str:
    """The tolerance the documented twin-pair paragraph (README or docs page) tells a user to pass."""
    text = document_with("- **A twin pair**")
    paragraph = text[text.index("- **A twin pair**") :].split("\n- ")[0]
    (value,) = set(re.findall(r"`--rtol ([0-9.e-]+)`", paragraph))
    return value


def _engines_gap(mjcf: Path, urdf: Path) -> float:
    """Independent route: MuJoCo's mass matrix of the MJCF against Pinocchio's (crba) of the URDF at random q."""
    m = mujoco.MjModel.from_xml_path(str(mjcf))
    d = mujoco.MjData(m)
    pm = pinocchio.buildModelFromUrdf(str(urdf))
    pd = pm.createData()
    names = [m.joint(j).name for j in range(m.njnt)]
    scalar = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
    assert all(m.jnt_type[j] in scalar for j in range(m.njnt))
    rng, gap = np.random.default_rng(0), 0.0
    for _ in range(20):
        q = rng.uniform(-1.0, 1.0, m.nq)
        d.qpos[:] = q
        mujoco.mj_forward(m, d)
        full = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, full)
        qp = pinocchio.neutral(pm)
        for j, name in enumerate(names):
            qp[pm.joints[pm.getJointId(name)].idx_q] = q[j]
        order = [pm.joints[pm.getJointId(n)].idx_v for n in names]
        mp = pinocchio.crba(pm, pd, qp)
        mp = np.triu(mp) + np.triu(mp, 1).T
        gap = max(gap, float(np.abs(mp[np.ix_(order, order)] - full).max() / np.abs(full).max()))
    return gap


def test_the_readmes_twin_advice_holds_on_a_written_twin(twin: tuple[Path, Path]) -> None:
    """The engines' own mass matrices differ by more than 1e-6 (the old advice) and within the README's value;
    compare, parity, dynamics and export --check-only all accept the twin with the README's --rtol."""
    mjcf, urdf = twin
    rtol = _readme_twin_rtol()
    gap = _engines_gap(mjcf, urdf)
    assert 1e-7 < gap <= float(rtol)
    pair = ["--pinocchio-model", str(urdf), "--rtol", rtol]
    assert main(["compare", str(mjcf), *pair, "--quiet"]) == 0
    assert main(["parity", str(mjcf), *pair]) == 0
    assert main(["dynamics", str(mjcf), *pair, "--poses", "3", "--formulas", "exact"]) == 0
    assert main(["export", "--check-only", str(urdf), str(mjcf), "--rtol", rtol]) == 0


@pytest.mark.parametrize("command", ["compare", "parity", "dynamics", "export"])
def test_every_command_names_the_option_on_a_written_twin(
    twin: tuple[Path, Path], command: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """At the default tolerance each command fails and says the gap is a 6-digit file's rounding, naming --rtol."""
    mjcf, urdf = twin
    if command == "export":
        argv = ["export", "--check-only", str(urdf), str(mjcf)]
    else:
        argv = [command, str(mjcf), "--pinocchio-model", str(urdf)]
        argv += {"compare": ["--quiet"], "dynamics": ["--poses", "3", "--formulas", "exact"]}.get(command, [])
    assert main(argv) == 1
    out, err = capsys.readouterr()
    verdict = out[out.index("\nverdict: ") :].split("\n\n")[0] if command == "parity" else ""
    # where each command says it: its stderr line; parity also on its verdict line; export in its list
    for text in {"compare": [err], "parity": [verdict, err], "dynamics": [err], "export": [out]}[command]:
        assert "6 significant digits" in text and "--rtol 1e-05 accepts it" in text, text
    assert all(len(line) <= 200 for line in (out + err).splitlines())
    if command == "dynamics":
        assert "exact disagrees" not in err  # it is the engines that differ, not exact
    if command == "export":  # values that differ are printed differently
        for original, export in re.findall(r"\(original ([0-9.e+-]+), export ([0-9.e+-]+)\)", out):
            assert original != export


def test_the_helper_and_the_plugins_text_name_the_option(twin: tuple[Path, Path]) -> None:
    mjcf, urdf = twin
    with pytest.raises(AssertionError, match=r"rtol=1e-05 accepts it"):  # Python's spelling, in Python
        assert_energy_parity(mjcf, pinocchio_model=urdf, n_poses=10)
    lines = verdict_lines(koenig_check.compare(mjcf, pinocchio_model=urdf, n_poses=10, formulas=["exact"]))
    assert any("rtol=1e-05 accepts it" in line for line in lines), lines
