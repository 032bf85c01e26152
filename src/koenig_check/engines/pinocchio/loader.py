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
import re
import sys
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pinocchio as pin

from koenig_check.engines.errors import ModelLoadError
from koenig_check.exceptions import quote_engine
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.edited_copy import edited_copy
from koenig_check.modelfile.validate import parse_xml
from koenig_check.sources.catalogue import ModelSource

#: Lines of Pinocchio's C++ exception text that say where in Pinocchio's sources it was raised, not why.
_SOURCE_LOCATION = ("From file:", "in function:", "at line:", "message:")
#: Pinocchio's MJCF parser refuses a keyframe whose size is that of the file's joints, not of the model it built.
KEYFRAME_SIZE = "Keyframe size does not match model size"
#: urdfdom's line for a link's ``<visual>``, ``<collision>`` or ``<inertial>`` it could not read: it leaves that element
#: out and reads on (the result of its link parser is not checked), so the line is not why a file was refused.
_SKIPPED_ELEMENT = re.compile(r"^Could not parse (visual|collision|inertial) element for Link \[")
#: A name in brackets in urdfdom's lines (``Link [right_hip]``).
_BRACKETED = re.compile(r"\[[^\]]*\]")


def parser_reason(exc: BaseException, parser_output: list[str] | None = None) -> str:
    """Pinocchio's whole reason on one line, without the C++ source-location lines.

    Parameters
    ----------
    exc : BaseException
        What the parser raised.
    parser_output : list of str, optional
        What it printed on standard error (urdfdom's ``Error:`` lines are kept).

    Returns
    -------
    str
        Every line of the reason, joined with ``"; "``: the exception's, then urdfdom's errors, those about link
        elements it skipped and read on after last (they are not why the file was refused); one message said of
        several names (``Link [a]``, ``Link [b]``) once, with the first name and how many more.
    """
    lines = [line.strip() for line in str(exc).splitlines()]
    reason = [line for line in lines if line and not line.startswith(_SOURCE_LOCATION)]
    errors = [line[len("Error:") :].strip() for line in parser_output or [] if line.startswith("Error:")]
    reason += _folded([e for e in errors if not _SKIPPED_ELEMENT.match(e)])
    reason += _folded([e for e in errors if _SKIPPED_ELEMENT.match(e)])
    return "; ".join(dict.fromkeys(reason)) or type(exc).__name__


def _folded(lines: list[str]) -> list[str]:
    """Lines that differ only in the names in brackets, said once: the first, and how many more."""
    groups: dict[str, list[str]] = {}
    for line in dict.fromkeys(lines):
        groups.setdefault(_BRACKETED.sub("[]", line), []).append(line)
    return [same[0] + (f" (and {len(same) - 1} more)" if len(same) > 1 else "") for same in groups.values()]


