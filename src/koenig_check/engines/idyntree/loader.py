"""A URDF read by iDynTree's ``ModelLoader`` as its users load a robot, its C++ messages kept as its reason.

What iDynTree 15.1 does, measured on the project's files and example-robot-data URDFs:

* every link with mass is a link; a massless link fixed to one other link becomes an additional *frame* of
  that link (a ROS ``base_link`` above ``base_inertia``, a tool frame), which has no kinetic energy either way;
* it has no MJCF reader: ``loadModelFromFile`` on an MJCF returns True with a model of 0 links (and prints
  ``No root link found in URDF string``): that is a refusal, said as one;
* its errors are printed from C++ to the standard error (``[ERROR] ...``): captured here
  (:mod:`koenig_check.engines.captured`), they are the reason given when it refuses a file;
* an XML declaration of a version other than 1.x (``<?xml version="0.0" ?>``, as pybullet_data's minitaur has)
  makes its XML parser print ``Unsupported version '0.0'`` and iDynTree then crashes the process (segmentation
  fault, from ``loadModelFromFile`` and ``loadModelFromString`` alike): such a file is not handed to it
  (cause ``idyntree.urdf.xml-version``).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from koenig_check.engines.captured import captured_output
from koenig_check.exceptions import ModelLoadError


class IDynTreeLoadError(ModelLoadError):
    """iDynTree refuses a file, or its joints cannot be paired with MuJoCo's (first line names the file)."""


#: The cause of a refusal of a file whose XML declaration iDynTree's parser does not read.
XML_VERSION_CAUSE = "idyntree.urdf.xml-version"

#: ``<?xml version="..."`` at the start of a file (after a byte-order mark or white space).
_DECLARATION = re.compile(rb"""\A(?:\xef\xbb\xbf)?\s*<\?xml\s+version\s*=\s*["']([^"']*)["']""")


class IDynTreeXmlVersionError(IDynTreeLoadError):
    """A file whose XML declaration would crash iDynTree (:data:`XML_VERSION_CAUSE`): it is not handed to it."""

    cause = XML_VERSION_CAUSE


def xml_version(path: Path) -> str | None:
    """The version of a file's XML declaration, or None when it has none (or cannot be read).

    Parameters
    ----------
    path : Path

    Returns
    -------
    str or None
    """
    try:
        with open(path, "rb") as f:
            head = f.read(256)
    except OSError:
        return None
    found = _DECLARATION.match(head)
    return found.group(1).decode("ascii", "replace") if found else None


def _said(printed: list[str]) -> str:
    """The lines iDynTree printed, each indented under the first line of a message."""
    lines = [line.strip() for line in "".join(printed).splitlines() if line.strip()]
    return "".join("\n    " + line for line in lines)


def load_idyntree(path: Path, package_dirs: tuple[Path, ...] = ()) -> Any:
    """Read a URDF with ``ModelLoader.loadModelFromFile``.

    Parameters
    ----------
    path : Path
    package_dirs : tuple of Path
        Directories searched for ``package://`` URIs (iDynTree reads meshes only for collision and visual shapes).

    Returns
    -------
    idyntree.swig.Model

    Raises
    ------
    IDynTreeLoadError
        iDynTree refuses the file, or reads no link from it.
    IDynTreeXmlVersionError
        The file's XML declaration is of a version other than 1.x, on which iDynTree crashes the process.
    """
    import idyntree.swig as idt

    version = xml_version(path)
    if version is not None and not version.startswith("1."):
        raise IDynTreeXmlVersionError(
            f'{path}: <?xml version="{version}"?> crashes iDynTree\'s ModelLoader (segmentation fault): not given to it'
            f"\n    [ERROR] XMLParser :: [Parsing] : Unsupported version '{version}'"
        )

    loader = idt.ModelLoader()
    printed: list[str] = []
    with captured_output(printed):
        ok = loader.loadModelFromFile(str(path), "urdf", [str(d) for d in package_dirs])
        model = loader.model().copy() if ok else None
    if model is None:
        raise IDynTreeLoadError(f"{path}: iDynTree's ModelLoader refuses the file" + _said(printed))
    if model.getNrOfLinks() == 0:
        raise IDynTreeLoadError(f"{path}: iDynTree's ModelLoader read no link from the file" + _said(printed))
    return model


def kin_dyn(model: Any) -> Any:
    """``KinDynComputations`` on a model, velocities in iDynTree's mixed representation.

    Parameters
    ----------
    model : idyntree.swig.Model

    Returns
    -------
    idyntree.swig.KinDynComputations
        The base's velocity is its origin's, in the world, and the angular velocity in the world.
    """
    import idyntree.swig as idt

    kd = idt.KinDynComputations()
    kd.loadRobotModel(model)
    kd.setFrameVelocityRepresentation(idt.MIXED_REPRESENTATION)
    return kd
