"""`koenig-check dynamics`: exit 0 when exact agrees with both engines, 1 when the engines disagree, 2 on usage."""

from __future__ import annotations

import json

import pytest

from koenig_check.cli import main
from koenig_check.engines.mujoco.adapter import MujocoEngine
from koenig_check.engines.pinocchio.adapter import PinocchioEngine
from koenig_check.formulas import FORMULAS


def test_dynamics_command_passes_and_writes_its_section(tmp_path, capsys):
    out = tmp_path / "report"
    assert main(["dynamics", "gimbal.xml", "--poses", "3", "--out", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    for name in FORMULAS:
        assert sum(line.startswith(f"{name} ") for line in lines) == 1, name
    assert any(line.startswith("alyushin_paper:integrated") and "depends on the path" in line for line in lines)
    md = (out / "dynamics.md").read_text()
    assert "Verdict on `exact`" in md and "agree" in md
    data = json.loads((out / "dynamics.json").read_text())
    assert data["ok"] is True
    assert len(data["errors"][0]["rel_error"]) == 3


def test_dynamics_command_takes_the_shared_load_options(capsys):
    assert main(["dynamics", "free_body.urdf", "--floating", "--poses", "2", "--formulas", "exact"]) == 0
    assert "exact" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv",
    [
        ["dynamics"],
        ["dynamics", "gimbal.xml", "--poses", "many"],
        ["dynamics", "gimbal.xml", "--poses", "0"],
        ["dynamics", "gimbal.xml", "--formulas", "no_such_formula"],
        ["dynamics", "gimbal.xml", "--q-rtol", "-1"],
    ],
)
def test_usage_errors_exit_2(argv, capsys):
    with pytest.raises(SystemExit) as err:
        main(argv)
    assert err.value.code == 2
    assert "error" in capsys.readouterr().err


def test_corrupted_pinocchio_mass_matrix_exits_1_with_one_line(monkeypatch, capsys):
    original = PinocchioEngine.mass_matrix
    monkeypatch.setattr(PinocchioEngine, "mass_matrix", lambda self, qpos: 1.001 * original(self, qpos))
    assert main(["dynamics", "gimbal.xml", "--poses", "2", "--formulas", "exact"]) == 1
    err = capsys.readouterr().err.strip()
    first, *rest = err.splitlines()  # one message: a line of at most 200 characters, the rest indented, never cut
    assert first.startswith("koenig-check: gimbal.xml: ") and len(first) <= 200 and not first.endswith("…")
    assert all(line.startswith("    ") for line in rest)
    assert "pinocchio" in first and "M of" in first


def test_corrupted_mujoco_inverse_dynamics_exits_1(monkeypatch, capsys):
    original = MujocoEngine.inverse_dynamics
    monkeypatch.setattr(MujocoEngine, "inverse_dynamics", lambda self, q, v, a: original(self, q, v, a) * (1 + 1e-4))
    assert main(["dynamics", "serial7.xml", "--poses", "2", "--formulas", "exact"]) == 1
    err = capsys.readouterr().err
    assert "Q* of" in err and "mujoco" in err


def test_missing_model_exits_1_naming_the_file(tmp_path, capsys):
    assert main(["dynamics", str(tmp_path / "nope.xml")]) == 1
    assert "nope.xml" in capsys.readouterr().err


def test_pinocchio_from_the_urdf_twin_with_armature_only_in_mujoco(capsys):
    argv = ["dynamics", "armature_chain.xml", "--pinocchio-model", "armature_chain.urdf", "--poses", "2"]
    assert main([*argv, "--formulas", "exact"]) == 0


def test_engine_disagreement_is_named_among_the_failures(monkeypatch):
    from koenig_check.implied_dynamics.analysis import ENGINE_PARITY, dynamics

    original = PinocchioEngine.mass_matrix
    monkeypatch.setattr(PinocchioEngine, "mass_matrix", lambda self, qpos: 1.001 * original(self, qpos))
    result = dynamics("gimbal.xml", n_poses=2, formulas=["exact"])
    assert not result.ok
    failed = {(e.formula, e.route, e.engine, e.quantity) for e in result.failures()}
    assert (ENGINE_PARITY, "mujoco", "pinocchio", "M") in failed
    assert ("exact", "kane@mujoco", "pinocchio", "M") in failed
    assert ("exact", "kane@mujoco", "mujoco", "M") not in failed


@pytest.mark.parametrize("options", [{"repair_inertia": True}, {"balance_inertia": True, "repair_inertia": True}])
def test_every_load_option_reaches_the_dynamics_loader(options, capsys):
    """``--repair-inertia`` loads in dynamics what it loads in compare (it was dropped: the refusal named it)."""
    from pathlib import Path

    from koenig_check.findings import Kind
    from koenig_check.implied_dynamics.analysis import dynamics

    path = Path(__file__).resolve().parents[1] / "engines" / "models" / "repair_needed.urdf"
    result = dynamics(path, n_poses=1, formulas=["exact"], engines=("mujoco", "pinocchio"), **options)
    repaired = {f.element for f in result.findings if f.kind is Kind.REPAIR}
    assert {"link tilted", "link virtual"} <= repaired
    flags = [f"--{k.replace('_', '-')}" for k in options]
    main(["dynamics", str(path), *flags, "--poses", "1", "--formulas", "exact", "--engines", "mujoco,pinocchio"])
    out, err = capsys.readouterr()
    assert "exact" in out and "MuJoCo rejects its inertia" not in err
