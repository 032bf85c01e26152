"""The catalogued cause of an engine's refusal of a file, read from the file as written.

A cause whose catalogue reading says an engine ``"refuses"`` the construct (for its installed version) may declare
how the construct shows in the file: ``FILE_SIGNS`` of the cause's own subpackage (``engines/<name>/causes.py``),
cause id to a test of the parsed file. When an engine refuses a file, :func:`refusal_cause` gives the first such
cause whose sign the file shows, so that the refusal carries the id (and its hint) whichever engine refused: Newton
and Drake both refuse a ``<mimic>`` inside a fixed URDF joint, a cause declared once, by Newton. The engine's
message is never read.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path

from koenig_check.engines.catalogue import applies, catalogue, cause_modules
from koenig_check.engines.specs import specs


def file_signs() -> dict[str, Callable[[ET.Element], bool]]:
    """Every declared sign, by cause id (each engine subpackage's ``causes.FILE_SIGNS``), in declaration order.

    Returns
    -------
    dict of str to callable
        ``sign(root) -> bool`` on the file's parsed root element.

    Raises
    ------
    ValueError
        A sign names a cause the catalogue does not declare.
    """
    known = {c.id for c in catalogue()}
    signs: dict[str, Callable[[ET.Element], bool]] = {}
    for _, module in cause_modules(specs()):
        declared = getattr(module, "FILE_SIGNS", {})
        unknown = sorted(set(declared) - known)
        if unknown:
            raise ValueError(
                f"{module.__name__}.FILE_SIGNS names causes the catalogue does not declare: {', '.join(unknown)}"
            )
        signs.update(declared)
    return signs


def refusal_cause(engine: str, path: str | Path, fmt: str) -> str:
    """The catalogued construct that explains why ``engine`` refused a file, or ``""``.

    Parameters
    ----------
    engine : str
        The engine that refused.
    path : str or Path
        The file it refused.
    fmt : str
        Its format (``"mjcf"``, ``"urdf"``): only the causes of that format are looked for.

    Returns
    -------
    str
        A cause id whose catalogue reading says ``engine`` refuses it (for its installed version) and whose sign
        the file shows, the first in the order the signs are declared (the order the engine meets the
        constructs); empty when none does or the file cannot be read.
    """
    from koenig_check.modelfile.validate import parse_xml

    signs = file_signs()
    refused = {
        c.id
        for c in catalogue()
        if fmt in c.formats and any(r.engine == engine and r.reads == "refuses" for r in c.readings)
    }
    # In the order the signs are declared: the order the engine meets the constructs (a file may show several).
    candidates = [cause_id for cause_id in signs if cause_id in refused and applies(cause_id, engine)]
    if not candidates:
        return ""
    try:
        root = parse_xml(Path(path)).getroot()
    except Exception:  # unreadable: the engines that read it say why
        return ""
    return next((cause_id for cause_id in candidates if signs[cause_id](root)), "")
