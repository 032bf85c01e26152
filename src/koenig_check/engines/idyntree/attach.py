"""iDynTree attached to a model already loaded in MuJoCo and Pinocchio, or loaded alone for the export's proof."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.base import Engine
from koenig_check.engines.idyntree import SPEC
from koenig_check.engines.registry import not_used
from koenig_check.exceptions import one_line
from koenig_check.findings import Finding

#: Why iDynTree does not check an MJCF file.
MJCF_REFUSAL = "iDynTree reads URDF only: its ModelLoader has no MJCF reader (it returns a model of 0 links)"


def _root_link(path: Path) -> str:
    """The URDF's root link: the one link no joint has as child ('' when the file cannot say)."""
    try:
        robot = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return ""
    children = {c.get("link") for c in robot.iter("child")}
    roots = [link.get("name", "") for link in robot.findall("link") if link.get("name") not in children]
    return roots[0] if len(roots) == 1 else ""


def _frame(model: Any, name: str) -> int:
    """The frame (link or additional frame) of that name in iDynTree's model, or -1 (without it printing an error)."""
    names = [model.getFrameName(k) for k in range(model.getNrOfFrames())]
    return names.index(name) if name in names else -1


def load_alone(source: Any, mj_model: Any) -> Engine:
    """Load a URDF in iDynTree (``ModelLoader``, ``KinDynComputations``), paired with MuJoCo's model of it.

    Parameters
    ----------
    source : koenig_check.sources.catalogue.ModelSource
    mj_model : mujoco.MjModel
        MuJoCo's model of the same file: the canonical layout; a free root joint there floats iDynTree's base.

    Returns
    -------
    IDynTreeEngine

    Raises
    ------
    IDynTreeLoadError
        iDynTree refuses the file (an MJCF), or its joints cannot be paired with MuJoCo's.
    """
    from koenig_check.engines.idyntree.adapter import IDynTreeEngine
    from koenig_check.engines.idyntree.loader import IDynTreeLoadError, kin_dyn, load_idyntree
    from koenig_check.engines.idyntree.state_map import IDynTreeStateMap, pair_joints
    from koenig_check.engines.mujoco.loader import root_free_joint

    path = Path(source.path)
    if source.format not in SPEC.formats:
        raise IDynTreeLoadError(f"{path}: {MJCF_REFUSAL}")
    model = load_idyntree(path, tuple(source.package_dirs))
    floating = root_free_joint(mj_model) is not None
    root = _root_link(path)
    root_frame = _frame(model, root)
    if root_frame < 0:
        raise IDynTreeLoadError(f"{path}: iDynTree has no link or frame named after the URDF's root link {root!r}")
    base = int(model.getFrameLink(root_frame))
    kd = kin_dyn(model)
    kd.setFloatingBase(model.getLinkName(base))
    n = model.getNrOfDOFs()
    kd.setRobotState(np.eye(4), np.zeros(n), np.zeros(6), np.zeros(n), np.zeros(3))
    root_to_base = kd.getRelativeTransform(root_frame, base).asHomogeneousTransform().toNumPy()
    pairs = pair_joints(mj_model, model, str(path), base, floating)
    state_map = IDynTreeStateMap(pairs, n, mj_model.nq, mj_model.nv, root_to_base, np.eye(4))
    return IDynTreeEngine(model, kd, state_map, path, np.asarray(mj_model.qpos0))


def attach(model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load a model's URDF in iDynTree, paired with MuJoCo's joints.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel

    Returns
    -------
    engine : IDynTreeEngine or None
        None when iDynTree cannot check this model.
    findings : list of Finding
        iDynTree's load findings, or one ``ENGINE_NOT_USED`` finding with its whole reason.
    """
    from koenig_check.engines.idyntree.loader import IDynTreeLoadError
    from koenig_check.engines.refusals import refusal_cause

    if model.options.pinocchio_model is not None:
        return None, [not_used("idyntree", "Pinocchio was given another file (--pinocchio-model)")]
    try:
        engine = load_alone(model.source, model.mujoco.model)
    except IDynTreeLoadError as err:
        refusal = not_used("idyntree", one_line(err).removeprefix(f"{model.source.path}: "))
        if model.source.format not in SPEC.formats:
            refusal = replace(refusal, cause="idyntree.mjcf.no-mjcf-reader")
        refusal = replace(refusal, cause=getattr(err, "cause", refusal.cause))
        if not refusal.cause:
            refusal = replace(refusal, cause=refusal_cause("idyntree", model.source.path, model.source.format))
        return None, [refusal]
    except ImportError as err:
        return None, [not_used("idyntree", f"idyntree cannot be imported: {one_line(err)}")]
    from koenig_check.engines.idyntree.traps import frame_findings

    return engine, list(engine.findings) + frame_findings(engine, Path(model.source.path))
