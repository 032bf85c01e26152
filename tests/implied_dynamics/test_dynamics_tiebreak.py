"""`dynamics` by default: Drake is consulted where MuJoCo and Pinocchio disagree on M or Q*, not elsewhere.

class_mass.xml is a model the engines read differently (a geom mass from a default class, which Pinocchio 4.1
does not apply): independently, their own mass matrices (mj_fullM, crba) differ.  There the dynamics check must
bring in the tie-breaker, and no note may say the engines agree; on gimbal.xml, where they agree, Drake is
not run and the note says why.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from independent_energy import engines_agree
from koenig_check.engines import load_model
from koenig_check.findings import Kind
from koenig_check.implied_dynamics.analysis import dynamics

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed")

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"


@pytest.mark.parametrize(("model", "disagree"), [(CAUSES / "class_mass.xml", True), ("gimbal.xml", False)])
def test_drake_is_consulted_exactly_where_the_engines_disagree(model: Path | str, disagree: bool) -> None:
    assert engines_agree(load_model(model)) is (not disagree)
    result = dynamics(model, n_poses=2, formulas=["exact"])
    not_used = [f for f in result.findings if f.kind is Kind.ENGINE_NOT_USED and f.engine == "drake"]
    if disagree:
        assert "drake" in result.engine_mass and not not_used
        assert not any("MuJoCo and Pinocchio agree" in n for n in result.notes)
    else:
        assert "drake" not in result.engine_mass
        assert [f.summary for f in not_used] == ["Drake not used: not needed, MuJoCo and Pinocchio agree"]
