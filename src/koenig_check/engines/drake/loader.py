"""Build a Drake ``MultibodyPlant`` from an MJCF or URDF file, with the base chosen like the other engines.

Drake (``pydrake``, the optional extra ``[drake]``) is the tie-breaker engine: it is imported only
here and in :mod:`koenig_check.engines.drake.adapter`, and only when asked for.

What Drake 1.51's parsers do, verified on the project's files and example-robot-data:

* A continuous plant (``time_step=0``).  Every link stays a body; a URDF fixed joint and a jointless
  MJCF body are ``WeldJoint`` s.
* MJCF: the parser refuses a file whose ``<mujoco>`` has no ``model`` attribute ("Your robot must have a
  name attribute or a model name must be specified").  The file is then parsed from a copy written
  next to it (so that includes and mesh directories resolve) whose ``model`` is the file's stem; a
  ``LOAD`` finding says so.  It ignores ``<keyframe>``, joint ``<equality>``, height fields, the
  compiler's ``settotalmass``, and the ``armature`` of a joint no ``<motor>`` drives (each with a warning,
  except ``armature``, which it drops silently).  A driven joint's armature becomes each motor's rotor inertia,
  armature / gear², with the motor's gear as gear ratio: Drake's reflected inertia, rotor inertia × gear
  ratio², is then the armature (counted once per joint, however many motors drive it).
  A joint's ``ref`` is honoured as MuJoCo does (the file's pose at ``q = ref``, Drake's default
  position; for a slide, the joint frame on the child is put ``ref`` along the axis).  A ``ball`` joint is a
  ``BallRpyJoint`` (roll-pitch-yaw coordinates, angular velocity in the parent frame); a free joint is a
  ``QuaternionFloatingJoint`` named after its body, not after the joint.
* URDF: a root link that no joint welds is given a floating joint by ``Finalize`` (the project's
  ``gimbal.urdf`` would get nq 9): the root link is welded to the world here at the file's root pose
  (identity), as MuJoCo and Pinocchio fix it, unless a floating base is asked for.  ``package://`` URIs
  resolve through Drake's package map, filled from the directories the model source knows.  Drake
  refuses a mimic joint whose leader has a different number of dofs (Talos's grippers), and warns
  (but loads) a link whose inertia has a negative principal moment (anymal's base).
* Floating base: a ``QuaternionFloatingJoint`` named :data:`~koenig_check.engines.mujoco.loader.ROOT_JOINT_NAME`
  on the body that carries MuJoCo's added free joint (replacing the weld the parser put there).

Every warning Drake prints while parsing is a ``LOAD`` finding (engine ``drake``), one per distinct
message, with the link it concerns when the line number names one.
"""

from __future__ import annotations

import logging
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from koenig_check.engines.drake.ignored_geoms import ignored_geom, ignored_geom_finding
from koenig_check.exceptions import ModelLoadError, without_build_location
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.edited_copy import edited_copy
from koenig_check.modelfile.mjcf import ROOT_TAG
from koenig_check.modelfile.validate import parse_xml
from koenig_check.sources.catalogue import ModelSource


class DrakeLoadError(ModelLoadError):
    """Drake cannot load a model file (or its joints cannot be paired with MuJoCo's); one line naming the file.

    Drake's own load error lives in Drake's subpackage; a caller that is not about Drake catches
    :class:`~koenig_check.exceptions.ModelLoadError`.
    """


_LOCATION = re.compile(r"^(?P<file>[^\s:]+):(?P<line>\d+): (?:warning|error): ")


def drake_available() -> bool:
    """Whether ``pydrake`` is installed (the optional extra ``[drake]``), without importing it.

    Importing pydrake takes a quarter of a second; a model on which MuJoCo and Pinocchio agree must
    not pay it.  A broken installation is found when Drake is first used, and reported then.

    Returns
    -------
    bool
    """
    from koenig_check.engines.registry import installed

    return installed("drake")


