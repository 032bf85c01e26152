"""``<replicate>``: MuJoCo makes ``count`` copies of what it holds, Pinocchio's MJCF parser reads none of it.

MuJoCo expands a ``<replicate count="n">`` while parsing: each element inside is copied ``n`` times, its name
suffixed with the copy's index (``sep`` between, empty by default: joint ``j`` becomes ``j0``, ``j1``, ...).
Pinocchio 4.1's ``buildModelFromMJCF`` skips the element and everything inside (verified on small files: the
copies' joints are missing; a file whose only root body is replicated fails with "No such node (body)").
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.mjcf import joint_names


def _copies(element: ET.Element, names: list[str]) -> list[str]:
    """The names MuJoCo gives the copies of ``names`` made by one ``<replicate>`` (written names when unknown)."""
    try:
        count = int(element.get("count", "1"))
    except ValueError:
        return names
    sep = element.get("sep", "")
    if element.find(".//replicate") is not None:  # nested copies: suffixes of suffixes, named as written
        return names
    return [f"{name}{sep}{k}" for name in names for k in range(count)]


def _own_geoms(element: ET.Element) -> int:
    """Geoms inside ``element`` that no body inside it holds."""
    return sum(1 if c.tag == "geom" else 0 if c.tag == "body" else _own_geoms(c) for c in element)


def replicate_causes(root: ET.Element, seg_of: dict[str, str]) -> list[Finding]:
    """Every outermost ``<replicate>`` under ``<worldbody>`` that holds a body or a geom.

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The MJCF document.
    seg_of : dict of str to str
        MuJoCo body name to the segment (joint) that moves it, from MuJoCo's compiled model.

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause (engine ``pinocchio``) per replicate, with the bodies and joints
        MuJoCo makes of it.
    """
    out: list[Finding] = []

    def walk(element: ET.Element, where: str, enclosing: str | None) -> None:
        count = 0
        for child in element:
            if child.tag == "replicate":
                count += 1
                bodies = _copies(child, [b.get("name", "?") for b in child.iter("body")])
                joints = _copies(child, joint_names(child))
                geoms = _own_geoms(child)  # geoms the replicate adds to the enclosing body
                if not bodies and not geoms:
                    continue
                carriers = (*bodies, enclosing or "") if geoms else tuple(bodies)
                moved = tuple(dict.fromkeys(seg_of[b] for b in carriers if seg_of.get(b)))
                out.append(
                    Finding(
                        Kind.IGNORED_CONSTRUCT,
                        "pinocchio",
                        f"replicate {child.get('name') or f'#{count}'} in {where}",
                        f"<replicate> not read by Pinocchio's MJCF parser: the {child.get('count', '1')} copies "
                        f"MuJoCo makes are missing ({len(bodies)} bodies, {len(joints)} joints)",
                        values={"bodies": tuple(bodies), "joints": tuple(joints), "count": child.get("count", "1")},
                        affects_energy=bool(joints or moved),
                        root_cause=True,
                        segments=moved or tuple(joints),
                        hint="koenig-check export MODEL --to mjcf writes the copies out (no <replicate>, no <frame>)",
                        cause="pinocchio.mjcf.replicate",
                    )
                )
            elif child.tag == "body":
                name = child.get("name", "?")
                walk(child, f"body {name}", name)
            elif child.tag == "frame":
                walk(child, where, enclosing)

    for world in root.findall("worldbody"):
        walk(world, "worldbody", None)
    return out
