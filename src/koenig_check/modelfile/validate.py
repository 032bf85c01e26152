"""Pre-flight checks of a model file before any engine parses it.

The engines' XML parsers are not hardened against hostile input; this module reads the
file once with bounded size, refuses document type declarations (so no entity can be
expanded: no "billion laughs"), bounds the nesting depth, and tells MJCF from URDF by
the root element.  Every failure is a :class:`ModelFileError` whose one-line message
names the file and the element or line.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path
from typing import cast

from koenig_check.exceptions import ModelFileError

#: Largest model file read (bytes).
MAX_FILE_BYTES = 64 * 1024 * 1024
#: Deepest element nesting accepted.
MAX_DEPTH = 256

_DOCTYPE = re.compile(rb"<!DOCTYPE|<!ENTITY", re.IGNORECASE)


def preflight(path: str | Path) -> str:
    """Check a model file and return its format, ``"mjcf"`` or ``"urdf"``.

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    str

    Raises
    ------
    ModelFileError
        Missing, unreadable, empty, oversized, not XML, truncated, with a DOCTYPE or
        entity declaration, nested deeper than :data:`MAX_DEPTH`, or neither MJCF
        (root ``<mujoco>``) nor URDF (root ``<robot>``).
    """
    path = Path(path)
    if not path.exists():
        raise ModelFileError(f"{path}: file not found")
    if path.is_dir():
        raise ModelFileError(f"{path}: is a directory, not a model file")
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise ModelFileError(f"{path}: {size} bytes, larger than the {MAX_FILE_BYTES} bytes accepted")
        data = path.read_bytes()
    except OSError as err:
        raise ModelFileError(f"{path}: cannot be read ({err.strerror or err})") from None
    if not data.strip():
        raise ModelFileError(f"{path}: file is empty")
    match = _DOCTYPE.search(data)
    if match:
        line = data.count(b"\n", 0, match.start()) + 1
        raise ModelFileError(
            f"{path}: line {line}: DOCTYPE/ENTITY declarations are refused (entity expansion is not allowed)"
        )
    return _root_format(path, data)


#: Attributes that hold names or words, never numbers (a body may be called "nan").
_WORD_ATTRIBUTES = frozenset(
    "name class childclass type joint joint1 joint2 body body1 body2 site site1 site2 geom geom1 geom2 tendon "
    "actuator link parent child material texture mesh hfield file filename model prefix target objname refname "
    "mode refsite slidersite cranksite jointinparent sidesite tendon1 tendon2 flex objtype reftype instance plugin "
    "meshdir texturedir assetdir".split()
)


def _refuse_nan(path: Path, elem: ET.Element, ancestors: list[ET.Element] | None = None) -> None:
    """Refuse a number written as NaN: MuJoCo only warns, then uses a default (a geom's mass from its density).

    An element without a name (``<mass>``, ``<inertia>``) is named by its nearest named ancestor
    (``<link name="forearm"> <mass> value="nan"``).
    """
    for key, value in elem.attrib.items():
        if key in _WORD_ATTRIBUTES or "nan" not in value.lower():
            continue
        if any(token.lower().lstrip("+-") == "nan" for token in value.split()):
            label = f' name="{elem.attrib["name"]}"' if "name" in elem.attrib else ""
            owner = next((a for a in reversed(ancestors or []) if "name" in a.attrib), None) if not label else None
            within = f'<{owner.tag} name="{owner.attrib["name"]}"> ' if owner is not None else ""
            raise ModelFileError(
                f'{path}: {within}<{elem.tag}{label}> {key}="{value}": NaN is not a number a model can use'
            )


def _root_format(path: Path, data: bytes) -> str:
    """The format by the root element; not well-formed XML is refused only if MuJoCo's own parser refuses it too.

    Expat is stricter than TinyXML2, the parser of MuJoCo and of Pinocchio's URDF reader: a blank line
    before ``<?xml ...?>`` and a NUL byte after the last element are refused by Expat and read by both
    engines.  A pre-flight check never refuses what the engines accept: the file is checked again as
    TinyXML2 reads it (leading white space skipped, the text ending at the first NUL byte, a bare ``&`` the
    character), and when that
    fails as well, MuJoCo's parser decides; its refusal is given whole after the line and column (TinyXML2's
    own "Line number" is the line of the element it was reading: for a mismatched tag, where that element opens).
    """
    try:
        return _parse(path, data)
    except _NotWellFormedError as err:
        for text in _as_the_engines_read(data):
            try:
                return _parse(path, text)
            except _NotWellFormedError:
                pass
        refusal = _mujoco_refusal(path)
        if refusal is None and err.root_tag in _FORMATS:
            return _FORMATS[err.root_tag]  # MuJoCo reads it: the engines decide
        because = f"; MuJoCo: {refusal}" if refusal else ""  # whole: its line is where the open element starts
        raise ModelFileError(f"{path}: {err}{because}") from None


_FORMATS = {"mujoco": "mjcf", "robot": "urdf"}


def as_engines_read(data: bytes) -> bytes:
    """The bytes of a model file as TinyXML2 (MuJoCo, Pinocchio's URDF reader) reads them.

    White space before the first markup is skipped and the text ends at the first NUL byte.

    Parameters
    ----------
    data : bytes

    Returns
    -------
    bytes
    """
    return data.lstrip(b" \t\r\n").split(b"\0", 1)[0]


def parse_xml(path: str | Path) -> ET.ElementTree[ET.Element[str]]:
    """Parse a model file as written, accepting what the engines accept (see :func:`as_engines_read`).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    xml.etree.ElementTree.ElementTree

    Raises
    ------
    xml.etree.ElementTree.ParseError
        Expat's error on the file as written, when the file as the engines read it (leading white space skipped,
        the text ending at the first NUL byte, a bare ``&`` a character) does not parse either.
    OSError
        When the file cannot be read.
    """
    data = Path(path).read_bytes()
    try:
        return ET.ElementTree(ET.fromstring(data))
    except ET.ParseError as err:
        for text in _as_the_engines_read(data):
            try:
                return ET.ElementTree(ET.fromstring(text))
            except ET.ParseError:
                pass
        raise err from None


def _as_the_engines_read(data: bytes) -> list[bytes]:
    """The file's text as TinyXML2 reads it, where it differs from the text as written.

    Leading white space skipped and the text ending at the first NUL byte; then also each bare ``&`` taken as the
    character.
    """
    engines_read = as_engines_read(data)
    literal = _BARE_AMPERSAND.sub(b"&amp;", engines_read)
    return [t for t in dict.fromkeys((engines_read, literal)) if t != data]


#: An ``&`` that starts no entity or character reference (``a & b``): Expat refuses it, TinyXML2 reads it as is.
_BARE_AMPERSAND = re.compile(rb"&(?!(?:[A-Za-z_][\w.-]*|#[0-9]+|#x[0-9A-Fa-f]+);)")


class _NotWellFormedError(Exception):
    """Expat's refusal (line, column, reason) and the root element read before it, if any."""

    def __init__(self, message: str, root_tag: str | None) -> None:
        super().__init__(message)
        self.root_tag = root_tag


