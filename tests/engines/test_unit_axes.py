"""``axisangle`` axes of other than unit length: named as the root cause of what Pinocchio reads differently.

The engines' own readings are checked directly: MuJoCo normalizes the axis (its box keeps the hand-computed
principal moments m/12 (b² + c²) = 0.8, 1.6, 2.08 kg m²), Pinocchio 4.1 does not (its moments, or its
placement's rotation matrix, change); with a unit axis both agree and no cause is given.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest

import koenig_check
from koenig_check.causes import cause as catalogued
from koenig_check.diagnosis.import_parity import import_parity
from koenig_check.engines import load_model
from koenig_check.exceptions import KoenigCheckError
from koenig_check.findings import Kind

BOX_MOMENTS = [0.8, 1.6, 2.08]  # 48 kg box of 0.2 x 0.4 x 0.6 m (density 1000)
HALF = np.sqrt(0.5)
PLACES = {
    "geom": '<body name="a"><joint name="j" axis="1 0 0"/><geom name="slab" type="box" size="0.1 0.2 0.3" '
    'pos="0.3 0 0" axisangle="{axis} 40"/></body>',
    "inertial": '<body name="a"><joint name="j" axis="1 0 0"/><inertial pos="0.3 0 0" mass="48" '
    'diaginertia="0.8 1.6 2.08" axisangle="{axis} 40"/><geom type="sphere" size="0.01" mass="0"/></body>',
    "body": '<body name="a" axisangle="{axis} 40"><joint name="j" axis="1 0 0"/><geom name="slab" type="box" '
    'size="0.1 0.2 0.3" pos="0.3 0 0"/><body name="b" pos="0 0 -1"><joint name="k" axis="0 1 0"/>'
    '<geom type="sphere" size="0.1"/></body></body>',
}
ELEMENTS = {"geom": ("geom slab", ("j",)), "inertial": ("inertial of body a", ("j",)), "body": ("body a", ("j", "k"))}


def _file(tmp_path: Path, place: str, axis: str) -> Path:
    path = tmp_path / f"{place}.xml"
    path.write_text(f"<mujoco><worldbody>{PLACES[place].format(axis=axis)}</worldbody></mujoco>")
    return path


def _pinocchio_reading(path: Path) -> tuple[np.ndarray, float]:
    """Pinocchio's principal moments of the first segment and how far its placement is from a rotation."""
    model = pin.buildModelFromMJCF(str(path))
    rotation = model.jointPlacements[1].rotation
    return np.linalg.eigvalsh(model.inertias[1].inertia), float(np.abs(rotation @ rotation.T - np.eye(3)).max())


@pytest.mark.parametrize("place", sorted(PLACES))
def test_a_unit_axis_reads_the_same_and_names_no_cause(tmp_path: Path, place: str) -> None:
    path = _file(tmp_path, place, f"{HALF} 0 {HALF}")
    mj = mujoco.MjModel.from_xml_path(str(path))
    np.testing.assert_allclose(sorted(mj.body_inertia[1]), BOX_MOMENTS, rtol=1e-9)
    moments, off = _pinocchio_reading(path)
    np.testing.assert_allclose(moments, BOX_MOMENTS, rtol=1e-9)
    assert off < 1e-12
    pair = load_model(path)
    assert not [f for f in pair.findings if "axisangle" in f.summary]
    assert koenig_check.compare(path, n_poses=3, formulas=["exact"]).ok


@pytest.mark.parametrize("place", sorted(PLACES))
def test_an_axis_of_length_sqrt2_is_the_named_cause(tmp_path: Path, place: str) -> None:
    path = _file(tmp_path, place, "1 0 1")
    mj = mujoco.MjModel.from_xml_path(str(path))  # MuJoCo normalizes: the same robot as with the unit axis
    np.testing.assert_allclose(sorted(mj.body_inertia[1]), BOX_MOMENTS, rtol=1e-9)
    moments, off = _pinocchio_reading(path)  # Pinocchio does not: other moments, or no rotation at all
    assert off > 0.1 if place == "body" else np.abs(moments - BOX_MOMENTS).max() > 0.1
    try:  # a distorted inertia or placement: refused with its cause, or compared with it
        causes = import_parity(load_model(path)).causes
    except KoenigCheckError as err:
        causes = list(err.causes)
    element, segments = ELEMENTS[place]
    (cause,) = [c for c in causes if c.cause == "pinocchio.mjcf.axisangle-length"]
    assert (cause.kind, cause.engine, cause.element) == (Kind.IGNORED_CONSTRUCT, "pinocchio", element)
    assert cause.segments == segments and cause.root_cause and cause.affects_energy
    assert cause.values["length"] == pytest.approx(np.sqrt(2.0), rel=1e-12)
    check = koenig_check.compare(path, n_poses=3, formulas=["exact"])
    assert not check.ok
    line = check.failure_lines.get(path.name) or check.reason()
    assert f"root cause: {element}: {catalogued('pinocchio.mjcf.axisangle-length').brief}" in line
