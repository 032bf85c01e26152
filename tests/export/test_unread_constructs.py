"""The ``<frame>`` elements named when an engine refuses a proof's file: for the engines whose declaration says
their MJCF parser skips ``<frame>`` (Pinocchio's and Drake's, measured), never for the others."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.engines.mujoco.loader import load_mujoco
from koenig_check.engines.specs import names
from koenig_check.export.unread_constructs import refusal_with_frames, unread_frames
from koenig_check.sources.catalogue import resolve_model

#: A hinge body inside a <frame>: the engines that skip the frame lose joint j2.
FRAME_BODY = Path(__file__).resolve().parents[1] / "models" / "causes" / "frame_body.xml"
#: The engines whose MJCF parser skips <frame> (measured on Pinocchio 4.1 and Drake 1.51).
SKIPPING = {"pinocchio", "drake"}


@pytest.fixture(scope="module")
def mj_model():
    return load_mujoco(resolve_model(str(FRAME_BODY)))[0]


@pytest.mark.parametrize("engine", names())
def test_the_frames_holding_joints_are_named_for_the_engines_that_skip_them(engine: str, mj_model) -> None:
    found = unread_frames(FRAME_BODY, mj_model, engine)
    if engine in SKIPPING:
        assert [list(f.values["joints"]) for f in found] == [["j2"]] and all(f.engine == engine for f in found)
    else:
        assert found == []


def test_a_refusal_keeps_the_engines_reason_whole_and_adds_the_frames(mj_model) -> None:
    reason = refusal_with_frames("joints do not match", FRAME_BODY, mj_model, "pinocchio")
    assert reason.startswith("joints do not match; root cause: ") and reason.endswith("(joints j2)")
    assert refusal_with_frames("joints do not match", FRAME_BODY, mj_model, "mujoco") == "joints do not match"
