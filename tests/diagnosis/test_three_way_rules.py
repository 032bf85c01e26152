"""The three-engine rules on hand-made values: what counts as a departure of the armature energy, which cause.

* The armature (reflected-inertia) energies are compared relative to the model's whole energy at each pose
  (MuJoCo's rigid plus armature energy), not to the armature energy itself: a difference of armature energy that
  is a thousandth of a tolerance of the whole energy changes nothing the user is told.
* The cause of a departure is looked up first among the findings on the segments that depart, then among the
  engine's other root causes: a construct is named even when its finding does not list those segments.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from koenig_check.diagnosis.three_way import TIEBREAK_RTOL, departure_cause, energy_verdicts
from koenig_check.findings import Finding, Kind


def _runs(drake_armature: float) -> dict[str, SimpleNamespace]:
    rigid = np.array([2.0, 3.0])  # J, equal in every engine
    armature = np.array([1e-9, 2e-9])  # J: a tiny rotor inertia
    return {
        "mujoco": SimpleNamespace(rigid=rigid, armature=armature),
        "pinocchio": SimpleNamespace(rigid=rigid.copy(), armature=armature.copy()),
        "drake": SimpleNamespace(rigid=rigid.copy(), armature=armature + np.array([0.0, drake_armature])),
    }


@pytest.mark.parametrize(
    ("change", "departs"),
    [
        (1e-3 * TIEBREAK_RTOL * 3.0, False),  # a thousandth of the tolerance of the whole energy (3 J)
        (0.5 * TIEBREAK_RTOL * 3.0, False),
        (10.0 * TIEBREAK_RTOL * 3.0, True),
    ],
)
def test_armature_energy_departs_only_beyond_the_tolerance_of_the_whole_energy(change: float, departs: bool) -> None:
    verdicts = energy_verdicts(_runs(change), [])
    assert [(v.engine, v.element) for v in verdicts] == ([("drake", "armature energy")] if departs else [])
    if departs:  # the values at the pose of largest spread, each engine's own
        assert verdicts[0].values == pytest.approx({"mujoco": 2e-9, "pinocchio": 2e-9, "drake": 2e-9 + change})


def test_a_cause_outside_the_departing_segments_is_still_named() -> None:
    elsewhere = Finding(
        Kind.IGNORED_CONSTRUCT,
        "drake",
        "joint armature",
        "not read",
        affects_energy=True,
        root_cause=True,
        segments=("elbow",),
    )
    here = Finding(Kind.MASS, "drake", "link wrist", "mass", affects_energy=True, root_cause=True, segments=("wrist",))
    assert departure_cause([elsewhere], "drake", ["shoulder"]) is elsewhere
    assert departure_cause([elsewhere, here], "drake", ["wrist"]) is here
    assert departure_cause([elsewhere], "mujoco", ["shoulder"]) is None
