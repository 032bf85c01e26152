"""Constructs of a model file that Pinocchio's parsers read differently from MuJoCo, read from the file alone.

An ``<include>`` its MJCF parser ignores, the root bodies after the first it does not read, and a URDF planar
joint about another axis than z, which it reads about z.  Each is one
:class:`~koenig_check.findings.Finding` with ``root_cause=True`` carrying its catalogued cause
(:mod:`koenig_check.engines.pinocchio.causes`): the engine it names is the cause's, the other side of its values
the reference engine's (:func:`koenig_check.engines.specs.reference`).  What Pinocchio 4.1 does was verified on
small files (``tests/models/causes/``, the catalogue's fixtures).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence

from koenig_check.engines.catalogue import cause
from koenig_check.engines.specs import reference
from koenig_check.findings import Finding, Kind
from koenig_check.modelfile.mjcf import Included, body_label, joint_names

#: The catalogued cause of an ``<include>`` not read.
INCLUDE = "pinocchio.mjcf.include"
#: The catalogued cause of a ``<frame>`` not read (built by :func:`koenig_check.engines.parser_traps.frame_causes`).
FRAME = "pinocchio.mjcf.frame"
#: The catalogued cause of the root bodies after the first.
ROOT_BODIES = "pinocchio.mjcf.root-bodies"
#: The catalogued cause of a URDF planar joint about another axis than z.
PLANAR_AXIS = "pinocchio.urdf.planar-axis"


def include_causes(found: Sequence[Included], seg_of: dict[str, str], world_bodies: bool) -> list[Finding]:
    """The ``<include>`` elements Pinocchio's MJCF parser ignores, each with what it holds.

    Parameters
    ----------
    found : sequence of Included
        The file's includes (:func:`koenig_check.modelfile.mjcf.includes`).
    seg_of : dict of str to str
        Body name to the segment (joint) that moves it, from MuJoCo's compiled model.
    world_bodies : bool
        Whether the file's own ``<worldbody>`` holds a ``<body>`` (without one, Pinocchio fails to load it).

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause per include that brings bodies or default classes.
    """
    ignores, reads = cause(INCLUDE).engine, reference()
    out = []
    for inc in found:
        if not inc.bodies and not inc.defaults:
            continue  # assets, visual settings: nothing kinematic
        moved = tuple(dict.fromkeys(seg_of[b] for b in inc.bodies if seg_of.get(b)))
        if inc.bodies and not world_bodies:
            summary = (
                "<include> ignored by Pinocchio's MJCF parser; the file's <worldbody> has no <body> of its own "
                "(Pinocchio fails with 'No such node (body)')"
            )
        elif inc.bodies:
            summary = "<include> ignored by Pinocchio's MJCF parser: the included bodies and joints are missing"
        else:
            summary = "<include> ignored by Pinocchio's MJCF parser: the default classes it defines are unknown"
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                ignores,
                f"include {inc.file}",
                summary,
                values={
                    "in": inc.where,
                    "bodies": inc.bodies,
                    "joints": inc.joints,
                    reads: f"{len(inc.bodies)} bodies, {len(inc.joints)} joints",
                    ignores: "not read",
                },
                affects_energy=bool(inc.joints or moved),
                root_cause=True,
                segments=moved or inc.joints,
                hint="load a file without <include> (e.g. the robot's own file)" if inc.bodies else "",
                cause=INCLUDE,
                tag="include",
            )
        )
    return out


def root_body_causes(world_bodies: list[ET.Element]) -> list[Finding]:
    """The root bodies after the first, which Pinocchio's MJCF parser does not read.

    Parameters
    ----------
    world_bodies : list of xml.etree.ElementTree.Element
        The ``<body>`` elements directly in ``<worldbody>``, in file order.

    Returns
    -------
    list of Finding
        One ``IGNORED_CONSTRUCT`` root cause per body after the first, with its joints.
    """
    skips, reads = cause(ROOT_BODIES).engine, reference()
    out = []
    for body in world_bodies[1:]:
        joints = tuple(joint_names(body))
        out.append(
            Finding(
                Kind.IGNORED_CONSTRUCT,
                skips,
                f"body {body_label(body, world_bodies)}",
                f"Pinocchio's MJCF parser reads only the first root body ({body_label(world_bodies[0], world_bodies)})",
                values={"joints": joints, reads: "loaded", skips: "not read"},
                affects_energy=bool(joints),
                root_cause=True,
                segments=joints,
                cause=ROOT_BODIES,
                tag="body",
            )
        )
    return out


def planar_cause(joint: str, axis: tuple[float, ...] = (1.0, 0.0, 0.0)) -> Finding:
    """A URDF ``planar`` joint about another axis than z: the engines read it in different planes or coordinates.

    MuJoCo's import makes it three joints (slides ``_TX``, ``_TY``, hinge ``_RZ``) with the URDF axis as the
    plane's normal; Pinocchio 4.1 makes it one ``JointModelPlanar`` about the joint frame's z, whatever the
    axis.  A planar joint about z is paired (:mod:`koenig_check.engines.pinocchio.planar`); this one is not.

    Parameters
    ----------
    joint : str
    axis : tuple of float
        The URDF ``<axis>`` (``1 0 0`` when the file writes none).

    Returns
    -------
    Finding
        An ``AXIS`` root cause naming MuJoCo's three joints.
    """
    parts = tuple(f"{joint}_{axis}" for axis in ("TX", "TY", "RZ"))
    written = " ".join(f"{a:g}" for a in axis)
    return Finding(
        Kind.AXIS,
        "both",
        f"joint {joint}",
        f"URDF planar joint about axis {written}, which Pinocchio reads about z: MuJoCo's import makes it three "
        f"joints ({', '.join(parts)}) in the plane normal to the axis, Pinocchio one planar joint about z (it "
        "ignores the axis); koenig-check pairs a planar joint only about z, where both read the same coordinates",
        values={reference(): parts, cause(PLANAR_AXIS).engine: (joint,), "axis": axis},
        affects_energy=True,
        root_cause=True,
        segments=parts,
        hint='write <axis xyz="0 0 1"/> and turn the joint\'s <origin> so that its z is the normal',
        cause=PLANAR_AXIS,
        tag="joint",
    )


def about_z(axis: tuple[float, ...]) -> bool:
    """Whether a URDF planar joint's axis is z (scaled), the one planar joint both engines read alike.

    Parameters
    ----------
    axis : tuple of float

    Returns
    -------
    bool
    """
    return len(axis) == 3 and axis[0] == axis[1] == 0.0 and axis[2] > 0.0
