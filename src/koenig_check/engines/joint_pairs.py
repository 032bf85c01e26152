"""MuJoCo's joints paired by name with those of an engine that reads a URDF link by link (PyBullet, iDynTree).

Also the one message of a pairing that fails, shared by every engine's state map: the joints found in MuJoCo only,
those found in the engine only, and those whose types differ.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_joint_names

#: MuJoCo's joint types (``mjtJoint``) in the words the state maps use.
MJ_KIND = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}


@dataclass(frozen=True)
class LinkJointPair:
    """One MuJoCo joint and the engine's joint (or floating base) it maps to.

    Parameters
    ----------
    name : str
        Canonical (MuJoCo) joint name.
    kind : str
        ``"free"``, ``"hinge"`` or ``"slide"``.
    link : int
        The engine's link it moves (the base link for the free joint).
    qadr, vadr : int
        Canonical addresses.
    dof : int
        The engine's velocity coordinate among its joints' (-1 for the base).
    """

    name: str
    kind: str
    link: int
    qadr: int
    vadr: int
    dof: int


@dataclass(frozen=True)
class EngineJoint:
    """An engine's joint with one degree of freedom, as the pairing needs it.

    Parameters
    ----------
    kind : str
        Its type in MuJoCo's words (``"hinge"``, ``"slide"``), or another word that pairs with no MuJoCo joint.
    word : str
        Its type in the engine's own words, for the message of a type that differs.
    link : int
        The link it moves.
    dof : int
        Its velocity coordinate.
    """

    kind: str
    word: str
    link: int
    dof: int


@dataclass
class Pairing:
    """The pairs found, and what could not be paired (each list empty when every joint pairs)."""

    pairs: list[LinkJointPair] = field(default_factory=list)
    only_mujoco: list[str] = field(default_factory=list)
    only_engine: list[str] = field(default_factory=list)
    mismatch: list[str] = field(default_factory=list)

    def failure(self, path: str, label: str) -> str | None:
        """The one message of a failed pairing (:func:`mismatch_message`), or None when every joint pairs.

        Parameters
        ----------
        path : str
        label : str
            The engine's name for people.

        Returns
        -------
        str or None
        """
        return mismatch_message(path, label, self.only_mujoco, self.only_engine, self.mismatch)


def mismatch_message(
    path: str, label: str, only_mujoco: list[str], only_engine: list[str], mismatch: list[str], *extra: str
) -> str | None:
    """``"<path>: joints do not match between MuJoCo and <label> (only in MuJoCo: ...; ...)"``, or None.

    Parameters
    ----------
    path : str
    label : str
        The engine's name for people.
    only_mujoco, only_engine : list of str
        The joints found in one engine only.
    mismatch : list of str
        ``"<name>: mujoco <kind> vs <engine> <kind>"`` per joint whose types differ.
    *extra : str
        Further parts, said after those (none when there is nothing else wrong).

    Returns
    -------
    str or None
        None when every list is empty and no extra part is given.
    """
    parts = [
        f"{what}: {', '.join(names)}"
        for what, names in (
            ("only in MuJoCo", only_mujoco),
            (f"only in {label}", only_engine),
            ("incompatible types", mismatch),
        )
        if names
    ]
    parts += extra
    if not parts:
        return None
    return f"{path}: joints do not match between MuJoCo and {label} ({'; '.join(parts)})"


def pair_by_name(
    mj_model: mujoco.MjModel, joints: Mapping[str, EngineJoint], engine: str, base: Callable[[int], int | None]
) -> Pairing:
    """Pair every MuJoCo joint with the engine's joint of the same name (a free root with the floating base).

    Parameters
    ----------
    mj_model : mujoco.MjModel
    joints : mapping of str to EngineJoint
        The engine's joints that move, by name.
    engine : str
        The engine's name, in the message of a type that differs.
    base : callable
        MuJoCo joint index -> the engine's floating base link it is, or None (then paired by name).

    Returns
    -------
    Pairing
        The pairs in canonical order.
    """
    out, used = Pairing(), set()
    for j, name in enumerate(mujoco_joint_names(mj_model)):
        kind = MJ_KIND[int(mj_model.jnt_type[j])]
        qadr, vadr = int(mj_model.jnt_qposadr[j]), int(mj_model.jnt_dofadr[j])
        link = base(j) if kind == "free" else None
        if link is not None:
            out.pairs.append(LinkJointPair(name, kind, link, qadr, vadr, -1))
            continue
        joint = joints.get(name)
        if joint is None:
            out.only_mujoco.append(name)
            continue
        used.add(name)
        if joint.kind != kind:
            out.mismatch.append(f"{name}: mujoco {kind} vs {engine} {joint.word}")
            continue
        out.pairs.append(LinkJointPair(name, kind, joint.link, qadr, vadr, joint.dof))
    out.only_engine = [n for n in joints if n not in used]
    return out


#: Canonical velocity coordinates of MuJoCo's joint kinds with more than one.
_WIDTH = {"free": 6, "ball": 3}


def dofs_by_kind(pairs: Iterable[Any], word: Callable[[Any], str]) -> dict[str, np.ndarray]:
    """Canonical dof indices grouped by the engine's word for each joint's type.

    Parameters
    ----------
    pairs : iterable of joint pairs
        Each with ``kind`` (MuJoCo's word) and ``vadr`` (its canonical velocity address).
    word : callable
        A pair -> the engine's word for its joint's type (``"revolute"``, ``"floating base"``, ...).

    Returns
    -------
    dict of str to ndarray of int
    """
    groups: dict[str, list[int]] = {}
    for p in pairs:
        groups.setdefault(word(p), []).extend(range(p.vadr, p.vadr + _WIDTH.get(p.kind, 1)))
    return {k: np.array(v, dtype=int) for k, v in groups.items()}


def per_dof(pairs: Iterable[Any], nv: int, value: Callable[[Any], float]) -> np.ndarray:
    """A value of each canonical hinge or slide dof (free and ball dofs: zero), such as an engine's armature.

    Parameters
    ----------
    pairs : iterable of joint pairs
        Each with ``kind`` and ``vadr``.
    nv : int
        The canonical velocity size.
    value : callable
        A hinge or slide pair -> its value.

    Returns
    -------
    ndarray, shape (nv,)
    """
    out = np.zeros(nv)
    for p in pairs:
        if p.kind in ("hinge", "slide"):
            out[p.vadr] = value(p)
    return out
