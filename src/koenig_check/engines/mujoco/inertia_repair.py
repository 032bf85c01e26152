"""The smallest change of a body's mass and inertia that MuJoCo's compiler accepts (``--repair-inertia``).

MuJoCo 4.0 refuses, at compile time (checks measured on MuJoCo 4.0, ``mujoco.mjMINVAL`` = 1e-15):

* a moving body (one with a joint) whose mass or a principal moment is below ``mjMINVAL``
  ("mass and inertia of moving bodies must be larger than mjMINVAL");
* a full inertia (``fullinertia``, products of inertia) whose eigenvalues, as MuJoCo computes them,
  are not above ``mjEPS`` = 1e-14 ("inertia must have positive eigenvalues": measured, 1e-14 passes
  about half the time and 2e-14 always for moments of order 1);
* principal moments that violate the triangle inequality ``A + B >= C`` (checked exactly, without
  tolerance; MuJoCo's own ``balanceinertia`` is the other way out).

:func:`repair_body` changes one spec body so that it passes all three checks, and nothing more:
a moving body's mass is raised to a floor just above ``mjMINVAL``; the sorted principal moments
``A <= B <= C`` are changed by the least largest amount ``t = max(floor − A, (C − A − B)/3, 0)``
that makes them acceptable: ``A`` is raised by ``t``, then ``B`` raised and ``C`` lowered by the same
amount, no more than needed for ``A + B >= C`` (plus a few ulps for MuJoCo's exact check).  The
principal axes are kept.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

#: MuJoCo's lower bound on a moving body's mass and principal moments.
MJMINVAL = float(mujoco.mjMINVAL)
#: Floor the repair raises masses and diagonal principal moments to (MuJoCo accepts values >= mjMINVAL).
FLOOR = 2.0 * MJMINVAL
#: MuJoCo's threshold on the eigenvalues of a full inertia (``mjEPS``).
MJEPS = 1e-14


@dataclass(frozen=True)
class Repair:
    """What :func:`repair_body` changed on one body (values before and after)."""

    body: str
    mass: tuple[float, float]
    moments: tuple[tuple[float, ...], tuple[float, ...]]

    @property
    def max_change(self) -> float:
        """Largest absolute change of a principal moment (kg m²)."""
        return float(np.abs(np.subtract(self.moments[1], self.moments[0])).max())


def repaired_moments(moments: np.ndarray, margin: float = 8.0, full: bool = False) -> np.ndarray:
    """Principal moments raised to the floor MuJoCo accepts and balanced so that ``A + B >= C``.

    Parameters
    ----------
    moments : ndarray, shape (3,)
        Principal moments in any order (the order is kept).
    margin : float
        Ulps of the largest moment added to the floor and to the balance so that MuJoCo's checks
        pass after its own eigen-decomposition.
    full : bool
        The moments come from a full inertia tensor: the floor is ``2 mjEPS`` plus the margin
        instead of ``2 mjMINVAL``.

    Returns
    -------
    ndarray, shape (3,)
    """
    lam = np.asarray(moments, dtype=float)
    ulps = margin * np.finfo(float).eps * float(np.abs(lam).max(initial=0.0))
    floor = 2.0 * MJEPS + 8.0 * ulps if full else FLOOR
    order = np.argsort(lam)
    a, b, c = lam[order]
    pad = 3.0 * ulps  # slack so that MuJoCo's exact A + B >= C holds after its own eigen-decomposition
    if a >= floor and a + b >= c + pad:
        return lam
    # The smallest largest change t: A + t >= floor and (A + t) + (B + t) >= C - t.
    t = max(floor - a, (c + pad - a - b) / 3.0, 0.0)
    x = a + t
    shift = min(max((c + pad - x - b) / 2.0, 0.0), t)  # raise B and lower C by as little as needed
    out = lam.copy()
    out[order] = (x, max(b + shift, floor), max(c - shift, floor))
    return out


def repair_body(body: mujoco.MjsBody, margin: float = 8.0) -> Repair:
    """Change a spec body's mass and inertia to the smallest values MuJoCo accepts (in place).

    Parameters
    ----------
    body : mujoco.MjsBody
    margin : float
        See :func:`repaired_moments`.

    Returns
    -------
    Repair
        The mass and principal moments before and after.
    """
    moving = len(list(body.joints)) > 0
    if not body.explicitinertial:  # no <inertial>: MuJoCo gives it nothing (inertiafromgeom=false)
        body.explicitinertial = True
        body.ipos = [0.0, 0.0, 0.0]
        body.mass = 0.0
        body.inertia = [0.0, 0.0, 0.0]
        body.fullinertia = [np.nan] * 6
    mass = float(body.mass)
    full = np.asarray(body.fullinertia, dtype=float)
    if np.isnan(full[0]):
        before = np.asarray(body.inertia, dtype=float).copy()
        after = repaired_moments(before, margin)
        body.inertia = after.tolist()
    else:
        xx, yy, zz, xy, xz, yz = full
        tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        before, axes = np.linalg.eigh(tensor)
        after = repaired_moments(before, margin, full=True)
        new = axes @ np.diag(after) @ axes.T
        body.fullinertia = [new[0, 0], new[1, 1], new[2, 2], new[0, 1], new[0, 2], new[1, 2]]
    new_mass = max(mass, FLOOR) if moving or mass > 0 else mass
    body.mass = new_mass
    return Repair(body.name, (mass, new_mass), (tuple(before.tolist()), tuple(after.tolist())))