def drake_version() -> str:
    """The installed Drake version, or ``""``.

    Returns
    -------
    str
    """
    try:
        import importlib.metadata

        return importlib.metadata.version("drake")
    except Exception:
        return ""


class _Collect(logging.Handler):
    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.messages: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.messages.append(record.getMessage())


@contextmanager
def _drake_warnings(messages: list[str]) -> Iterator[None]:
    """Collect what Drake logs (its ``drake`` logger) instead of printing it."""
    logger = logging.getLogger("drake")
    handler = _Collect()
    previous = logger.propagate
    logger.addHandler(handler)
    logger.propagate = False
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.propagate = previous
        messages += handler.messages


def one_line_reason(text: str, path: Path) -> str:
    """Drake's whole message on one line, without repeating the file's path.

    Parameters
    ----------
    text : str
    path : Path

    Returns
    -------
    str
    """
    lines = [line.strip() for line in str(text).splitlines() if line.strip()]
    out = []
    for line in lines:
        m = _LOCATION.match(line)
        if m:
            line = f"line {m['line']}: " + line[m.end() :]
        out.append(line.replace(str(path), path.name))
    return without_build_location("; ".join(out).replace("ERROR: ", ""))


def _element_at(path: Path, line: int) -> tuple[str, str]:
    """The URDF link or joint (MJCF body or joint) open at a line of the file: its tag and name, or empty."""
    try:
        head = path.read_text(errors="replace").splitlines()[:line]
    except OSError:
        return "", ""
    for text in reversed(head):
        m = re.search(r"<(link|joint|body)\b[^>]*\bname\s*=\s*\"([^\"]*)\"", text)
        if m:
            return (m[1], m[2]) if m[2] else ("", "")
    return "", ""


def warning_findings(messages: list[str], path: Path) -> list[Finding]:
    """One ``LOAD`` finding per distinct parser warning, naming the element when its line names one.

    Parameters
    ----------
    messages : list of str
        What Drake logged.
    path : Path
        The model file.

    Returns
    -------
    list of Finding
    """
    grouped: dict[tuple[str, str, str], list[int]] = {}
    for message in messages:
        first = without_build_location(" ".join(message.split()))  # Drake's reason, not its build tree
        m = _LOCATION.match(first)
        line = int(m["line"]) if m else 0
        body = first[m.end() :] if m else first
        tag, name = _element_at(path, line) if line and "inertia" in body else ("", "")
        grouped.setdefault((tag, f"{tag} {name}" if tag else "model", body), []).append(line)
    return [
        ignored_geom_finding(path, geom, body, sorted(set(lines)) if any(lines) else [])
        if (geom := ignored_geom(body)) and path.suffix.lower() != ".urdf"
        else Finding(
            Kind.LOAD,
            "drake",
            element,
            f"parser warns: {body}",
            {"lines": sorted(set(lines))} if any(lines) else {},
            tag=tag,
        )
        for (tag, element, body), lines in grouped.items()
    ]


def _needs_model_name(path: Path) -> bool:
    try:
        root = parse_xml(path).getroot()
    except ET.ParseError:
        return False
    return root.tag == ROOT_TAG and not root.get("model")


@contextmanager
def _named_copy(path: Path) -> Iterator[Path]:
    """A copy of an MJCF file whose ``<mujoco>`` has ``model="<stem>"`` (Drake requires a model name)."""
    tree = parse_xml(path)
    tree.getroot().set("model", path.stem)
    with edited_copy(path, tree, "drake") as copy:
        yield copy


def _fill_package_map(parser: Any, source: ModelSource) -> None:
    """Make every ROS package under the source's package directories known to Drake's package map."""
    package_map = parser.package_map()
    for directory in source.package_dirs:
        if not Path(directory).is_dir():
            continue
        for child in sorted(Path(directory).iterdir()):
            if child.is_dir() and not package_map.Contains(child.name):
                package_map.Add(child.name, str(child))


