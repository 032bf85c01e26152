"""Newton attached to a model already loaded in MuJoCo and Pinocchio, or loaded alone on a file (the export's proof)."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.base import Engine
from koenig_check.findings import Finding


def load_newton_engine(source: Any, mj_model: Any, floating: bool = False, causes: bool = False) -> Engine:
    """Load a model file into Newton, pair its joints with MuJoCo's and build the adapter.

    Parameters
    ----------
    source : ModelSource
    mj_model : mujoco.MjModel
        The MuJoCo model of the same file (canonical layout and reference configuration).
    floating : bool
        A free-floating base asked for (Newton's ``floating=True``).
    causes : bool
        Also look for the catalogued causes that apply to the file, each sized on this robot (a few more loads).

    Returns
    -------
    NewtonEngine

    Raises
    ------
    NewtonLoadError
        Newton refuses the file, or its joints cannot be paired with MuJoCo's.
    """
    from koenig_check.engines.newton.adapter import NewtonEngine
    from koenig_check.engines.newton.loader import build, finalized, parse, warning_findings
    from koenig_check.engines.newton.state_map import FREE, NewtonStateMap, match_joints

    path = Path(source.path)
    package_dirs = tuple(getattr(source, "package_dirs", ()))
    load = partial(build, path, source.format, floating, package_dirs)
    robot, parsed = parse(path, source.format, floating, package_dirs)  # the file read once, with its meshes
    model, done = finalized(robot, path)
    warned = list(dict.fromkeys(parsed + done))
    pairs = match_joints(mj_model, model, str(path), source.format == "mjcf")
    jtype, child = model.joint_type.numpy(), model.joint_child.numpy()
    com = model.body_com.numpy()
    free_com = {p.joint: com[child[p.joint]] for p in pairs if int(jtype[p.joint]) == FREE}
    state_map = NewtonStateMap(
        pairs, int(mj_model.nq), int(mj_model.nv), int(model.joint_coord_count), int(model.joint_dof_count), free_com
    )
    engine = NewtonEngine(
        lambda copies: load(copies=copies)[0],
        model,
        state_map,
        path,
        np.asarray(mj_model.qpos0),
        warning_findings(warned),
    )
    if causes:
        from koenig_check.engines.newton.file_causes import anchor_findings, attach_causes

        segment_of_joint = _segments_of_joints(mj_model)
        engine.findings += anchor_findings(mj_model, model, pairs, segment_of_joint)
        variant = _Variants(robot, path, load)
        engine.findings += attach_causes(path, source.format, variant, model, engine.segment_of_body())
    return engine


class _Variants:
    """The file in Newton with other ``finalize`` or parser options, from the builder already parsed where they allow.

    ``finalize`` options reuse the builder (``finalize`` leaves it as it is); ``collapse_fixed_joints=True``, which
    Newton's parsers apply to the builder at the end, is applied to it in place, its last use; another parser option
    (``floating=False``), or any load after the collapse, parses the file again with ``load``.
    """

    def __init__(self, robot: Any, path: Path, load: Any) -> None:
        self.robot: Any = robot
        self.path, self.load = path, load

    def __call__(
        self, finalize: dict[str, Any] | None = None, options: dict[str, Any] | None = None
    ) -> tuple[Any, list[str]]:
        from koenig_check.engines.newton.loader import finalized

        rest = dict(options or {})
        collapse = bool(rest.pop("collapse_fixed_joints", False))
        if rest or self.robot is None:
            return self.load(finalize=finalize, options=options)
        robot = self.robot
        if collapse:
            self.robot = None
        return finalized(robot, self.path, finalize=finalize, collapse=collapse)


def _segments_of_joints(mj_model: Any) -> dict[str, str]:
    """MuJoCo joint -> the segment it moves (named after its body's last joint)."""
    from koenig_check.engines.canonical import mujoco_joint_names

    names = mujoco_joint_names(mj_model)
    out = {}
    for k, name in enumerate(names):
        body = int(mj_model.jnt_bodyid[k])
        out[name] = names[int(mj_model.body_jntadr[body] + mj_model.body_jntnum[body] - 1)]
    return out


def attach(model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load a model's file in Newton, paired with MuJoCo's joints.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel

    Returns
    -------
    engine : NewtonEngine or None
        None when Newton cannot check this model.
    findings : list of Finding
        Newton's load findings and the catalogued causes that apply to this file; or one ``ENGINE_NOT_USED``
        finding with Newton's whole reason.
    """
    from dataclasses import replace

    from koenig_check.engines.newton.loader import NewtonLoadError
    from koenig_check.engines.refusals import refusal_cause
    from koenig_check.engines.registry import ENGINE_TEXT, not_used
    from koenig_check.exceptions import one_line

    if model.options.pinocchio_model is not None:
        return None, [not_used("newton", "Pinocchio was given another file (--pinocchio-model)")]
    try:
        engine = load_newton_engine(model.source, model.mujoco.model, bool(model.options.floating), causes=True)
    except NewtonLoadError as err:  # Newton's reason, whole; the model's row already names the file
        if err.engine_text:  # the refusal on the summary's line, Newton's own text whole beside it
            refused = not_used("newton", err.reason, **{ENGINE_TEXT: err.engine_text})
        else:
            refused = not_used("newton", one_line(err).removeprefix(f"{model.source.path}: "))
        return None, [replace(refused, cause=refusal_cause("newton", model.source.path, model.source.format))]
    except ImportError as err:  # installed but not importable
        return None, [not_used("newton", f"newton cannot be imported: {err}")]
    return engine, list(engine.findings)


def load_alone(source: Any, mj_model: Any) -> Engine:
    """Load a file in Newton alone, paired with MuJoCo's model of it (the export's proof).

    Parameters
    ----------
    source : ModelSource
    mj_model : mujoco.MjModel

    Returns
    -------
    NewtonEngine
    """
    return load_newton_engine(source, mj_model)