def load_pinocchio(source: ModelSource, root_joint: str | None = None) -> tuple[pin.Model, list[Finding]]:
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
    findings : list of Finding
        What was decided while loading (kind ``LOAD``) and what the parser printed.

    Raises
    ------
    ModelLoadError
        If Pinocchio cannot parse the file: one line naming the file, with the parser's whole reason.

    Notes
    -----
    Pinocchio's MJCF parser checks each ``<key>`` against the model it built: with a free flyer
    added for a floating base, the file's keyframes (written for the fixed base) no longer fit and
    it refuses the file ("Keyframe size does not match model size").  Keyframes play no part in the
    model's kinetic energy, so the file is then parsed again without its ``<keyframe>`` elements
    (a copy written next to the original, so that includes and asset directories resolve), and a
    ``LOAD`` finding says so.
    """
    path = str(source.path)
    notes: list[Finding] = []
    flyer = pin.JointModelFreeFlyer()
    parser_output: list[str] = []
    try:
        with _captured_c_stderr(parser_output):
            try:
                model = _build(source, path, flyer, root_joint, notes)
            except ValueError as exc:
                if source.format != "mjcf" or not root_joint or KEYFRAME_SIZE not in str(exc):
                    raise
                with _without_keyframes(source.path) as copy:
                    model = _build(source, str(copy), flyer, root_joint, notes)
                notes.append(
                    Finding(
                        Kind.LOAD,
                        "pinocchio",
                        "keyframe",
                        "loaded without the file's keyframes: with the added free joint they no longer match the "
                        "model's size (Pinocchio refuses them); keyframes do not change the kinetic energy",
                        hint="MuJoCo keeps them (--pose-kind keyframes uses MuJoCo's)",
                    )
                )
    except ModelLoadError:
        raise  # our own refusal, already one line naming the file (not Pinocchio's parser: no "cannot parse")
    except (RuntimeError, ValueError, IndexError) as exc:  # IndexError: a name its MJCF parser looks up in vain
        reason = parser_reason(exc, parser_output)
        hint = limitation_hint(source, reason)
        error = ModelLoadError(f"{path}: Pinocchio cannot parse the file: {reason}" + (f" ({hint})" if hint else ""))
        if "hfields" in reason or _UNKNOWN_NAME in reason:  # one line: what to do stays, not in parentheses
            error.brief = f"{path}: Pinocchio cannot parse the file: {reason}; {hint}"
        error.hint = hint
        words = [line.strip() for line in [*str(exc).splitlines(), *parser_output] if line.strip()]
        quote_engine(error, "Pinocchio", "\n".join(w for w in words if not w.startswith(_SOURCE_LOCATION)))
        raise error from exc
    notes += [
        Finding(Kind.LOAD, "pinocchio", "model", f"parser says: {line}")
        for line in parser_output
        if line.startswith(("Error:", "Warning:"))
    ]
    return model, notes


def limitation_hint(source: ModelSource, reason: str) -> str:
    """What to do about a known limitation of Pinocchio's parsers, from its reason (empty when unknown).

    Parameters
    ----------
    source : ModelSource
    reason : str
        From :func:`parser_reason`.

    Returns
    -------
    str
    """
    if "hfields are not supported" in reason:
        return "give Pinocchio a copy without the <hfield> and its geoms: --pinocchio-model (pinocchio_model=...)"
    if "No such node (body)" in reason and source.format == "mjcf":
        try:
            world = parse_xml(source.path).getroot().find("worldbody")
        except ET.ParseError:
            world = None
        included = [e.get("file", "?") for e in world.findall("include")] if world is not None else []
        if included:
            return (
                f"Pinocchio's MJCF parser does not follow an <include> standing directly in <worldbody> "
                f"({', '.join(included)}): load the included robot file instead"
            )
    if KEYFRAME_SIZE in reason:
        return "the file's keyframes do not fit the model Pinocchio builds: remove <keyframe> from a copy"
    if _UNKNOWN_NAME in reason and source.format == "mjcf":
        unknown = _undefined_classes(Path(source.path))
        if unknown:
            classes = ", ".join(unknown)
            return f"class {classes}: not in the file's own <default>; Pinocchio's MJCF parser ignores <include>"
    return ""


#: What Pinocchio's MJCF parser raises (IndexError) for a name it cannot find, e.g. a default class.
_UNKNOWN_NAME = "unordered_map::at"


def _undefined_classes(path: Path) -> list[str]:
    """The default classes an MJCF file uses and does not define itself (``'soft' of joint shoulder``)."""
    try:
        root = parse_xml(path).getroot()
    except ET.ParseError:
        return []
    defined = {"main"} | {d.get("class", "main") for d in root.iter("default")}
    out: dict[str, str] = {}
    for element in root.iter():
        for attr in ("class", "childclass"):
            name = element.get(attr)
            if name is not None and name not in defined and name not in out:
                label = f" of {element.tag} {element.get('name')}" if element.get("name") else f" of a {element.tag}"
                out[name] = f"'{name}'{label}"
    return list(out.values())


@contextmanager
def _without_keyframes(path: os.PathLike[str] | str) -> Iterator[Path]:
    """A copy of an MJCF file without its ``<keyframe>`` elements (removed afterwards)."""
    tree = parse_xml(Path(path))
    for parent in list(tree.getroot().iter()):
        for child in list(parent):
            if child.tag == "keyframe":
                parent.remove(child)
    with edited_copy(Path(path), tree, "nokeys") as copy:
        yield copy


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
    source: ModelSource, path: str, flyer: pin.JointModelFreeFlyer, root_joint: str | None, notes: list[Finding]
) -> pin.Model:
    """Call the Pinocchio parser that fits the format and the root joint."""
    if source.format == "urdf":
        if root_joint and _is_floating_joint(source, root_joint):  # the file's own free joint: none is added
            root_joint = None
        stripped = _strip_world_link(source) if root_joint else None
        if stripped is not None:
            model = pin.buildModelFromXML(stripped, flyer, root_joint)
            notes.append(
                Finding(
                    Kind.LOAD,
                    "pinocchio",
                    "link world",
                    "URDF root link 'world' (MuJoCo's world body) and its fixed joint removed so that the free "
                    "joint moves the same link in both engines",
                )
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


def _is_floating_joint(source: ModelSource, name: str) -> bool:
    """Whether the URDF has a ``floating`` joint of this name (MuJoCo's import makes it the free joint)."""
    try:
        robot = parse_xml(source.path).getroot()
    except ET.ParseError:
        return False
    return any(j.get("name") == name and j.get("type") == "floating" for j in robot.findall("joint"))


def _link_of(joint: ET.Element, end: str) -> str | None:
    """Return the link named by a URDF joint's ``<parent>`` or ``<child>`` element."""
    element = joint.find(end)
    return None if element is None else element.get("link")


def _strip_world_link(source: ModelSource) -> str | None:
    """Return the URDF text without a root link named ``world`` and its fixed joint, or ``None``."""
    tree = parse_xml(source.path)
    robot = tree.getroot()
    links = {link.get("name") for link in robot.findall("link")}
    children = {_link_of(j, "child") for j in robot.findall("joint")}
    roots = links - children
    if roots != {"world"}:
        return None
    below = [j for j in robot.findall("joint") if _link_of(j, "parent") == "world"]
    if len(below) != 1 or below[0].get("type") != "fixed":
        found = ", ".join(f"{j.get('name')} ({j.get('type')})" for j in below) or "none"
        raise ModelLoadError(
            f"{source.path}: link 'world': --floating (floating=True) frees the link below 'world' only when one "
            f"fixed joint holds it; joints below 'world': {found}"
        )
    robot.remove(below[0])
    for link in robot.findall("link"):
        if link.get("name") == "world":
            robot.remove(link)
    return ET.tostring(robot, encoding="unicode")