def load_drake(source: ModelSource, free_joints: dict[str, str] | None = None) -> tuple[Any, list[Finding]]:
    """Parse a model file into a finalized Drake ``MultibodyPlant`` (continuous, with the gravity it read).

    Parameters
    ----------
    source : ModelSource
    free_joints : dict of str to str, optional
        Body -> joint name of every free joint MuJoCo's model has on a top-level body (the file's own
        or the one added for ``floating=True``): each such body gets a ``QuaternionFloatingJoint`` of
        that name (replacing a weld the parser gave it).  Every other root body not already jointed to
        the world is welded at its file pose.

    Returns
    -------
    plant : pydrake.multibody.plant.MultibodyPlant
    findings : list of Finding
        Loading decisions and parser warnings (kind ``LOAD``, engine ``drake``).

    Raises
    ------
    DrakeLoadError
        If Drake refuses the file: one line naming the file, with Drake's whole reason.
    """
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import MultibodyPlant

    path = Path(source.path)
    findings: list[Finding] = []
    messages: list[str] = []
    plant = MultibodyPlant(time_step=0.0)
    parser = Parser(plant)
    _fill_package_map(parser, source)
    parsed = path
    try:
        with _drake_warnings(messages):
            if source.format == "mjcf" and _needs_model_name(path):
                with _named_copy(path) as parsed:
                    parser.AddModels(parsed)
                findings.append(
                    Finding(
                        Kind.LOAD,
                        "drake",
                        "mujoco model",
                        "Drake's MJCF parser requires a model name and the file has none: parsed with the file's "
                        "stem as its name",
                        {"model": path.stem},
                    )
                )
            else:
                parser.AddModels(path)
    except RuntimeError as exc:
        reason = one_line_reason(str(exc).replace(str(parsed), str(path)), path)
        raise DrakeLoadError(f"{path}: Drake cannot load the file: {reason}") from exc
    findings += warning_findings([m.replace(str(parsed), str(path)) for m in messages], path)
    _fix_base(plant, dict(free_joints or {}), path, findings)
    try:
        plant.Finalize()
    except RuntimeError as exc:
        raise DrakeLoadError(f"{path}: Drake cannot finalize the model: {one_line_reason(str(exc), path)}") from exc
    return plant, findings


def _fix_base(plant: Any, free_joints: dict[str, str], path: Path, findings: list[Finding]) -> None:
    """Float the bodies MuJoCo floats (joint names as MuJoCo's), weld the other free root bodies at their file pose."""
    from pydrake.math import RigidTransform
    from pydrake.multibody.tree import BodyIndex, QuaternionFloatingJoint

    world = plant.world_body()
    child_of = {}
    for j in plant.GetJointIndices():
        joint = plant.get_joint(j)
        child_of[joint.child_body().index()] = joint
    for body_name, joint_name in free_joints.items():
        if not plant.HasBodyNamed(body_name):
            raise DrakeLoadError(f"{path}: Drake has no body {body_name!r} to give the free joint {joint_name!r}")
        body = plant.GetBodyByName(body_name)
        joint = child_of.pop(body.index(), None)
        if joint is not None:
            if joint.parent_body().index() != world.index() or joint.type_name() != "weld":
                raise DrakeLoadError(
                    f"{path}: body {body_name!r}: Drake joins it to {joint.parent_body().name()!r} by "
                    f"{joint.type_name()} joint {joint.name()!r}; MuJoCo gives it free joint {joint_name!r}"
                )
            plant.RemoveJoint(joint)
        child_of[body.index()] = plant.AddJoint(
            QuaternionFloatingJoint(joint_name, plant.world_frame(), body.body_frame())
        )
    welded = []
    for b in range(1, plant.num_bodies()):
        body = plant.get_body(BodyIndex(b))
        if body.index() not in child_of:
            plant.WeldFrames(plant.world_frame(), body.body_frame(), RigidTransform())
            welded.append(body.name())
    if welded:
        findings.append(
            Finding(
                Kind.LOAD,
                "drake",
                "links " + ", ".join(welded),
                "root link welded to the world at the file's pose (Drake would give it a floating base)",
            )
        )
