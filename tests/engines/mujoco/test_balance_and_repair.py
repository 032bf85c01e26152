"""``--balance-inertia`` and ``--repair-inertia`` together: each link changed by one of them, named once, by its own.

rod_and_plate.urdf welds three refused links to a moving arm (fusestatic fuses them away, so the balance findings
are read from the file compiled again without fusing).  The rod's zero principal moment is MuJoCo's refusal
whatever ``balanceinertia`` does: only the repair loads it.  The plate's moments (0.1, 0.1, 0.25) break
``A + B >= C``; MuJoCo's ``balanceinertia`` makes them all their mean, (0.1 + 0.1 + 0.25) / 3 = 0.15 (by hand).
The shell's full inertia has a negative eigenvalue: only the repair loads it (and balances it on the way), so it
is the repair's finding alone, never also a balance finding.
Both options together failed to load the file (the balance findings' second compilation lacked the repair).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.findings import Kind

MODEL = Path(__file__).resolve().parents[1] / "models" / "rod_and_plate.urdf"


def _repairs(options: dict[str, bool]) -> dict[str, list[str]]:
    pair = load_model(MODEL, **options)
    out: dict[str, list[str]] = {}
    for f in pair.findings:
        if f.kind is Kind.REPAIR:
            out.setdefault(f.element, []).append(f.summary)
    return out


def test_both_options_load_the_file_each_link_named_once_by_what_changed_it() -> None:
    pair = load_model(MODEL, balance_inertia=True, repair_inertia=True)
    found = {f.element: f for f in pair.findings if f.kind is Kind.REPAIR}
    assert sorted(found) == ["link plate", "link rod", "link shell"]
    for link in ("link rod", "link shell"):  # one finding each, the repair's
        assert sum(f.element == link for f in pair.findings if f.kind is Kind.REPAIR) == 1
        assert "so that MuJoCo accepts" in found[link].summary
    rod, plate = found["link rod"], found["link plate"]
    assert "so that MuJoCo accepts" in rod.summary and "balanceinertia" not in rod.summary
    assert rod.values["moments before"] == [0.0, 0.002, 0.002]
    assert 0 < rod.values["moments after"][0] < 1e-12 and rod.values["moments after"][1:] == pytest.approx([0.002] * 2)
    assert "balanceinertia" in plate.summary
    assert plate.values["moments before"] == pytest.approx([0.1, 0.1, 0.25])
    assert plate.values["moments after"] == pytest.approx([0.15, 0.15, 0.15], rel=1e-12)
    assert plate.values["max relative change"] == pytest.approx(0.1 / 0.25)


@pytest.mark.parametrize(
    ("options", "expected"),
    [
        ({"repair_inertia": True}, {"link plate": "accepts", "link rod": "accepts", "link shell": "accepts"}),
        (
            {"balance_inertia": True, "repair_inertia": True},
            {"link plate": "balanceinertia", "link rod": "accepts", "link shell": "accepts"},
        ),
    ],
)
def test_the_arm_carries_the_welded_links_as_changed(options: dict[str, bool], expected: dict[str, str]) -> None:
    """Each option set names each link once, with the change that loaded it; the arm's mass is the file's."""
    repairs = _repairs(options)
    assert {k: len(v) for k, v in repairs.items()} == dict.fromkeys(expected, 1)
    for element, word in expected.items():
        assert word in repairs[element][0], repairs[element]
    pair = load_model(MODEL, **options)
    q0 = np.asarray(pair.mujoco.model.qpos0, dtype=float)[None]
    mass = pair.mujoco.segment_states(q0, np.zeros((1, pair.mujoco.nv))).mass
    assert mass == pytest.approx([2.0 + 0.5 + 1.0 + 0.2])  # arm, rod, plate and shell, as the file writes them


def test_a_body_balanceinertia_leaves_as_written_is_no_finding() -> None:
    """A zero principal moment with A + B >= C: MuJoCo compiles it unchanged (read back from its own model), so no
    finding may say balanceinertia changed it (one said so, with 'max relative change' 0)."""
    path = MODEL.parent / "static_rod.xml"
    compiled = mujoco.MjModel.from_xml_path(str(path))  # MuJoCo alone, balanceinertia off
    balanced_spec = mujoco.MjSpec.from_file(str(path))
    balanced_spec.compiler.balanceinertia = True
    balanced = balanced_spec.compile()
    assert np.array_equal(balanced.body_inertia, compiled.body_inertia)
    pair = load_model(path, balance_inertia=True)
    assert [f.message() for f in pair.findings if f.kind is Kind.REPAIR] == []
