"""Why an engine could not load an MJCF file of a proof: the ``<frame>`` elements its parser skips.

An engine whose MJCF parser skips a ``<frame>`` with everything inside it (the catalogue declares its cause
``<engine>.mjcf.frame``: Pinocchio's and Drake's) misses the joints of the
bodies it holds, and the engine's joints do not match MuJoCo's.  When an engine refuses a file of a
proof (``koenig-check export --check-only``), the frames of that file that hold joints are named with what
they hold: data read from the file (:func:`koenig_check.engines.parser_traps.frame_causes`), not from the
engine's message.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from koenig_check.findings import Finding


def unread_frames(path: str | os.PathLike[str], mj_model: Any, engine: str) -> list[Finding]:
    """The ``<frame>`` causes of an MJCF file that take joints away from an engine's reading of it.

    Parameters
    ----------
    path : str or path
        The file (a URDF, or a name that is not a file, gives none).
    mj_model : mujoco.MjModel
        MuJoCo's model of the file.
    engine : str
        An engine whose ``<frame>`` cause the catalogue declares (``<engine>.mjcf.frame``); any other gives none.

    Returns
    -------
    list of Finding
        ``IGNORED_CONSTRUCT`` root causes (that cause), one per outermost frame holding joints.
    """
    from koenig_check.engines.canonical import segment_of_body
    from koenig_check.engines.parser_traps import frame_causes
    from koenig_check.modelfile.mjcf import read_mjcf

    if not Path(path).is_file():
        return []
    root = read_mjcf(Path(path))
    if root is None:
        return []
    return [f for f in frame_causes(root, segment_of_body(mj_model), engine) if f.values.get("joints")]


def refusal_with_frames(reason: str, path: str | os.PathLike[str], mj_model: Any, engine: str) -> str:
    """An engine's refusal of a file followed by the ``<frame>`` elements that explain missing joints.

    Parameters
    ----------
    reason : str
        The engine's own one-line reason (kept whole).
    path : str or path
    mj_model : mujoco.MjModel
    engine : str

    Returns
    -------
    str
        ``"<reason>; root cause: frame #1 in body base: <frame> not read by Pinocchio's MJCF parser: ... (joints
        j2)"``, or ``reason`` alone when no frame holds a joint.
    """
    causes = unread_frames(path, mj_model, engine)
    said = [f"{c.element}: {c.summary} (joints {', '.join(c.values['joints'])})" for c in causes]
    return "; ".join([reason, *(f"root cause: {s}" for s in said)])
