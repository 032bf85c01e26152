"""The engines' declarations read through :mod:`koenig_check.engines.specs`: the reference and the parity pair."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

import koenig_check.engines
from koenig_check.engines import specs


def test_the_parity_pair_is_the_reference_then_the_other_required_engine() -> None:
    """Read from the subpackages' own declarations: MuJoCo declares itself the reference, Pinocchio is required."""
    from koenig_check.engines.mujoco import SPEC as MUJOCO
    from koenig_check.engines.pinocchio import SPEC as PINOCCHIO

    assert MUJOCO.reference and MUJOCO.required and PINOCCHIO.required and not PINOCCHIO.reference
    assert specs.reference() == "mujoco"
    assert specs.parity_pair() == ("mujoco", "pinocchio")


def test_a_third_required_engine_makes_the_parity_pair_refuse(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The pair is the reference and exactly one other required engine: a third one is refused, not guessed."""
    (tmp_path / "third").mkdir()
    (tmp_path / "third" / "__init__.py").write_text(
        "from koenig_check.engines.specs import EngineSpec\n\n"
        'SPEC = EngineSpec(name="third", label="Third", module="json", required=True)\n'
    )
    monkeypatch.setattr(koenig_check.engines, "__path__", [*koenig_check.engines.__path__, str(tmp_path)])
    monkeypatch.delitem(sys.modules, "koenig_check.engines.third", raising=False)
    try:
        assert "third" in specs.names()  # the premise: the engine is found
        with pytest.raises(ValueError, match="the import-parity pair is the required reference and one other"):
            specs.parity_pair()
    finally:
        sys.modules.pop("koenig_check.engines.third", None)
