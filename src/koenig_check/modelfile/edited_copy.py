"""A temporary copy of an MJCF file, edited for one engine's parser, that reads its includes and assets as the original.

Some parsers need a small change to a file before they read it (Drake a ``model`` name, Pinocchio no
``<keyframe>``).  The copy is written next to the original, so that relative ``<include>`` files and asset
directories resolve as they do for it; where that directory is not writable (a read-only install), it is
written to the system's temporary directory with those paths made absolute.
"""

from __future__ import annotations

import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

#: The ``<compiler>`` attributes naming directories, relative to the model file.
_DIRECTORIES = ("meshdir", "texturedir", "assetdir")


def _absolute_paths(root: ET.Element, folder: Path) -> None:
    """Make the includes and asset directories of an MJCF tree absolute, as read from ``folder``."""
    for element in root.iter("include"):
        if element.get("file"):
            element.set("file", str((folder / element.get("file", "")).resolve()))
    named = False
    for element in root.iter("compiler"):
        for attr in _DIRECTORIES:
            if element.get(attr) is not None:
                element.set(attr, str((folder / element.get(attr, "")).resolve()))
                named = True
    if not named:  # assets are then read from the model file's folder: say which, for a copy elsewhere
        root.insert(0, ET.Element("compiler", {"assetdir": str(folder.resolve())}))


@contextmanager
def edited_copy(path: str | Path, tree: ET.ElementTree[ET.Element[str]], tag: str) -> Iterator[Path]:
    """Write ``tree`` (the file at ``path``, as edited by the caller) to a temporary copy, removed afterwards.

    Parameters
    ----------
    path : str or Path
        The original MJCF file.
    tree : ElementTree
        Its parsed and edited content.
    tag : str
        A word in the copy's name, for whoever sees it in an engine's message (``drake``, ``nokeys``).

    Yields
    ------
    Path
        The copy: next to the original (a hidden file), or in the temporary directory with the includes and
        asset directories made absolute when the original's folder is not writable.
    """
    original = Path(path)
    try:
        handle = tempfile.NamedTemporaryFile(
            "wb", suffix=".xml", prefix=f".{original.stem}-{tag}-", dir=original.parent, delete=False
        )
    except OSError:
        _absolute_paths(tree.getroot(), original.parent)
        handle = tempfile.NamedTemporaryFile("wb", suffix=".xml", prefix=f"{original.stem}-{tag}-", delete=False)
    copy = Path(handle.name)
    try:
        with handle:
            tree.write(handle)
        yield copy
    finally:
        copy.unlink(missing_ok=True)
