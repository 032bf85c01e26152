"""Rewording a finding changes no verdict: grouping, ordering and blame are keyed on cause ids and values.

Every :class:`~koenig_check.findings.Finding` built while comparing is given another summary (a digest of the
original, so that two equal summaries stay equal and two different ones stay different); the verdicts, the
engines blamed, the causes named and their order must be those of the run with the real words.
"""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Any

import pytest

import koenig_check
from koenig_check.causes import catalogue, fixture_path
from koenig_check.diagnosis.cause_groups import cause_groups
from koenig_check.diagnosis.reason import root_cause_groups
from koenig_check.engines import load_model
from koenig_check.exceptions import KoenigCheckError
from koenig_check.findings import Finding, Kind

TESTS = Path(__file__).resolve().parents[1]
#: The catalogue's fixtures and the corpus's files with several causes or a three-engine verdict.
FILES = sorted(
    {fixture_path(c) for c in catalogue()}
    | {TESTS / "models" / "causes" / n for n in ("include_and_roots.xml", "class_geom_inertial.xml", "frame_body.xml")}
    | {TESTS / "models" / "tiebreak" / n for n in ("all_differ.xml", "settotalmass.xml", "hinge_ref.xml")},
    key=lambda p: p.name,
)


def _outcome(path: Path) -> dict[str, Any]:
    """What a comparison decides about a file, without any of its words."""
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=["mujoco", "pinocchio", "drake"])
    out: dict[str, Any] = {"ok": check.ok, "failed": [name for name, _ in check.failures]}
    for comp in check.comparisons:
        findings = comp.findings
        out["verdicts"] = [(f.engine, f.element, f.cause) for f in findings if f.kind is Kind.VERDICT]
        out["groups"] = [
            [(f.cause, f.kind.value, f.engine, f.element, f.segments) for f in g.findings]
            for g in root_cause_groups(findings)
        ]
        out["lost"] = [g.lost_joints() for g in root_cause_groups(findings)]
    if check.failures:
        try:
            load_model(path)
        except KoenigCheckError as err:
            groups = cause_groups(err.causes)
            out["refusal causes"] = [[(f.cause, f.kind.value, f.engine, f.element) for f in g.findings] for g in groups]
            out["refusal lost"] = [g.lost_joints() for g in groups]
    return out


def _reworded(monkeypatch: pytest.MonkeyPatch) -> None:
    original = Finding.__post_init__

    def post_init(self: Finding) -> None:
        original(self)
        digest = hashlib.sha1(self.summary.encode()).hexdigest()[:12]
        object.__setattr__(self, "summary", f"reworded {digest}")

    monkeypatch.setattr(Finding, "__post_init__", post_init)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_rewording_every_summary_changes_no_verdict_and_no_order(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("pydrake")
    as_written = _outcome(path)
    _reworded(monkeypatch)
    assert Finding(Kind.LOAD, "mujoco", "model", "words").summary.startswith("reworded ")  # the rewording is on
    assert _outcome(path) == as_written
