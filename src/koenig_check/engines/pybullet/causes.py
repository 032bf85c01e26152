"""The constructs and loading options PyBullet reads differently from the file, and PyBullet's reading of a fixture.

Each :class:`~koenig_check.causes.Cause` is measured on its fixture by the suite (``tests/causes/``) with
:func:`measure`, PyBullet's own reading of a file: ``loadURDF`` in a DIRECT client and ``calculateMassMatrix`` at
``q = 0``.  A cause that is a loading option (a flag left out or added) is measured with that option: the fixture
is loaded as a user who makes that choice loads it (:data:`LOADING`).  On a user's robot the same options are
measured by :mod:`koenig_check.engines.pybullet.traps` and said with their effect.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: The PyBullet release these readings were measured on.
MEASURED = "3.2.7"
#: The others' releases they were measured on (each reads these fixtures as written unless declared otherwise).
_OTHERS = (
    Reading("mujoco", "as written", measured="4.0.0"),
    Reading("pinocchio", "as written", measured="4.1.0"),
    Reading("idyntree", "as written", measured="15.1.0"),
)
#: The flag users pass to read the file's inertias (:data:`LOADING`'s default).
INERTIA_FROM_FILE = "URDF_USE_INERTIA_FROM_FILE"

CAUSES: tuple[Cause, ...] = (
    Cause(
        id="pybullet.urdf.inertia-from-collision",
        construct="loadURDF without URDF_USE_INERTIA_FROM_FILE (PyBullet's default)",
        formats=("urdf",),
        readings=(
            *_OTHERS,
            Reading(
                "pybullet",
                "differently",
                "computes each link's inertia from its collision shapes (the mass is the file's)",
                measured=MEASURED,
            ),
        ),
        quantities=("inertia",),
        brief="loadURDF without URDF_USE_INERTIA_FROM_FILE: inertia from collision shapes",
        hint="pass flags=URDF_USE_INERTIA_FROM_FILE to loadURDF",
        fixture="pybullet_inertia_from_collision.urdf",
    ),
    Cause(
        id="pybullet.urdf.merge-fixed-links",
        construct="loadURDF with URDF_MERGE_FIXED_LINKS",
        formats=("urdf",),
        readings=(
            *_OTHERS,
            Reading(
                "pybullet",
                "differently",
                "merges each fixed link into its parent without the <inertial> origins: COM and inertia wrong",
                measured=MEASURED,
            ),
        ),
        quantities=("com", "inertia"),
        brief="URDF_MERGE_FIXED_LINKS: merged COM and inertia wrong",
        hint="leave URDF_MERGE_FIXED_LINKS out when the dynamics matter",
        fixture="pybullet_merge_fixed_links.urdf",
    ),
    Cause(
        id="pybullet.urdf.link-without-inertial",
        construct="a moving <link> without <inertial>",
        formats=("urdf",),
        readings=(*_OTHERS, Reading("pybullet", "differently", "1 kg and a unit inertia", measured=MEASURED)),
        quantities=("mass", "com", "inertia"),
        brief="link without <inertial> given 1 kg by PyBullet",
        hint="give the link an <inertial> (mass 0 for a frame), or make it a frame of its parent",
        fixture="pybullet_link_without_inertial.urdf",
    ),
    Cause(
        id="pybullet.urdf.floating-root-without-inertial",
        construct="a root <link> without <inertial> (a ROS base_link) when the base floats",
        formats=("urdf",),
        readings=(*_OTHERS, Reading("pybullet", "differently", "1 kg and a unit inertia", measured=MEASURED)),
        quantities=("mass", "com", "inertia"),
        brief="floating root link without <inertial> given 1 kg by PyBullet",
        hint="give the root link an <inertial>, or make the link with mass the root",
        fixture="pybullet_floating_root_without_inertial.urdf",
    ),
    Cause(
        id="pybullet.urdf.missing-mesh",
        construct="a <mesh filename> that does not exist",
        formats=("urdf",),
        readings=(
            Reading(
                "mujoco",
                "refuses",
                "from_xml_path cannot open the mesh (koenig-check's loader drops it and says so)",
                measured="4.0.0",
            ),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading("idyntree", "as written", measured="15.1.0"),
            Reading("pybullet", "refuses", "loadURDF refuses the whole file", measured=MEASURED),
        ),
        quantities=("mass", "inertia", "joints"),
        brief="a missing mesh file: PyBullet refuses the whole URDF",
        hint="ship the mesh, or point setAdditionalSearchPath at its package",
        fixture="pybullet_missing_mesh.urdf",
    ),
    Cause(
        id="pybullet.urdf.zeroed-inertia",
        construct="an <inertia> whose principal moments break the triangle inequality (A + B < C)",
        formats=("urdf",),
        readings=(
            Reading(
                "mujoco",
                "refuses",
                "inertia must satisfy A + B >= C (--repair-inertia or --balance-inertia loads it)",
                measured="4.0.0",
            ),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading("idyntree", "as written", measured="15.1.0"),
            Reading(
                "pybullet",
                "differently",
                "'Bad inertia tensor properties, setting inertia to zero': the link keeps its mass, not its inertia",
                measured=MEASURED,
            ),
        ),
        quantities=("inertia",),
        brief="inertia breaking A + B >= C set to zero by PyBullet",
        hint="give the link principal moments with A + B >= C",
        fixture="pybullet_zeroed_inertia.urdf",
    ),
    Cause(
        id="pybullet.mjcf.load-mjcf",
        construct="an MJCF file",
        formats=("mjcf",),
        readings=(
            Reading("mujoco", "as written", measured="4.0.0"),
            Reading("pinocchio", "as written", measured="4.1.0"),
            Reading(
                "pybullet",
                "refuses",
                "loadMJCF is no reader of MuJoCo's model: it ignores fullinertia, armature, default classes and "
                "freejoint and splits bodies",
                measured=MEASURED,
            ),
        ),
        quantities=("mass", "inertia", "armature", "joints"),
        brief="PyBullet does not read MJCF as written",
        hint="check the URDF of the robot with PyBullet, or leave PyBullet out (--engines)",
        fixture="urdf_only_mjcf.xml",
    ),
)

#: How a fixture is loaded when its cause is a loading option: fixture -> (flags, floating base).
LOADING: dict[str, tuple[tuple[str, ...], bool]] = {
    "pybullet_inertia_from_collision.urdf": ((), False),
    "pybullet_merge_fixed_links.urdf": ((INERTIA_FROM_FILE, "URDF_MERGE_FIXED_LINKS"), False),
    "pybullet_floating_root_without_inertial.urdf": ((INERTIA_FROM_FILE,), True),
}


def measure(path: Path) -> Measurement:
    """PyBullet's reading of a model file: ``loadURDF`` (:data:`LOADING`), ``calculateMassMatrix`` at ``q = 0``.

    Parameters
    ----------
    path : pathlib.Path
        A URDF.

    Returns
    -------
    Measurement
        The mass of every link that moves (the base's too when it floats); PyBullet's gravity (none from a URDF).

    Raises
    ------
    PyBulletLoadError
        PyBullet refuses the file (an MJCF; a missing mesh: its own text).
    """
    from koenig_check.engines.pybullet.client import Client, PyBulletLoadError
    from koenig_check.engines.pybullet.tree import read_tree

    path = Path(path)
    if path.suffix.lower() != ".urdf":
        raise PyBulletLoadError(f"{path}: {CAUSES[-1].reading('pybullet').how}")
    flags, floating = LOADING.get(path.name, ((INERTIA_FROM_FILE,), False))
    client = Client(path.parent)
    try:
        body = client.load_urdf(path, floating, flags)
        tree = read_tree(client, body)
        M = np.asarray(client.call("calculateMassMatrix", body, [0.0] * tree.n_dofs), dtype=float)
    finally:
        client.close()
    width = 6 if floating else 0
    dofs = {tree.joint_names[k]: width + int(u) for k, u in enumerate(tree.u_index) if u >= 0}
    moves = np.zeros(len(tree.link_names), dtype=bool)
    moves[0] = floating
    for row in range(1, len(tree.link_names)):
        moves[row] = moves[tree.parent[row]] or tree.u_index[row] >= 0
    return Measurement(
        joints=tuple(sorted(dofs)),
        mass=float(tree.mass[moves].sum()),
        mass_matrix={(a, b): float(M[i, k]) for a, i in dofs.items() for b, k in dofs.items()},
        gravity=(0.0, 0.0, 0.0),
    )