def _mujoco_refusal(path: Path) -> str | None:
    """MuJoCo's own reason for not parsing the file (one line), or None when it parses it."""
    import mujoco

    try:
        mujoco.MjSpec.from_file(str(path))
    except Exception as err:  # MuJoCo raises ValueError with its parser's multi-line message
        return " ".join(str(err).split())
    return None


def _parse(path: Path, data: bytes) -> str:
    parser: ET.XMLPullParser[ET.Element] = ET.XMLPullParser(events=("start", "end"))
    depth = 0
    root_tag = None
    open_elements: list[ET.Element] = []
    try:
        # Feed in chunks so that a pathological depth is caught before the tree is built.
        for i in range(0, len(data), 1 << 16):
            parser.feed(data[i : i + (1 << 16)])
            # Only "start" and "end" events were asked for: each is (event, element).
            for event, elem in cast("Iterator[tuple[str, ET.Element]]", parser.read_events()):
                if event == "start":
                    depth += 1
                    if root_tag is None:
                        root_tag = elem.tag
                    if depth > MAX_DEPTH:
                        raise ModelFileError(f"{path}: element <{elem.tag}> nested deeper than {MAX_DEPTH} levels")
                    _refuse_nan(path, elem, open_elements)
                    open_elements.append(elem)
                else:
                    depth -= 1
                    open_elements.pop()
                    elem.clear()
        parser.close()
    except ET.ParseError as err:
        line, col = err.position
        reason = str(err).split(":")[0]
        raise _NotWellFormedError(f"not well-formed XML at line {line}, column {col} ({reason})", root_tag) from None
    if root_tag in _FORMATS:
        return _FORMATS[root_tag]
    raise ModelFileError(f"{path}: root element <{root_tag}> is neither <mujoco> (MJCF) nor <robot> (URDF)")
