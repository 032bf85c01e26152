"""A model file in Drake, paired with MuJoCo's compiled model: the adapter, its joints' anchors, its free joints."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.engines.drake.adapter import DrakeEngine
from koenig_check.engines.drake.state_map import DrakeStateMap
from koenig_check.findings import Finding, Kind


def load_drake_engine(source: Any, mj_model: mujoco.MjModel) -> DrakeEngine:
    """Load a model file into Drake, pair its joints with MuJoCo's and build the adapter.

    Parameters
    ----------
    source : ModelSource
    mj_model : mujoco.MjModel
        The MuJoCo model of the same file (canonical layout and reference configuration).

    Returns
    -------
    DrakeEngine

    Raises
    ------
    DrakeLoadError
        Drake refuses the file, or its joints cannot be paired with MuJoCo's (one line naming the file).
    """
    from koenig_check.engines.drake.loader import load_drake
    from koenig_check.engines.drake.state_map import build_drake_state_map

    plant, findings = load_drake(source, free_top_joints(mj_model))
    state_map = build_drake_state_map(mj_model, plant, str(source.path))
    if any(p.q_offset for p in state_map.pairs):
        offs = [p.name for p in state_map.pairs if p.q_offset]
        findings.append(
            Finding(
                Kind.LOAD,
                "drake",
                "joints " + ", ".join(offs),
                "Drake puts the file's pose at q = 0 (MuJoCo at q = ref): the state map offsets these coordinates",
            )
        )
    engine = DrakeEngine(plant, state_map, source.path, np.asarray(mj_model.qpos0), findings)
    engine.findings += anchor_findings(plant, mj_model, state_map)
    if source.format == "urdf":
        from koenig_check.engines.drake.inertia import replaced_inertias

        # a parser warning names its link only when Drake's message is about an inertia (loader.warning_findings)
        elements = [f.element.partition(" ") for f in findings if f.kind is Kind.LOAD]
        warned = [name for tag, _, name in elements if tag == "link"]
        engine.findings += replaced_inertias(plant, Path(source.path), warned, engine.segment_of_body())
    return engine


def free_top_joints(mj_model: mujoco.MjModel) -> dict[str, str]:
    """Body -> canonical joint name of every free joint on a top-level MuJoCo body.

    Parameters
    ----------
    mj_model : mujoco.MjModel

    Returns
    -------
    dict of str to str
    """
    names = mujoco_joint_names(mj_model)
    out = {}
    for j in range(mj_model.njnt):
        body = int(mj_model.jnt_bodyid[j])
        if mj_model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE and mj_model.body_parentid[body] == 0:
            out[mj_model.body(body).name] = names[j]
    return out


def anchor_findings(plant: Any, mj_model: mujoco.MjModel, state_map: DrakeStateMap) -> list[Finding]:
    """Joints whose anchor Drake places elsewhere than MuJoCo, at ``qpos0`` (world frame).

    Verified on Drake 1.51: for an MJCF body with several joints, Drake chains them through massless
    bodies and puts the *first* joint's frame on the parent at the joint's ``pos`` *without the body's
    own ``pos``*, so that joint turns about another point (the file's pose at ``q = ref`` is right;
    the motion is not).  Each such joint is a root cause (engine ``drake``) naming both anchors.

    Slide joints are not compared: a translation has no point it turns about, and translations commute, so
    a body's ``pos`` moved past a slide (Drake puts it on the body's last joint: dm_control's cheetah, whose
    torso has ``rootx``, ``rootz`` slides then the ``rooty`` hinge) moves no part of the robot; were the body
    itself moved, the next hinge's anchor here and the segment COMs of the verdicts would show it.

    Parameters
    ----------
    plant : pydrake.multibody.plant.MultibodyPlant
    mj_model : mujoco.MjModel
    state_map : DrakeStateMap

    Returns
    -------
    list of Finding
    """
    data = mujoco.MjData(mj_model)
    mujoco.mj_kinematics(mj_model, data)
    context = plant.CreateDefaultContext()
    plant.SetPositions(context, state_map.positions(np.asarray(mj_model.qpos0, dtype=float)[None])[0])
    names = mujoco_joint_names(mj_model)
    index = {n: k for k, n in enumerate(names)}
    out = []
    for p in state_map.pairs:
        if p.kind in ("free", "slide"):  # a slide has no point it turns about: see below
            continue
        k = index[p.name]
        joint = plant.GetJointByName(p.drake_name)
        where = np.asarray(joint.frame_on_parent().CalcPoseInWorld(context).translation(), dtype=float)
        anchor = np.asarray(data.xanchor[k], dtype=float)
        if np.abs(where - anchor).max() <= 1e-9 * max(1.0, float(np.abs(anchor).max())):
            continue
        body = int(mj_model.jnt_bodyid[k])
        several = int(mj_model.body_jntnum[body]) > 1
        last = names[int(mj_model.body_jntadr[body] + mj_model.body_jntnum[body] - 1)]
        out.append(
            Finding(
                Kind.ANCHOR,
                "drake",
                f"joint {p.name}",
                "Drake turns the joint about another point than MuJoCo"
                + (
                    " (first joint of a body with several joints: Drake's MJCF parser drops the body's pos for it)"
                    if several
                    else ""
                ),
                {"mujoco": np.round(anchor, 12).tolist(), "drake": np.round(where, 12).tolist()},
                affects_energy=True,
                root_cause=True,
                segments=(last,),
                cause="drake.mjcf.multi-joint-anchor" if several else "",
            )
        )
    return out
