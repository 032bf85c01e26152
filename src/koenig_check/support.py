"""Model features the state map does not support, refused by name rather than mis-mapped.

The cross-check treats every joint as an independent coordinate.  A model whose joints
are coupled (URDF ``<mimic>``, MJCF joint or tendon equalities) or whose bodies close a
kinematic loop (MJCF ``connect``/``weld`` equalities) has fewer true degrees of freedom
than joints, and the two engines treat the coupling differently (MuJoCo turns a mimic
joint into an equality constraint; Pinocchio keeps it as a free joint unless asked).
Such models are refused with the elements concerned named.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco


class UnsupportedModelError(ValueError):
    """The model uses a feature the state map does not support; the message names the elements."""


def _name(model: mujoco.MjModel, obj: mujoco.mjtObj, i: int) -> str:
    return mujoco.mj_id2name(model, obj, int(i)) or f"#{int(i)}"


def unsupported_features(mj_model: mujoco.MjModel, path: str | Path) -> list[str]:
    """List the couplings and closed loops of a model, one phrase each.

    Parameters
    ----------
    mj_model : mujoco.MjModel
        The model compiled by MuJoCo.
    path : str or Path
        The model file (URDF ``<mimic>`` elements are read from it directly).

    Returns
    -------
    list of str
        Empty when the model is supported.
    """
    found = []
    mimics = _urdf_mimics(Path(path))
    found += [f"URDF joint {j!r} mimics joint {leader!r}" for j, leader in mimics.items()]
    J, B, T = mujoco.mjtObj.mjOBJ_JOINT, mujoco.mjtObj.mjOBJ_BODY, mujoco.mjtObj.mjOBJ_TENDON
    for k in range(mj_model.neq):
        kind = int(mj_model.eq_type[k])
        a, b = mj_model.eq_obj1id[k], mj_model.eq_obj2id[k]
        label = mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_EQUALITY, k)
        label = f"equality {label!r}" if label else f"equality #{k}"
        if kind == int(mujoco.mjtEq.mjEQ_JOINT):
            if _name(mj_model, J, a) in mimics:
                continue  # MuJoCo's form of a URDF mimic joint, already named
            other = f" to joint {_name(mj_model, J, b)!r}" if b >= 0 else " to a constant"
            found.append(f"{label} couples joint {_name(mj_model, J, a)!r}{other}")
        elif kind == int(mujoco.mjtEq.mjEQ_TENDON):
            other = f" and {_name(mj_model, T, b)!r}" if b >= 0 else ""
            found.append(f"{label} constrains tendon {_name(mj_model, T, a)!r}{other}, coupling its joints")
        elif kind in (int(mujoco.mjtEq.mjEQ_CONNECT), int(mujoco.mjtEq.mjEQ_WELD)):
            if int(mj_model.eq_objtype[k]) == int(B):
                other = _name(mj_model, B, b) if b >= 0 else "world"
                found.append(f"{label} closes a kinematic loop between body {_name(mj_model, B, a)!r} and {other!r}")
            else:
                found.append(f"{label} closes a kinematic loop between sites")
        else:
            found.append(f"{label} of type {mujoco.mjtEq(kind).name} constrains the model")
    return found


def _urdf_mimics(path: Path) -> dict[str, str]:
    """Mimic joints of a URDF file: follower name to leader name."""
    if path.suffix.lower() != ".urdf":
        return {}
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError):
        return {}
    return {
        j.get("name", "?"): j.find("mimic").get("joint", "?") for j in root.iter("joint") if j.find("mimic") is not None
    }


def refuse_unsupported(mj_model: mujoco.MjModel, path: str | Path) -> None:
    """Raise :class:`UnsupportedModelError` if the model has couplings or closed loops.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    path : str or Path

    Raises
    ------
    UnsupportedModelError
        Naming every coupled joint, tendon or loop-closing body.
    """
    found = unsupported_features(mj_model, path)
    if found:
        raise UnsupportedModelError(
            f"{path}: not supported by the state map (joints must be independent coordinates): " + "; ".join(found)
        )
