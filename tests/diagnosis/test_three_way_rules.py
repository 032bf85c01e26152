"""The three-engine rules on hand-made values: what counts as a departure of the armature energy, which cause.

* The armature (reflected-inertia) energies are compared relative to the model's whole energy at each pose
  (MuJoCo's rigid plus armature energy), not to the armature energy itself: a difference of armature energy that
  is a thousandth of a tolerance of the whole energy changes nothing the user is told.
* The cause of a departure is looked up first among the findings on the segments that depart, then among the
  engine's other root causes: a construct is named even when its finding does not list those segments.
"""

from __future__ import annotations

from pathlib import Path
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


SMALL_FIRST = Path(__file__).resolve().parents[1] / "models" / "tiebreak" / "small_cause_first.xml"


def test_the_construct_named_is_the_cause_of_largest_effect_not_the_first_found() -> None:
    """small_cause_first.xml: a 0.5 kg visual-only sphere (body a) and a 6 kg class mass (body b) Pinocchio misreads.

    By hand: body a weighs 1 + 0.5 = 1.5 kg in MuJoCo and 1 kg in Pinocchio (the visual sphere left out: 0.5 kg);
    body b's box weighs its class's 2 kg in MuJoCo and density 1000 x 0.2^3 m^3 = 8 kg in Pinocchio (6 kg).  Given in
    file order (body a's first), the verdict names the 6 kg cause, as the reason ranks it.
    """
    pytest.importorskip("pydrake")
    import koenig_check
    from koenig_check.diagnosis.reason import ordered_causes

    check = koenig_check.compare(SMALL_FIRST, n_poses=3, formulas=["exact"], engines=("mujoco", "pinocchio", "drake"))
    findings = check.comparisons[0].findings
    (light,) = [f for f in findings if f.cause == "pinocchio.mjcf.visual-geoms"]
    (heavy,) = [f for f in findings if f.cause == "pinocchio.mjcf.class-geom-mass"]
    assert (light.values["mujoco"], light.values["pinocchio"]) == pytest.approx((1.5, 1.0), rel=1e-12)
    assert (heavy.values["mujoco"], heavy.values["pinocchio"]) == pytest.approx((2.0, 8.0), rel=1e-12)
    assert ordered_causes(findings)[:2] == [heavy, light]  # the reason: 6 kg first
    assert departure_cause([light, heavy], "pinocchio") == heavy  # in file order: still the 6 kg one
    assert departure_cause([light, heavy], "pinocchio", ("ja",)) == light  # the only one on body a's segment
    (energy,) = [f for f in findings if f.kind is Kind.VERDICT and f.element == "rigid-body energy"]
    assert energy.engine == "pinocchio" and energy.summary.endswith("construct responsible: geom box")


def test_where_all_differ_each_engine_is_named_with_its_own_construct() -> None:
    """all_differ.xml: MuJoCo alone rescales to settotalmass=3, Pinocchio alone ignores the pole's class mass.

    By hand: the pole's class gives it 0.1 kg (Drake); MuJoCo rescales 1 + 0.1 kg to 3 kg (0.1 x 3 / 1.1); Pinocchio
    weighs the capsule (radius 0.045, length 1) at density 1000: 1000 (pi r^2 + 4/3 pi r^3).  The settotalmass cause
    is Pinocchio's (MuJoCo applies the option as the file asks), built so; Drake, which ignores settotalmass too
    (the catalogue's reading), gets its own finding of that id and casts no vote (it once made "all three engines
    differ" here).
    """
    pytest.importorskip("pydrake")
    import koenig_check
    from koenig_check.engines import load_model

    path = Path(__file__).resolve().parents[1] / "models" / "tiebreak" / "all_differ.xml"
    model = load_model(path, engines=("mujoco", "pinocchio", "drake"))
    model.attach("drake")
    q0, zero = np.asarray(model.mujoco.model.qpos0)[None], np.zeros((1, model.mujoco.nv))
    pole = {
        n: float(dict(zip(s.names, s.mass, strict=True))["hinge"])
        for n, s in ((n, e.segment_states(q0, zero)) for n, e in model.engines.items())
    }
    r = 0.045
    expected = {"mujoco": 0.1 * 3 / 1.1, "pinocchio": 1000 * (np.pi * r**2 + 4 / 3 * np.pi * r**3), "drake": 0.1}
    assert pole == pytest.approx(expected, rel=1e-9)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=("mujoco", "pinocchio", "drake"))
    findings = check.comparisons[0].findings
    assert not [f.message() for f in findings if f.kind is Kind.VERDICT]
    causes = {(f.engine, f.cause) for f in findings if f.root_cause and f.cause}
    assert {
        ("pinocchio", "pinocchio.mjcf.settotalmass"),
        ("pinocchio", "pinocchio.mjcf.class-geom-mass"),
        ("drake", "pinocchio.mjcf.settotalmass"),
    } <= causes
