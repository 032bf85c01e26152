"""Geoms with ``contype="0" conaffinity="0"``: the geoms Pinocchio reads as visual only are named as the root cause.

Gymnasium's swimmer gives every geom ``contype="0" conaffinity="0"`` through its main default; MuJoCo weighs
them, Pinocchio 4.1's MJCF parser leaves them out, and the old verdict named only the symptom ("segment
free_body_rot: massless in Pinocchio").  Expected masses are computed by hand (density 1000 × volume) and
confirmed from each engine's own model (``MjModel.body_mass``, Pinocchio's inertias); the disagreement itself
from the engines' mass matrices (:mod:`independent_energy`).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest

import koenig_check
from independent_energy import engines_agree
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.diagnosis.reason import short_cause
from koenig_check.engines import load_model
from koenig_check.findings import Kind

CAUSES = Path(__file__).resolve().parents[1] / "models" / "causes"
BOX = 1000.0 * 0.2 * 0.4 * 0.6  # body a's box (class touch): collides, weighs in both engines
BALL = 1000.0 * 4.0 / 3.0 * np.pi * 0.2**3  # body a's sphere (class look): visual only
ROD = 1000.0 * (4.0 / 3.0 * np.pi * 0.05**3 + np.pi * 0.05**2 * 0.5)  # body b's capsule (main default): visual only
TIP = 1000.0 * 4.0 / 3.0 * np.pi * 0.1**3  # body b's sphere, contype 0 and conaffinity 1: weighs in both engines
HAS_DRAKE = importlib.util.find_spec("pydrake") is not None

#: (edit of the file, the geoms Pinocchio leaves out, their segments, Pinocchio's mass of j and of j2).
CASES = {
    "as written": (lambda t: t, ("ball", "rod"), ("j", "j2"), (BOX, TIP)),
    "ball collides": (
        lambda t: t.replace(
            '<default class="look">\n      <geom contype="0"', '<default class="look">\n      <geom contype="1"'
        ),
        ("rod",),
        ("j2",),
        (BOX + BALL, TIP),
    ),
    "b massless in Pinocchio": (
        lambda t: t.replace('conaffinity="1"/>', 'conaffinity="0"/>'),
        ("ball", "rod", "tip"),
        ("j", "j2"),
        (BOX, 0.0),
    ),
    "nothing visual": (lambda t: t.replace('conaffinity="0"', 'conaffinity="1"'), (), (), (BOX + BALL, ROD + TIP)),
}


def _visual_causes(path: Path) -> list:
    return [c for c in import_parity(load_model(path)).causes if "visual only" in c.summary]


def _written(tmp_path: Path, case: str) -> Path:
    path = tmp_path / "visual_geom.xml"
    text = (CAUSES / "visual_geom.xml").read_text()
    edited = CASES[case][0](text)
    assert case == "as written" or edited != text  # the edit took
    path.write_text(edited)
    return path


@pytest.mark.parametrize("case", list(CASES))
def test_the_engines_own_masses_differ_by_the_visual_geoms(tmp_path: Path, case: str) -> None:
    path = _written(tmp_path, case)
    m = mujoco.MjModel.from_xml_path(str(path))
    p = pin.buildModelFromMJCF(str(path))
    assert m.body("a").mass[0] == pytest.approx(BOX + BALL, rel=1e-12)  # MuJoCo weighs every geom
    assert m.body("b").mass[0] == pytest.approx(ROD + TIP, rel=1e-12)
    pin_j, pin_j2 = CASES[case][3]
    assert p.inertias[p.getJointId("j")].mass == pytest.approx(pin_j, rel=1e-12, abs=1e-12)
    assert p.inertias[p.getJointId("j2")].mass == pytest.approx(pin_j2, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("case", list(CASES))
def test_visual_geoms_are_the_named_cause(tmp_path: Path, case: str) -> None:
    _, left_out, segments, (pin_j, pin_j2) = CASES[case]
    path = _written(tmp_path, case)
    pair = load_model(path)
    causes = _visual_causes(path)
    assert engines_agree(pair) is (not left_out)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert check.ok is (not left_out)
    if not left_out:
        assert causes == []
        return
    (cause,) = causes
    assert (cause.kind, cause.engine) == (Kind.MASS, "pinocchio") and cause.root_cause and cause.affects_energy
    assert cause.values["geoms"] == left_out and cause.segments == segments
    mujoco_mass = {"j": BOX + BALL, "j2": ROD + TIP}
    pinocchio_mass = {"j": pin_j, "j2": pin_j2}
    assert cause.values["mujoco"] == pytest.approx(sum(mujoco_mass[s] for s in segments), rel=1e-12)
    assert cause.values["pinocchio"] == pytest.approx(sum(pinocchio_mass[s] for s in segments), rel=1e-12)
    assert cause.values["mujoco, visual geoms left out"] == pytest.approx(cause.values["pinocchio"], abs=1e-9)
    assert short_cause(cause) in check.reason()
    assert f"{cause.element}: {cause.summary}" in check.agreements[0].reason
    assert "massless" not in check.agreements[0].reason  # the symptom is not a second root cause


@pytest.mark.skipif(not HAS_DRAKE, reason="Drake (the optional extra [drake]) is not installed")
def test_three_engines_name_the_geoms_pinocchio_leaves_out() -> None:
    check = koenig_check.compare(
        CAUSES / "visual_geom.xml", n_poses=3, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"]
    )
    verdicts = [f for f in check.comparisons[0].findings if f.kind is Kind.VERDICT]
    assert verdicts and all(v.engine == "pinocchio" for v in verdicts)
    assert all("construct responsible: geom ball, rod" in v.summary for v in verdicts)
