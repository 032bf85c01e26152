"""A geom Drake's MJCF parser ignores (a box given by ``fromto``): Drake checks another robot, and says which geom.

The box weighs density × volume = 1000 × 0.1 × 0.1 × 0.5 = 5 kg in MuJoCo (computed by hand; MuJoCo's own
body mass is checked against it); Drake warns that it ignores the geom.  With the geom's mass written as 0 the
robot is the same in every engine and Drake votes as usual.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import koenig_check
from koenig_check.findings import Kind

pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed: its tests are skipped")

BOX = 1000.0 * 0.1 * 0.1 * 0.5  # kg: half-sizes 0.05 x 0.05, length 0.5 along the fromto segment
ARM = 1000.0 * 0.2 * 0.2 * 0.2  # kg: the 0.2 m cube every engine reads
FILE = """<mujoco model="fromto_box"><worldbody><body name="arm">
  <joint name="hinge" axis="0 1 0"/>
  <geom name="cube" type="box" size="0.1 0.1 0.1" pos="0.3 0 0"/>
  <geom name="slab" type="box" fromto="0 0 0 0 0 -0.5" size="0.05 0.05 0.05"{mass}/>
</body></worldbody></mujoco>"""
ENGINES = ["mujoco", "pinocchio", "drake"]


def _file(tmp_path: Path, mass: str) -> Path:
    path = tmp_path / "fromto_box.xml"
    path.write_text(FILE.format(mass=mass))
    return path


@pytest.mark.parametrize(("mass", "weighs"), [("", True), (' mass="0"', False)])
def test_a_geom_drake_ignores_is_named_and_takes_its_vote_when_it_weighs(
    tmp_path: Path, mass: str, weighs: bool
) -> None:
    path = _file(tmp_path, mass)
    assert mujoco.MjModel.from_xml_path(str(path)).body("arm").mass[0] == pytest.approx(ARM + BOX * weighs, rel=1e-12)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"], engines=ENGINES)
    findings = check.comparisons[0].findings
    (ignored,) = [f for f in findings if f.engine == "drake" and f.element == "geom slab"]
    assert "will be ignored" in ignored.summary  # Drake's own warning, whole
    assert ignored.kind is Kind.IGNORED_CONSTRUCT and ignored.affects_energy is weighs
    assert ignored.values["mujoco"] == pytest.approx(BOX * weighs, abs=1e-12)
    unable = [f for f in findings if f.kind is Kind.ENGINE_UNABLE]
    verdicts = [f for f in findings if f.kind is Kind.VERDICT]
    if weighs:  # Drake read another robot: no vote, and named, the model fails saying which geom
        assert len(unable) == 1 and "geom slab" in unable[0].summary and not verdicts and not check.ok
    else:
        assert not unable and not verdicts and check.ok
