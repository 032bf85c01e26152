"""A file Expat refuses but both engines read is checked, not refused by the pre-flight.

TinyXML2 (MuJoCo's parser, and Pinocchio's for MJCF) reads a bare ``&`` in an attribute as the character; Expat
refuses it.  The file is read again with each bare ``&`` escaped; an ``&`` in the root element's own start tag
(``<mujoco model="arm & base">``) used to be refused, and in a URDF it passed the pre-flight and failed in our
mimic-joint reader.  Otherwise the pre-flight asks MuJoCo before refusing: when MuJoCo reads the file, the root
element decides the format (``--`` inside a comment).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.modelfile.validate import preflight

_ARM = """<mujoco model="{model}">
  <worldbody>{comment}
    <body name="upper">
      <joint name="shoulder" type="hinge" axis="0 1 0"/>
      <geom name="{geom}" type="capsule" fromto="0 0 0 0.3 0 0" size="0.02" mass="1.5"/>
      <body name="lower" pos="0.3 0 0">
        <joint name="elbow" type="hinge" axis="0 0 1"/>
        <geom type="box" size="0.1 0.02 0.03" pos="0.1 0 0" mass="0.7"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

_CASES = {
    "ampersand-in-the-root-tag": {"model": "arm & base", "geom": "upper_geom", "comment": ""},
    "ampersand-in-a-geom-name": {"model": "arm", "geom": "upper & geom", "comment": ""},
    # Expat refuses "--" inside a comment whatever the text around it: MuJoCo's reading decides
    "double-hyphen-in-a-comment": {"model": "arm", "geom": "upper_geom", "comment": "\n    <!-- upper -- lower -->"},
}


@pytest.mark.parametrize("case", sorted(_CASES))
def test_a_file_both_engines_read_is_checked_not_refused(tmp_path: Path, case: str) -> None:
    path = tmp_path / "arm.xml"
    path.write_text(_ARM.format(**_CASES[case]))
    mj = mujoco.MjModel.from_xml_path(str(path))  # the engines' own readers accept it
    pn = pin.buildModelFromMJCF(str(path))
    assert (mj.nv, pn.nv) == (2, 2)
    assert preflight(path) == "mjcf"
    check = koenig_check.compare([path], n_poses=4, seed=2)
    assert not check.failures, check.failures
    assert check.ok, check.reason()
    assert sum(c.n_poses for c in check.comparisons) == 4


MODELS = Path(__file__).parents[2] / "models"


def test_a_urdf_with_a_bare_ampersand_both_engines_read_is_the_same_robot(tmp_path: Path) -> None:
    """``<robot name="serial7 & co">``: MuJoCo and Pinocchio read it; every reader of ours must too (the URDF's
    mimic joints were read by Expat, which refused the file after the pre-flight let it through)."""
    import numpy as np

    text = (MODELS / "serial7.urdf").read_text()
    assert text.count('<robot name="serial7">') == 1
    path = tmp_path / "serial7.urdf"
    path.write_text(text.replace('<robot name="serial7">', '<robot name="serial7 & co">'))
    assert mujoco.MjModel.from_xml_path(str(path)).nv == pin.buildModelFromUrdf(str(path)).nv == 7
    check = koenig_check.compare([path], n_poses=4, seed=2, keep_records=True)
    original = koenig_check.compare([MODELS / "serial7.urdf"], n_poses=4, seed=2, keep_records=True)
    assert not check.failures, check.failures
    assert check.ok, check.reason()
    for name in ("value", "reference_value"):
        got, want = (np.asarray(c.comparisons[0].records[name]) for c in (check, original))
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-300, err_msg=name)
