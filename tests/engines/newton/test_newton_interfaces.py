"""Newton named by ``--engines`` (command line) and ``engines=`` (API, ``assert_energy_parity``); the pytest plugin
with each new engine is in ``tests/testing/test_plugin_engines.py``."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("newton", reason="Newton (the optional extra [newton]) is not installed: its tests are skipped")

import koenig_check
from koenig_check.causes import cause, fixture_path
from koenig_check.cli import main
from koenig_check.engines.newton import causes as ids
from koenig_check.findings import Kind
from koenig_check.testing import assert_energy_parity

ENGINES = ("mujoco", "pinocchio", "newton")
#: Pinocchio ignores a <default> class's geom mass; MuJoCo and Newton read it as written.
CLASS_MASS = Path(__file__).resolve().parents[2] / "models" / "causes" / "class_mass.xml"


@pytest.mark.parametrize(
    ("model", "floating"), [("serial7.urdf", False), ("serial7.urdf", True), ("gimbal.xml", False)]
)
def test_cli_compare_with_newton_agrees(model: str, floating: bool, tmp_path: Path, capsys) -> None:
    argv = ["compare", model, "--poses", "4", "--formulas", "exact", "--engines", ",".join(ENGINES)]
    assert main([*argv, *(["--floating"] if floating else []), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Models: do MuJoCo, Pinocchio and Newton agree?")
    row = next(line for line in out.splitlines() if line.startswith(model)).split()
    row = [w for w in row if w != "(floating)"]
    assert row[1] == "agree" and 0 < float(row[3]) < 1e-5  # Newton's float32 gap: printed, not a disagreement


def test_cli_refusal_fails_the_run_with_newtons_reason(capsys) -> None:
    path = fixture_path(cause(ids.SOLVER_PGS))
    assert main(["compare", str(path), "--poses", "2", "--formulas", "exact", "--engines", ",".join(ENGINES)]) != 0
    err = capsys.readouterr().err.splitlines()
    first = next(k for k, line in enumerate(err) if line.startswith("koenig-check: newton_solver_pgs.xml: Newton"))
    assert err[first + 1] == "    ValueError: invalid literal for int() with base 10: 'pgs'"  # Newton's text, whole


def test_api_three_engines_name_the_engine_that_departs() -> None:
    check = koenig_check.compare(str(CLASS_MASS), n_poses=4, formulas=["exact"], engines=ENGINES)
    comparison = check.comparisons[0]
    assert comparison.engines == ENGINES and not check.ok
    verdicts = [f for f in comparison.findings if f.kind is Kind.VERDICT]
    assert verdicts and {f.engine for f in verdicts} == {"pinocchio"}
    assert all(f.summary.startswith("Pinocchio departs (MuJoCo and Newton agree)") for f in verdicts)


def test_assert_energy_parity_with_newton() -> None:
    assert_energy_parity("double_pendulum.urdf", engines=ENGINES, n_poses=4)
    with pytest.raises(AssertionError, match=r"Pinocchio departs \(MuJoCo and Newton agree\)"):
        assert_energy_parity(CLASS_MASS, engines=ENGINES, n_poses=4)


def test_dynamics_has_newtons_column() -> None:
    result = koenig_check.dynamics("serial7.urdf", n_poses=3, formulas=["exact"], engines=ENGINES)
    assert list(result.engine_mass) == list(ENGINES)


def test_parity_command_with_newton(capsys) -> None:
    assert main(["parity", "serial7.urdf", "--engines", ",".join(ENGINES)]) == 0


def test_export_proof_with_newton_named(tmp_path: Path) -> None:
    """Named, Newton proves the export within its precision; by default (tolerance 1e-9) it is not asked to."""
    result = koenig_check.export("serial7.xml", to="urdf", out=tmp_path / "serial7.urdf", engines=ENGINES)
    proofs = {p.engine: p for p in result.proof.engines}
    assert proofs["newton"].equivalent and 0 < proofs["newton"].mass_matrix <= 1e-5
    default = koenig_check.export("serial7.xml", to="urdf", out=tmp_path / "default.urdf")
    assert "newton" not in {p.engine for p in default.proof.engines}
