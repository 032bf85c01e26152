"""A root pose Pinocchio's MJCF parser drops is a constant transform: with Drake named, no 'Pinocchio departs'."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.engines import load_model
from koenig_check.findings import Kind
from koenig_check.run.poses import random_pose_range

pytest.importorskip("pydrake")

POSED_ROOT = Path(__file__).resolve().parents[1] / "models" / "causes" / "posed_root.xml"
NAMED = ["mujoco", "pinocchio", "drake"]


def test_a_dropped_root_pose_gives_no_verdict_when_the_three_energies_agree() -> None:
    model = load_model(POSED_ROOT, engines=NAMED)
    model.attach("drake")
    poses = random_pose_range(model.mujoco.model, 0, 8, 0, 1.0)
    energy = {name: e.kinetic_energy(poses.qpos, poses.qvel).rigid for name, e in model.engines.items()}
    for name in ("pinocchio", "drake"):  # the premise, from the engines' own energies: the same robot
        np.testing.assert_allclose(energy[name], energy["mujoco"], rtol=1e-9)
    check = koenig_check.compare(POSED_ROOT, n_poses=8, formulas=["exact"], engines=NAMED)
    findings = check.comparisons[0].findings
    assert not [f.message() for f in findings if f.kind is Kind.VERDICT], check.reasons()
    gravity = check.comparisons[0].gravity  # gravity sees the dropped pose (issue 27): the only disagreement
    assert gravity is not None and not gravity.agrees and all(p.agrees for p in check.agreements)
    assert not check.ok and [f.cause for f in gravity.findings if f.root_cause] == ["pinocchio.mjcf.welded-root-pose"]
    assert any(f.kind is Kind.FRAME for f in findings)  # the dropped pose is still said, as a note
