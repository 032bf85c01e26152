"""``koenig-check export MODEL --to ... --out ...`` exits 1 when the file it wrote is not the same robot.

The writer is made to write link b's mass 1.1 times the original's (as a bug in it would): the proof loads the
written file back and finds the mass, so the command says "not equivalent", names the link, and exits 1 (the exit
status of a written export was not checked by any test: only ``--check-only``'s was).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from export_helpers import MODELS

import koenig_check
import koenig_check.export.api as export_api
from koenig_check.cli import main


def _write_b_scaled(monkeypatch: pytest.MonkeyPatch, factor: float) -> None:
    """Make the URDF writer multiply link b's mass by ``factor`` (1.0: the export as written)."""
    original = export_api.write_urdf

    def scaled_b(*args, **kwargs):  # type: ignore[no-untyped-def]
        text, not_carried = original(*args, **kwargs)
        root = ET.fromstring(text)
        mass = root.find("link[@name='b']/inertial/mass")
        assert mass is not None
        mass.set("value", repr(float(mass.get("value", "0")) * factor))
        return ET.tostring(root, encoding="unicode"), not_carried

    monkeypatch.setattr(export_api, "write_urdf", scaled_b)


@pytest.mark.parametrize("factor", [1.1, 1.0])
def test_a_written_export_that_differs_exits_1(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], factor: float
) -> None:
    _write_b_scaled(monkeypatch, factor)
    out = tmp_path / "hinge_ref.urdf"
    status = main(["export", str(MODELS / "hinge_ref.xml"), "--to", "urdf", "--out", str(out), "--poses", "3"])
    text = capsys.readouterr().out
    assert out.is_file()
    if factor == 1.0:
        assert status == 0 and "equivalent: max relative difference" in text
    else:
        assert status == 1 and "not equivalent" in text and "link b (joint twist): mass" in text


@pytest.mark.parametrize("factor", [1.1, 1.0])
def test_the_api_result_is_ok_exactly_when_the_proof_holds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, factor: float
) -> None:
    """``ExportResult.ok``, named as ``CrossCheck.ok``, is the proof's verdict both ways."""
    _write_b_scaled(monkeypatch, factor)
    result = koenig_check.export(MODELS / "hinge_ref.xml", to="urdf", out=tmp_path / "h.urdf", poses=3)
    assert result.ok is result.equivalent is (factor == 1.0)
