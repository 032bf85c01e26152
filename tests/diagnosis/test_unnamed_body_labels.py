"""An unnamed body is named by its place (issue 28, item 5): Menagerie's umi_gripper gave "both: body : inertia
differs" in ``records.json``.  The model: an unnamed body whose geom's mass Pinocchio does not read as MuJoCo does."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.cli import main

MODEL = Path(__file__).parent / "models" / "unnamed_body_mass.xml"
LABEL = "unnamed body in body a (joint j2)"


def test_the_engines_differ_on_the_unnamed_body() -> None:
    """Each engine's own mass for it: MuJoCo the class mass 2 kg, Pinocchio density × volume (by hand)."""
    mj = mujoco.MjModel.from_xml_path(str(MODEL))
    unnamed = [b for b in range(1, mj.nbody) if not mj.body(b).name]
    assert len(unnamed) == 1 and mj.body_mass[unnamed[0]] == pytest.approx(2.0)
    pm = pin.buildModelFromMJCF(str(MODEL))
    volume = math.pi * 0.05**2 * 0.5 + 4 / 3 * math.pi * 0.05**3
    assert pm.inertias[pm.getJointId("j2")].mass == pytest.approx(1000 * volume, rel=1e-12)


def test_no_finding_names_a_body_without_its_name_or_place() -> None:
    check = koenig_check.compare(MODEL, n_poses=3)
    assert not check.ok
    (comparison,) = check.comparisons
    assert comparison.segment_labels["j2"] == LABEL
    elements = [f.element for f in comparison.findings]
    assert all(e.split(" ", 1)[-1].strip() for e in elements if e.startswith(("body", "link"))), elements
    assert any(LABEL in e for e in elements), elements
    assert all("body :" not in f.message() and "body  " not in f.message() for f in comparison.findings)
    assert LABEL in check.reason() and "body :" not in check.reason()


def test_parity_names_it_in_its_table_and_notes(capsys: pytest.CaptureFixture[str]) -> None:
    main(["parity", str(MODEL)])
    out = capsys.readouterr().out
    assert any(line.startswith(LABEL) for line in out.splitlines())
    assert "'?'" not in out and "body :" not in out
    assert "body, unnamed, with joint 'j2' has no <inertial>" in out
