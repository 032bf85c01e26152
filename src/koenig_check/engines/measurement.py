"""What an engine reads from a fixture, measured with the engine's own calls: the catalogue's claims re-measured.

Every engine subpackage that declares causes gives ``measure(path) -> Measurement`` in its ``causes.py``: the
moving joints it built, their total mass, its mass matrix at the reference configuration and its gravity, each
read straight from the engine (no koenig-check adapter in between).  :func:`differences` says which of a cause's
quantities two engines read differently; the suite checks that the engine a cause names departs from an engine
that reads the file as written, on that cause's quantities, and that the others do not.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Measurement:
    """An engine's reading of one model file.

    Parameters
    ----------
    joints : tuple of str
        The names of the joints that move (one degree of freedom or more), sorted.
    mass : float
        Total mass of the bodies that move.
    mass_matrix : mapping of (str, str) to float
        M at the reference configuration (MuJoCo ``qpos0``, Pinocchio's neutral, Drake's default) for pairs of
        one-degree-of-freedom joints, by name; armature included where the engine adds it to M.
    gravity : tuple of float
        The gravity vector the engine uses for this model (zero when gravity is disabled).
    gravity_forces : mapping of str to float
        ``g(q)`` at the reference configuration (the force to apply to hold it still) per one-degree-of-freedom
        joint: what gravity does to the robot the engine built (a dropped root pose, a lost joint axis).
    armature : mapping of str to float
        Rotor inertia per one-degree-of-freedom joint as the engine holds it (empty: none).
    com : tuple of float
        The centre of mass of the bodies that move, in the world, at the reference configuration (empty: not
        measured).
    spectrum : tuple of float
        The eigenvalues of the whole M at the reference configuration (every degree of freedom, multi-dof joints
        included), ascending: the same for one joint split into several that move the body alike (a URDF planar
        joint as MuJoCo's three), different when the body moves in another plane or about another point (empty:
        not measured).
    """

    joints: tuple[str, ...]
    mass: float
    mass_matrix: Mapping[tuple[str, str], float] = field(default_factory=dict)
    gravity: tuple[float, ...] = (0.0, 0.0, -9.81)
    gravity_forces: Mapping[str, float] = field(default_factory=dict)
    armature: Mapping[str, float] = field(default_factory=dict)
    com: tuple[float, ...] = ()
    spectrum: tuple[float, ...] = ()


#: The measured fields each quantity of a cause stands for.
_FIELDS_OF = {
    "joints": ("joints",),
    "mass": ("mass",),
    "com": ("com",),
    "inertia": ("mass_matrix",),
    "kinematics": ("mass_matrix", "spectrum"),
    "armature": ("armature",),
    "gravity": ("gravity",),
}


def differences(a: Measurement, b: Measurement, rtol: float) -> set[str]:
    """The fields two readings of one file differ in, beyond ``rtol`` relative.

    Parameters
    ----------
    a, b : Measurement
    rtol : float
        The larger precision of the two engines.

    Returns
    -------
    set of str
        Among ``joints``, ``mass``, ``mass_matrix``, ``gravity``, ``armature``, ``com``, ``spectrum``.
    """
    out = set()
    if a.joints != b.joints:
        out.add("joints")
    if not _close(a.mass, b.mass, rtol):
        out.add("mass")
    shared = sorted(set(a.mass_matrix) & set(b.mass_matrix))
    scale = max([abs(v) for v in (*a.mass_matrix.values(), *b.mass_matrix.values())] or [0.0])
    if any(abs(a.mass_matrix[k] - b.mass_matrix[k]) > rtol * max(scale, 1e-300) for k in shared):
        out.add("mass_matrix")
    if not np.allclose(a.gravity, b.gravity, rtol=rtol, atol=rtol * 9.81) or _differ(
        a.gravity_forces, b.gravity_forces, rtol
    ):
        out.add("gravity")
    if a.com and b.com and not np.allclose(a.com, b.com, rtol=rtol, atol=rtol * max(1.0, *map(abs, a.com))):
        out.add("com")
    if (
        a.spectrum
        and b.spectrum
        and (
            len(a.spectrum) != len(b.spectrum)
            or not np.allclose(a.spectrum, b.spectrum, rtol=0.0, atol=rtol * max(map(abs, (*a.spectrum, *b.spectrum))))
        )
    ):
        out.add("spectrum")
    joints = set(a.armature) | set(b.armature)
    if any(not _close(a.armature.get(j, 0.0), b.armature.get(j, 0.0), rtol) for j in joints):
        out.add("armature")
    return out


def fields(quantities: tuple[str, ...]) -> set[str]:
    """The measured fields that stand for a cause's quantities.

    Parameters
    ----------
    quantities : tuple of str

    Returns
    -------
    set of str
    """
    return {f for q in quantities for f in _FIELDS_OF[q]}


def _differ(a: Mapping[str, float], b: Mapping[str, float], rtol: float) -> bool:
    """Whether two per-joint readings differ on a joint both have, relative to their largest entry."""
    shared = sorted(set(a) & set(b))
    scale = max([abs(v) for v in (*a.values(), *b.values())] or [0.0])
    return any(abs(a[k] - b[k]) > rtol * max(scale, 1e-300) for k in shared)


def _close(x: float, y: float, rtol: float) -> bool:
    return abs(x - y) <= rtol * max(abs(x), abs(y), 1e-300)
