"""MJCF model composition (``<attach>`` of a ``<model>`` asset): MuJoCo builds it, Pinocchio's MJCF parser ignores it.

MuJoCo (3.2 and later) reads ``<asset><model name="child" file="child.xml"/></asset>`` and ``<attach model="child"
body="arm" prefix="other_"/>`` inside a body (or ``<worldbody>``, or a ``<frame>``) as the child model's body
``arm`` and its subtree, every name prefixed, placed there.  Pinocchio 4.1's ``buildModelFromMJCF`` does not read
``<attach>`` (verified on ``causes/fixtures/attach.xml``: the slide alone, nv 1): the attached bodies' joints and
masses are missing.  Catalogued as ``pinocchio.mjcf.attach``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from koenig_check.findings import Finding, Kind, shown_names

#: The catalogue's id of this cause (declared in ``engines/pinocchio/causes.py``).
CAUSE_ID = "pinocchio.mjcf.attach"


def attach_causes(root: ET.Element, folder: Path, mj_model: Any = None) -> list[Finding]:
    """One root cause per ``<attach>`` element of an MJCF document.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    folder : pathlib.Path
        The document's folder (a ``<model file=...>`` is relative to it).
    mj_model : mujoco.MjModel, optional
        MuJoCo's compiled model: the attached bodies MuJoCo built, their joints (as the engines' joint pairing names
        them) and the segments they move.  Without it, the names are read from the attached model's file.

    Returns
    -------
    list of Finding
        ``IGNORED_CONSTRUCT`` findings (engine ``pinocchio``, ``cause="pinocchio.mjcf.attach"``) naming the model,
        where it is attached, and the bodies and joints Pinocchio lacks.
    """
    files = {m.get("name", ""): m.get("file", "") for a in root.iter("asset") for m in a.findall("model")}
    parents = {child: parent for parent in root.iter() for child in parent}
    out = []
    for attach in root.iter("attach"):
        model = attach.get("model", "")
        prefix = attach.get("prefix", "")
        written = [prefix + name for name in _subtree_bodies(folder / files.get(model, ""), attach.get("body"))]
        bodies, joints, segments = _as_built(written, mj_model) if mj_model is not None else (written, [], [])
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                "pinocchio",
                f"attach {model or '(no model)'}" + (f" (bodies {shown_names(bodies, 3)})" if bodies else ""),
                "<attach> not read by Pinocchio's MJCF parser: "
                + (f"bodies {shown_names(bodies, 3)} and their joints missing" if bodies else "nothing attached"),
                values={
                    "in": _where(attach, parents),
                    "file": files.get(model, ""),
                    "bodies": tuple(bodies),
                    "joints": tuple(joints),
                    "attached": f"{len(bodies)} bodies, {len(joints)} joints",
                    "pinocchio": "not read",
                },
                affects_energy=bool(joints or segments),
                root_cause=True,
                segments=tuple(segments or joints),
                hint="load a file with the attached bodies written out (MuJoCo's MjSpec.to_xml of the composed model)",
                cause=CAUSE_ID,
            )
        )
    return out


def _where(element: ET.Element, parents: dict[ET.Element, ET.Element]) -> str:
    """Where an element sits: ``body base``, ``frame f in body base``, ``worldbody``."""
    parent = parents.get(element)
    words = []
    while parent is not None and parent.tag in ("frame", "body"):
        words.append(f"{parent.tag} {parent.get('name')}" if parent.get("name") else f"unnamed {parent.tag}")
        if parent.tag == "body":
            break
        parent = parents.get(parent)
    return " in ".join(words) or "worldbody"


def _subtree_bodies(path: Path, body: str | None) -> list[str]:
    """The names of a model file's body ``body`` and the bodies below it (every top-level body's without one)."""
    try:
        doc = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return []
    tops = [b for w in doc.iter("worldbody") for b in w.findall("body")]
    chosen = [next((b for b in doc.iter("body") if b.get("name") == body), None)] if body else tops
    return [str(b.get("name")) for top in chosen if top is not None for b in top.iter("body") if b.get("name")]


def _as_built(written: list[str], mj_model: Any) -> tuple[list[str], list[str], list[str]]:
    """The attached bodies MuJoCo built, their joints (canonical names) and the segments they move."""
    import mujoco

    from koenig_check.engines.canonical import mujoco_joint_names, segment_by_body_id

    names = mujoco_joint_names(mj_model)
    seg = segment_by_body_id(mj_model)
    bodies, joints, segments = [], [], []
    for name in written:
        b = mujoco.mj_name2id(mj_model, mujoco.mjtObj.mjOBJ_BODY, name)
        if b < 0:
            continue
        bodies.append(name)
        start, count = int(mj_model.body_jntadr[b]), int(mj_model.body_jntnum[b])
        joints += names[start : start + count] if start >= 0 else []
        if seg[b] and seg[b] not in segments:
            segments.append(seg[b])
    return bodies, joints, segments
