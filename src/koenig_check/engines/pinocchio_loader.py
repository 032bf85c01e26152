"""Build a Pinocchio ``Model`` from an MJCF or URDF file.

Pinocchio's kinematic/dynamic model never reads meshes, so ``package://`` URIs need no
resolution here (``package_dirs`` only matter for geometry models, which this project does not
build).  A floating base is a ``JointModelFreeFlyer`` named :data:`ROOT_JOINT_NAME`.

A URDF whose root link is named ``world`` is special: MuJoCo's importer turns that link into its
world body, so its child becomes MuJoCo's top body and carries the added free joint.  For a
floating base Pinocchio would put the free flyer on the ``world`` link instead (a different frame
whenever the fixed joint below it has a non-identity origin, e.g. ``TwoDofs``), so the ``world``
link and its fixed joint are removed from the XML given to Pinocchio.
"""

from __future__ import annotations

import os
import sys
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from contextlib import contextmanager

import pinocchio as pin

from koenig_check.engines.errors import ModelLoadError
from koenig_check.engines.sources import ModelSource


def load_pinocchio(source: ModelSource, root_joint: str | None = None) -> tuple[pin.Model, list[str]]:
    """Parse a model file into Pinocchio.

    Parameters
    ----------
    source : ModelSource
    root_joint : str, optional
        Make the base floating with a free flyer of this name, unless the file's root already
        has a free joint (MJCF ``<freejoint>``), which is then kept with its own name.

    Returns
    -------
    model : pinocchio.Model
    notes : list of str

    Raises
    ------
    ModelLoadError
        If Pinocchio cannot parse the file.
    """
    path = str(source.path)
    notes: list[str] = []
    flyer = pin.JointModelFreeFlyer()
    parser_output: list[str] = []
    try:
        with _captured_c_stderr(parser_output):
            model = _build(source, path, flyer, root_joint, notes)
    except (RuntimeError, ValueError) as exc:
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        detail = next((line for line in parser_output if line.startswith("Error:")), "")
        detail = f" ({detail[len('Error:') :].strip()})" if detail else ""
        raise ModelLoadError(f"{path}: Pinocchio cannot parse the file: {first}{detail}") from exc
    notes += [f"pinocchio: parser says: {line}" for line in parser_output if line.startswith(("Error:", "Warning:"))]
    return model, notes


@contextmanager
def _captured_c_stderr(lines: list[str]) -> Iterator[None]:
    """Collect what C++ code (urdfdom's console bridge) prints on file descriptor 2, instead of showing it."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile(mode="w+b") as sink:
        os.dup2(sink.fileno(), 2)
        try:
            yield
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            text = sink.read().decode("utf-8", errors="replace")
            lines += [line.strip() for line in text.splitlines() if line.strip() and not line.strip().startswith("at ")]


def _build(
    source: ModelSource, path: str, flyer: pin.JointModelFreeFlyer, root_joint: str | None, notes: list[str]
) -> pin.Model:
    """Call the Pinocchio parser that fits the format and the root joint."""
    if source.format == "urdf":
        stripped = _strip_world_link(source) if root_joint else None
        if stripped is not None:
            model = pin.buildModelFromXML(stripped, flyer, root_joint)
            notes.append(
                "pinocchio: URDF root link 'world' (MuJoCo's world body) and its fixed joint removed so "
                "that the free joint moves the same link in both engines"
            )
        elif root_joint:
            model = pin.buildModelFromUrdf(path, flyer, root_joint)
        else:
            model = pin.buildModelFromUrdf(path)
    else:
        model = pin.buildModelFromMJCF(path)
        has_free = model.njoints > 1 and model.joints[1].shortname() == "JointModelFreeFlyer"
        if root_joint and not has_free:
            model = pin.buildModelFromMJCFAndRootJoint(path, flyer, root_joint)
    return model


def _link_of(joint: ET.Element, end: str) -> str | None:
    """Return the link named by a URDF joint's ``<parent>`` or ``<child>`` element."""
    element = joint.find(end)
    return None if element is None else element.get("link")


def _strip_world_link(source: ModelSource) -> str | None:
    """Return the URDF text without a root link named ``world`` and its fixed joint, or ``None``."""
    tree = ET.parse(source.path)
    robot = tree.getroot()
    links = {link.get("name") for link in robot.findall("link")}
    children = {_link_of(j, "child") for j in robot.findall("joint")}
    roots = links - children
    if roots != {"world"}:
        return None
    below = [j for j in robot.findall("joint") if _link_of(j, "parent") == "world"]
    if len(below) != 1 or below[0].get("type") != "fixed":
        names = [j.get("name") for j in below]
        raise ModelLoadError(
            f"{source.path}: link 'world': floating=True needs exactly one fixed joint below it, found {names}"
        )
    robot.remove(below[0])
    for link in robot.findall("link"):
        if link.get("name") == "world":
            robot.remove(link)
    return ET.tostring(robot, encoding="unicode")
