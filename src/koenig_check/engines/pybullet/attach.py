"""PyBullet attached to a model already loaded in MuJoCo and Pinocchio, or loaded alone for the export's proof."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.base import Engine
from koenig_check.engines.pybullet import SPEC
from koenig_check.engines.registry import not_used
from koenig_check.exceptions import one_line
from koenig_check.findings import Finding

#: Why PyBullet does not check an MJCF file (its ``loadMJCF`` is not a reader of MuJoCo's model: measured on 3.2.7).
MJCF_REFUSAL = (
    "PyBullet reads URDF only: its loadMJCF ignores fullinertia, armature, default classes and freejoint and "
    "splits bodies, so it does not read an MJCF as written"
)


def load_alone(source: Any, mj_model: Any) -> Engine:
    """Load a URDF in PyBullet (``loadURDF`` with ``URDF_USE_INERTIA_FROM_FILE``), paired with MuJoCo's model of it.

    Parameters
    ----------
    source : koenig_check.sources.catalogue.ModelSource
    mj_model : mujoco.MjModel
        MuJoCo's model of the same file: the canonical layout; a free root joint there floats PyBullet's base.

    Returns
    -------
    PyBulletEngine

    Raises
    ------
    PyBulletLoadError
        PyBullet refuses the file (an MJCF, a missing mesh), or its joints cannot be paired with MuJoCo's.
    """
    from koenig_check.engines.mujoco.loader import root_free_joint
    from koenig_check.engines.pybullet.adapter import PyBulletEngine
    from koenig_check.engines.pybullet.client import Client, PyBulletLoadError
    from koenig_check.engines.pybullet.state_map import PyBulletStateMap, pair_joints
    from koenig_check.engines.pybullet.tree import read_tree

    path = Path(source.path)
    if source.format not in SPEC.formats:
        raise PyBulletLoadError(f"{path}: {MJCF_REFUSAL}")
    floating = root_free_joint(mj_model) is not None
    client = Client(source.package_dirs[0] if source.package_dirs else None)
    try:
        body = client.load_urdf(path, floating)
        tree = read_tree(client, body)
        pairs = pair_joints(mj_model, tree, str(path), floating)
        state_map = PyBulletStateMap(pairs, tree, mj_model.nq, mj_model.nv)
        return PyBulletEngine(client, body, tree, state_map, path, np.asarray(mj_model.qpos0))
    except BaseException:
        client.close()
        raise


def attach(model: Any) -> tuple[Engine | None, list[Finding]]:
    """Load a model's URDF in PyBullet, paired with MuJoCo's joints.

    Parameters
    ----------
    model : koenig_check.engines.LoadedModel

    Returns
    -------
    engine : PyBulletEngine or None
        None when PyBullet cannot check this model.
    findings : list of Finding
        PyBullet's load findings, or one ``ENGINE_NOT_USED`` finding with its whole reason.
    """
    from koenig_check.engines.pybullet.client import PyBulletLoadError
    from koenig_check.engines.pybullet.traps import inertial_findings, missing_meshes, option_findings, zeroed_findings
    from koenig_check.engines.refusals import refusal_cause

    source = model.source
    if model.options.pinocchio_model is not None:
        return None, [not_used("pybullet", "Pinocchio was given another file (--pinocchio-model)")]
    try:
        engine = load_alone(source, model.mujoco.model)
    except PyBulletLoadError as err:
        refusal = not_used("pybullet", one_line(err).removeprefix(f"{source.path}: "))
        if source.format not in SPEC.formats:
            return None, [replace(refusal, cause="pybullet.mjcf.load-mjcf")]
        missing = missing_meshes(Path(source.path), tuple(source.package_dirs))
        if missing:
            refusal = replace(
                refusal, values={**refusal.values, "missing meshes": missing}, cause="pybullet.urdf.missing-mesh"
            )
        else:
            refusal = replace(refusal, cause=refusal_cause("pybullet", source.path, source.format))
        return None, [refusal]
    except ImportError as err:
        return None, [not_used("pybullet", f"pybullet cannot be imported: {one_line(err)}")]
    path = Path(source.path)
    traps = inertial_findings(engine, path) + zeroed_findings(engine, path, model.mujoco.model)
    traps += option_findings(engine, source, model.mujoco.model)
    return engine, list(engine.findings) + traps
