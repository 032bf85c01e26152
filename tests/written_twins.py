"""Twins as a user makes them: a real robot's URDF without its meshes, and the MJCF MuJoCo's own writer saves.

``MjSpec.to_xml`` writes every number with 6 significant digits, so the MJCF is the same robot as the URDF up
to that rounding: the case the rounding hint and the README's twin advice are for.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco

from koenig_check.engines import resolve_model


def written_twin(robot: str, folder: Path) -> tuple[Path, Path]:
    """Write ``ROBOT_nomesh.urdf`` (visual and collision elements removed) and ``ROBOT_mj.xml`` beside it.

    Parameters
    ----------
    robot : str
        An example-robot-data name (``ur5``, ``panda``).
    folder : Path

    Returns
    -------
    (Path, Path)
        The MJCF written by MuJoCo, then the URDF it was made from.
    """
    tree = ET.parse(resolve_model(robot).path)
    for link in tree.getroot().iter("link"):
        for child in [c for c in link if c.tag in ("visual", "collision")]:
            link.remove(child)
    urdf = folder / f"{robot}_nomesh.urdf"
    tree.write(urdf)
    mjcf = folder / f"{robot}_mj.xml"
    mjcf.write_text(mujoco.MjSpec.from_file(str(urdf)).to_xml(), encoding="utf-8")
    return mjcf, urdf
