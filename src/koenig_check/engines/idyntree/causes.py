"""What iDynTree reads differently (an MJCF; a massless link's inertia), and iDynTree's reading of a fixture.

Each :class:`~koenig_check.causes.Cause` is measured on its fixture by the suite (``tests/causes/``) with
:func:`measure`, iDynTree's own reading of a file: ``ModelLoader`` and ``getFreeFloatingMassMatrix`` at ``s = 0``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: The iDynTree release these readings were measured on.
MEASURED = "15.1.0"

CAUSES: tuple[Cause, ...] = (
    Cause(
        id="idyntree.mjcf.no-mjcf-reader",
        construct="an MJCF file",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading(
                "idyntree",
                "refuses",
                "no MJCF reader: ModelLoader.loadModelFromFile returns True with a model of 0 links",
                measured=MEASURED,
            ),
        ),
        quantities=("mass", "inertia", "armature", "joints"),
        brief="iDynTree has no MJCF reader",
        hint="check the URDF of the robot with iDynTree, or leave iDynTree out (--engines)",
        fixture="urdf_only_mjcf.xml",
    ),
    Cause(
        id="idyntree.urdf.massless-link-inertia",
        construct="a massless <link> with a rotational inertia fixed to another link",
        formats=("urdf",),
        readings=(
            Reading(
                "mujoco",
                "differently",
                "fusestatic merges the link into its parent without its rotational inertia",
                measured="4.0.0",
            ),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading("pybullet", "as written", measured="3.2.7"),
            Reading(
                "idyntree",
                "differently",
                "makes the link a frame of the link it is fixed to: its rotational inertia is dropped",
                measured=MEASURED,
            ),
        ),
        quantities=("inertia",),
        brief="massless link's inertia dropped by iDynTree (the link made a frame)",
        hint="give the link its mass, or fold its inertia into the link it is fixed to",
        fixture="idyntree_massless_link_inertia.urdf",
    ),
    Cause(
        id="idyntree.urdf.xml-version",
        construct='an XML declaration of a version other than 1.x (<?xml version="0.0" ?>)',
        formats=("urdf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading("pybullet", "as written", measured="3.2.7"),
            Reading("drake", "as written", measured="1.51.1"),
            Reading("newton", "as written", measured="1.8.0"),
            Reading(
                "idyntree",
                "refuses",
                "its XML parser says \"Unsupported version '0.0'\" and ModelLoader then crashes the process "
                "(segmentation fault): koenig-check does not hand it the file",
                measured=MEASURED,
            ),
        ),
        quantities=("mass", "inertia", "joints"),
        brief="XML version other than 1.x crashes iDynTree",
        hint='write <?xml version="1.0" ?> (pybullet_data\'s minitaur, quadruped and bike URDFs have "0.0")',
        fixture="idyntree_xml_version.urdf",
    ),
)


def measure(path: Path) -> Measurement:
    """A model file as iDynTree reads it: ``ModelLoader``, its free-floating M's joint block at ``s = 0``.

    Parameters
    ----------
    path : pathlib.Path

    Returns
    -------
    Measurement
        The mass of every link a joint moves (the base fixed); iDynTree takes gravity as an argument (none here).

    Raises
    ------
    IDynTreeLoadError
        iDynTree refuses the file, or reads no link from it (an MJCF).
    """
    import idyntree.swig as idt

    from koenig_check.engines.idyntree.loader import kin_dyn, load_idyntree

    model = load_idyntree(Path(path))
    kd = kin_dyn(model)
    n = model.getNrOfDOFs()
    kd.setRobotState(np.eye(4), np.zeros(n), np.zeros(6), np.zeros(n), np.zeros(3))
    full = idt.MatrixDynSize(n + 6, n + 6)
    kd.getFreeFloatingMassMatrix(full)
    M = full.toNumPy()
    base = model.getLinkIndex(kd.getFloatingBase())
    traversal = idt.Traversal()
    model.computeFullTreeTraversal(traversal, base)
    moves = np.zeros(model.getNrOfLinks(), dtype=bool)
    for k in range(1, traversal.getNrOfVisitedLinks()):  # parents are visited before children
        link = traversal.getLink(k).getIndex()
        parent = traversal.getParentLinkFromLinkIndex(link).getIndex()
        moves[link] = moves[parent] or traversal.getParentJointFromLinkIndex(link).getNrOfDOFs() > 0
    dofs = {}
    for j in range(model.getNrOfJoints()):
        joint = model.getJoint(j)
        if joint.getNrOfDOFs() == 1:
            dofs[model.getJointName(j)] = 6 + int(joint.getDOFsOffset())
    mass = sum(model.getLink(k).getInertia().getMass() for k in range(model.getNrOfLinks()) if moves[k])
    return Measurement(
        joints=tuple(sorted(dofs)),
        mass=float(mass),
        mass_matrix={(a, b): float(M[i, k]) for a, i in dofs.items() for b, k in dofs.items()},
        gravity=(0.0, 0.0, 0.0),
    )
