"""Constructs beyond the kinematic tree (equalities, tendons, actuators, sensors, keyframes) listed as not carried."""

from __future__ import annotations

import mujoco

from koenig_check.export.carried import NotCarried

_EQ_NAMES = {int(v): k.removeprefix("mjEQ_").lower() for k, v in mujoco.mjtEq.__members__.items()}


def _names(model: mujoco.MjModel, obj: mujoco.mjtObj, count: int, prefix: str) -> list[str]:
    return [mujoco.mj_id2name(model, obj, i) or f"{prefix}{i}" for i in range(count)]


def extras_not_carried(model: mujoco.MjModel, target: str, keep_equalities: bool = False) -> list[NotCarried]:
    """The model's equality constraints, tendons, actuators, sensors and keyframes, one record per kind.

    Parameters
    ----------
    model : mujoco.MjModel
    target : str
        The target format's name, for the reason (``"URDF"``).
    keep_equalities : bool
        Joint equalities are written by the target (portable MJCF): only the other kinds are listed.

    Returns
    -------
    list of NotCarried
    """
    out = []
    eqs = _names(model, mujoco.mjtObj.mjOBJ_EQUALITY, model.neq, "equality")
    listed = [
        f"{_EQ_NAMES.get(int(model.eq_type[i]), 'equality')} {eqs[i]}"
        for i in range(model.neq)
        if not (keep_equalities and int(model.eq_type[i]) == int(mujoco.mjtEq.mjEQ_JOINT))
    ]
    if listed:
        out.append(
            NotCarried(
                "equality",
                ", ".join(listed),
                f"{target} has no constraints (a mimic or joint equality couples the coordinates; "
                "the mass matrix of the tree is kept)",
            )
        )
    for kind, obj, count, prefix in (
        ("tendon", mujoco.mjtObj.mjOBJ_TENDON, model.ntendon, "tendon"),
        ("actuator", mujoco.mjtObj.mjOBJ_ACTUATOR, model.nu, "actuator"),
        ("sensor", mujoco.mjtObj.mjOBJ_SENSOR, model.nsensor, "sensor"),
        ("keyframe", mujoco.mjtObj.mjOBJ_KEY, model.nkey, "key"),
    ):
        if count:
            names = _names(model, obj, count, prefix)
            shown = ", ".join(names[:6]) + (f" (+{count - 6})" if count > 6 else "")
            out.append(NotCarried(kind, f"{kind}s {shown}", f"not written to {target}"))
    return out
