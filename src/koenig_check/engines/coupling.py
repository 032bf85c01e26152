"""Find joints that are not independent: URDF mimic joints, MJCF equality constraints.

Both engines' kinetic energy, mass matrix and inverse dynamics treat every joint as independent
(Pinocchio is built with ``mimic=False``; MuJoCo keeps mimic and equality constraints out of
``M``), so a coupled model is refused by default and loaded only on request, with a note.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco

from koenig_check.engines.sources import ModelSource

_LOOP = (mujoco.mjtEq.mjEQ_CONNECT, mujoco.mjtEq.mjEQ_WELD)


def _name(model: mujoco.MjModel, obj: mujoco.mjtObj, i: int) -> str:
    return (mujoco.mj_id2name(model, obj, int(i)) or f"#{int(i)}") if i >= 0 else "world"


def _tendon_joints(model: mujoco.MjModel, tendon: int) -> list[str]:
    start, count = int(model.tendon_adr[tendon]), int(model.tendon_num[tendon])
    return [
        _name(model, mujoco.mjtObj.mjOBJ_JOINT, model.wrap_objid[w])
        for w in range(start, start + count)
        if model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_JOINT
    ]


def _equalities(model: mujoco.MjModel) -> list[str]:
    out = []
    for e in range(model.neq):
        kind = mujoco.mjtEq(model.eq_type[e])
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_EQUALITY, e) or f"#{e}"
        a, b = int(model.eq_obj1id[e]), int(model.eq_obj2id[e])
        if kind in _LOOP:
            obj = mujoco.mjtObj(model.eq_objtype[e])
            what = "sites" if obj == mujoco.mjtObj.mjOBJ_SITE else "bodies"
            out.append(
                f"equality {name!r} closes a kinematic loop between {what} {_name(model, obj, a)!r} and "
                f"{_name(model, obj, b) if b >= 0 else 'world'!r}"
            )
        elif kind == mujoco.mjtEq.mjEQ_JOINT:
            j = mujoco.mjtObj.mjOBJ_JOINT
            other = _name(model, j, b) if b >= 0 else "a constant"
            out.append(f"equality {name!r} couples joint {_name(model, j, a)!r} to {other!r}")
        elif kind == mujoco.mjtEq.mjEQ_TENDON:
            tendons = [t for t in (a, b) if t >= 0]
            names = ", ".join(repr(_name(model, mujoco.mjtObj.mjOBJ_TENDON, t)) for t in tendons)
            joints = [j for t in tendons for j in _tendon_joints(model, t)]
            out.append(f"equality {name!r} constrains tendon {names}, coupling its joints {joints}")
        else:
            out.append(f"equality {name!r} of type {kind.name} constrains the model")
    return out


def _mimics(source: ModelSource) -> list[str]:
    out = []
    for joint in ET.parse(source.path).getroot().findall("joint"):
        mimic = joint.find("mimic")
        if mimic is not None:
            out.append(f"joint {joint.get('name')!r} mimics joint {mimic.get('joint')!r}")
    return out


def coupled_joints(source: ModelSource, model: mujoco.MjModel) -> list[str]:
    """Describe every constraint that makes joints dependent.

    Parameters
    ----------
    source : ModelSource
        The file (URDF ``<mimic>`` tags are read from it).
    model : mujoco.MjModel
        The compiled model (MJCF ``<equality>`` constraints are read from it).

    Returns
    -------
    list of str
        One phrase per constraint, naming the joints, bodies or tendons; empty if none.
    """
    if source.format == "urdf":
        return _mimics(source)
    return _equalities(model)
