"""What Newton reads differently from the file (and the loading options of its users that change the robot).

Each :class:`~koenig_check.engines.cause.Cause` is measured on its fixture by the suite (``tests/causes/``) with
:func:`measure`, Newton's own reading of a file.  A cause that a loading option makes (``collapse_fixed_joints=True``,
``floating=False``) is measured with that option: :data:`FIXTURE_OPTIONS` says which, by fixture.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from koenig_check.engines.cause import Cause, Reading
from koenig_check.engines.measurement import Measurement

#: The Newton release these readings were measured on; and the other engines'.
MEASURED = "1.8.0"
_MUJOCO, _PINOCCHIO, _DRAKE = "4.0.0", "4.1.0", "1.51.1"

COLLAPSE = "newton.any.collapse-fixed-joints"
NO_INERTIAL = "newton.urdf.no-inertial-collision-mass"
VALIDATION = "newton.any.inertia-validation"
MIMIC_FIXED = "newton.urdf.mimic-fixed-joint"
SOLVER_PGS = "newton.mjcf.solver-pgs"
BOX_FROMTO = "newton.mjcf.box-fromto"
FLOATING_FALSE = "newton.mjcf.floating-false"
MULTI_JOINT_POS = "newton.mjcf.multi-joint-pos"


def _as_written(*engines: tuple[str, str]) -> tuple[Reading, ...]:
    return tuple(Reading(e, "as written", measured=v) for e, v in engines)


def _newton(reads: str, how: str) -> Reading:
    return Reading("newton", reads, how, measured=MEASURED)


_OTHERS = _as_written(("mujoco", _MUJOCO), ("pinocchio", _PINOCCHIO), ("drake", _DRAKE))

CAUSES: tuple[Cause, ...] = (
    Cause(
        id=COLLAPSE,
        construct="links joined by fixed joints, loaded with collapse_fixed_joints=True",
        formats=("mjcf", "urdf"),
        readings=(
            *_OTHERS,
            _newton(
                "differently",
                "merges each welded body with its central inertia shifted to the fixed joint's origin instead of "
                "the merged COM, and the parent's never shifted (mass and COM right, inertia wrong)",
            ),
        ),
        quantities=("inertia",),
        brief="Newton's collapse_fixed_joints=True merges inertias wrongly",
        hint="load without collapse_fixed_joints (Newton's default); docs/upstream/newton-collapse-fixed-joints.md",
        fixture="newton_collapse_fixed_joints.urdf",
    ),
    Cause(
        id=NO_INERTIAL,
        construct="a URDF <link> without <inertial> that has collision shapes",
        formats=("urdf",),
        readings=(
            Reading("mujoco", "differently", "mass from the geoms (MuJoCo's URDF compiler)", measured=_MUJOCO),
            *_as_written(("pinocchio", _PINOCCHIO), ("drake", _DRAKE)),
            _newton("differently", "mass and inertia from the collision shapes, density 1000"),
        ),
        quantities=("mass", "inertia"),
        brief="a link without <inertial> given mass from its collision shapes by Newton",
        hint="write the link's <inertial> (or load with ignore_inertial_definitions=False and no collision mass)",
        fixture="newton_no_inertial.urdf",
    ),
    Cause(
        id=VALIDATION,
        construct="a body with zero inertia (a point mass) or an inertia that breaks the triangle inequality",
        formats=("mjcf", "urdf"),
        readings=(
            *_OTHERS,
            _newton(
                "differently",
                "finalize() replaces a zero inertia by 1.0001e-6 kg·m² per axis whatever the body's size, and "
                "balances triangle-inequality violations (MuJoCo refuses those)",
            ),
        ),
        quantities=("inertia",),
        brief="inertias replaced by Newton's finalize() validation",
        hint="give the body its real inertia; finalize(skip_validation_inertia=True) keeps the file's",
        fixture="newton_inertia_validation.urdf",
    ),
    Cause(
        id=MIMIC_FIXED,
        construct="a <mimic> inside a fixed <joint>",
        formats=("urdf",),
        readings=(
            *_as_written(("mujoco", _MUJOCO), ("pinocchio", _PINOCCHIO)),
            Reading("drake", "refuses", "a 0-dof joint cannot mimic a joint", measured=_DRAKE),
            _newton("refuses", "Mimic followers and references only support PRISMATIC, REVOLUTE, D6 joints"),
        ),
        quantities=("joints",),
        brief="Newton refuses a <mimic> inside a fixed joint",
        hint="remove the <mimic> from the fixed joint (a fixed joint has nothing to mimic)",
        fixture="newton_mimic_fixed.urdf",
    ),
    Cause(
        id=SOLVER_PGS,
        construct='<option solver="PGS">',
        formats=("mjcf",),
        readings=(*_OTHERS, _newton("refuses", "invalid literal for int(): 'pgs'")),
        quantities=("joints",),
        brief='Newton refuses <option solver="PGS">',
        hint='remove solver="PGS" from <option> for Newton (it does not change the dynamics checked here)',
        fixture="newton_solver_pgs.xml",
    ),
    Cause(
        id=BOX_FROMTO,
        construct="a box <geom> given by fromto",
        formats=("mjcf",),
        readings=(
            *_as_written(("mujoco", _MUJOCO), ("pinocchio", _PINOCCHIO)),
            Reading("drake", "differently", "ignores the geom (with a warning)", measured=_DRAKE),
            _newton("refuses", "IndexError: invalid index"),
        ),
        quantities=("mass", "inertia"),
        brief="Newton refuses a box geom given by fromto",
        hint="give the box pos, quat and three half-sizes instead of fromto",
        fixture="newton_box_fromto.xml",
    ),
    Cause(
        id=FLOATING_FALSE,
        construct="a root body with its own joints, loaded with add_mjcf(floating=False)",
        formats=("mjcf",),
        readings=(
            *_OTHERS,
            _newton(
                "differently",
                "floating=False replaces the root body's own joints by a fixed joint (floating=None keeps them)",
            ),
        ),
        quantities=("joints",),
        brief="Newton's floating=False fixes the root body's own joints",
        hint="load with floating=None (Newton's default) for a fixed base, floating=True for a free one",
        fixture="newton_floating_false.xml",
        loses_joints=True,
    ),
    Cause(
        id=MULTI_JOINT_POS,
        construct="a body with several joints at different pos",
        formats=("mjcf",),
        readings=(
            *_as_written(("mujoco", _MUJOCO), ("pinocchio", _PINOCCHIO)),
            Reading("drake", "differently", "drops the body's pos for the first joint", measured=_DRAKE),
            _newton(
                "differently",
                "merges them into one D6 joint anchored at the first joint's pos: the others turn about it",
            ),
        ),
        quantities=("kinematics",),
        brief="Newton turns every joint of a multi-joint body about the first joint's pos",
        hint="give the joints of one body the same pos, or split the body with a massless child body per joint",
        fixture="newton_multi_joint_pos.xml",
    ),
)


def _mimic_in_fixed_joint(root: ET.Element) -> bool:
    return any(j.get("type") == "fixed" and j.find("mimic") is not None for j in root.iter("joint"))


def _solver_pgs(root: ET.Element) -> bool:
    return any((o.get("solver") or "").lower() == "pgs" for o in root.iter("option"))


def _box_fromto(root: ET.Element) -> bool:
    return any(g.get("type") == "box" and g.get("fromto") is not None for g in root.iter("geom"))


#: How the constructs that make an engine refuse a file show in the file as written (its parsed root): the sign
#: names the cause of a refusal, whichever engine the catalogue says refuses it (:mod:`koenig_check.engines.refusals`).
#: In the order Newton meets them: ``<option>`` before the geoms (a file with both stops at ``solver="PGS"``).
FILE_SIGNS: dict[str, Callable[[ET.Element], bool]] = {
    MIMIC_FIXED: _mimic_in_fixed_joint,
    SOLVER_PGS: _solver_pgs,
    BOX_FROMTO: _box_fromto,
}


#: The loading option under which a cause's fixture shows it (Newton's users pass them), by fixture.
FIXTURE_OPTIONS: dict[str, dict[str, Any]] = {
    "newton_collapse_fixed_joints.urdf": {"collapse_fixed_joints": True},
    "newton_floating_false.xml": {"floating": False},
}


def measure(path: Path) -> Measurement:
    """Newton's reading of a model file: its parser and ``finalize()``, ``eval_mass_matrix`` at ``joint_q = 0``.

    The file is loaded as Newton's users load it (``floating=None``), with the option :data:`FIXTURE_OPTIONS`
    gives for a cause's fixture.

    Parameters
    ----------
    path : pathlib.Path
        An MJCF (``.xml``) or URDF (``.urdf``) file.

    Returns
    -------
    Measurement

    Raises
    ------
    NewtonLoadError
        Newton refuses the file (its own text).
    """
    from koenig_check.engines.newton.departures import mass_matrices
    from koenig_check.engines.newton.loader import build
    from koenig_check.engines.newton.state_map import FIXED, short_name

    path = Path(path)
    fmt = "urdf" if path.suffix.lower() == ".urdf" else "mjcf"
    model, _ = build(path, fmt, False, options=FIXTURE_OPTIONS.get(path.name))
    qds = model.joint_qd_start.numpy()
    jtype, parent, child = model.joint_type.numpy(), model.joint_parent.numpy(), model.joint_child.numpy()
    labels = [short_name(x) for x in model.joint_label]
    moving = [j for j in range(len(labels)) if qds[j + 1] > qds[j]]
    welded_to_world = set()
    for j in range(len(labels)):  # parents come before children
        if int(jtype[j]) == FIXED and (parent[j] < 0 or int(parent[j]) in welded_to_world):
            welded_to_world.add(int(child[j]))
    mass = model.body_mass.numpy()
    named = _dof_names(path, model) if fmt == "mjcf" else {}
    one_dof = {labels[j]: int(qds[j]) for j in moving if qds[j + 1] - qds[j] == 1}
    for j, dofs in named.items():  # a D6 joint's dofs, by the MJCF joints they are
        one_dof.update({name: int(qds[j]) + k for k, name in enumerate(dofs)})
        labels[j] = ""
    zero = np.zeros((1, int(model.joint_coord_count)))
    zero[0, :] = model.joint_q.numpy()  # a free joint's identity quaternion; every other coordinate is 0
    full = mass_matrices(model, zero)[0]
    arm = model.joint_armature.numpy()
    return Measurement(
        joints=tuple(sorted([labels[j] for j in moving if labels[j]] + [n for d in named.values() for n in d])),
        mass=float(sum(mass[b] for b in range(len(mass)) if b not in welded_to_world)),
        mass_matrix={(a, b): float(full[i, k]) for a, i in one_dof.items() for b, k in one_dof.items()},
        gravity=tuple(float(g) for g in np.asarray(model.gravity.numpy()).reshape(-1, 3)[0]),
        armature={j: float(arm[i]) for j, i in one_dof.items() if arm[i]},
    )


def _dof_names(path: Path, model: Any) -> dict[int, list[str]]:
    """Newton joint index -> the names of the MJCF joints its dofs are, for a D6 joint merging a body's joints."""
    from koenig_check.engines.newton.state_map import D6, short_name
    from koenig_check.modelfile.validate import parse_xml

    joints_of = {  # Newton's D6 lists the slides first, then the hinges (each in the file's order)
        b.get("name"): [j.get("name") for j in b.findall("joint") if j.get("type") == "slide"]
        + [j.get("name") for j in b.findall("joint") if j.get("type") != "slide"]
        for b in parse_xml(path).getroot().iter("body")
    }
    qds, jtype, child = model.joint_qd_start.numpy(), model.joint_type.numpy(), model.joint_child.numpy()
    out = {}
    for j in range(len(jtype)):
        names = joints_of.get(short_name(model.body_label[child[j]]), [])
        if int(jtype[j]) == D6 and len(names) == qds[j + 1] - qds[j] and all(names):
            out[j] = [str(n) for n in names]
    return out
