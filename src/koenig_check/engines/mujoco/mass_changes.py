"""What MuJoCo's compiler changed in the file's masses and inertias, each a finding on the body it concerns.

A ``balanceinertia`` change, or a mass or inertia the compiler altered (``settotalmass``, ``boundmass``, ...):
MuJoCo differs from the file there, Pinocchio keeps the file's values.  (A body repaired with ``repair_inertia``
is found while compiling: :func:`koenig_check.engines.mujoco.compiling.repair_finding`.)
"""

from __future__ import annotations

import mujoco
import numpy as np

from koenig_check.engines.mujoco.meshes import drop_mesh
from koenig_check.findings import Finding, Kind
from koenig_check.segments import check_physical_inertia, principal_moments
from koenig_check.sources.catalogue import ModelSource

#: A body's mass-property change with the body it concerns (mapped to its segment by the engine adapter).
BodyFinding = tuple[str, Finding]

#: Relative change of the principal moments under which the compiler is taken to have left a body as written.
UNCHANGED_RTOL = 1e-9


def balance_findings(
    spec_before: mujoco.MjSpec,
    refused: list[str],
    model: mujoco.MjModel,
    source: ModelSource,
    file_inertia: dict[str, tuple[float, np.ndarray]],
) -> list[BodyFinding]:
    """Per link whose inertia MuJoCo would reject: how balanceinertia changed it (a REPAIR finding).

    Parameters
    ----------
    spec_before : mujoco.MjSpec
        The spec as it was before compilation (compiled again without fusing when a body was fused away).
    refused : list of str
        Meshes dropped while compiling.
    model : mujoco.MjModel
        The compiled model.
    source : ModelSource
    file_inertia : dict of str to (float, ndarray)
        Each body's mass and inertia as the file declares them.

    Returns
    -------
    list of (str, Finding)
    """
    bad = {}
    for name, (mass, inertia) in file_inertia.items():
        lam = principal_moments(inertia)
        if mass > 0 and (check_physical_inertia(mass, inertia) is not None or lam[0] <= 0):
            bad[name] = lam
    if not bad:
        return []
    compiled = model
    if any(mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n) < 0 for n in bad):
        spec_before.compiler.fusestatic = False
        for mesh in list(spec_before.meshes):
            if mesh.name in refused:
                drop_mesh(spec_before, mesh)
        compiled = spec_before.compile()
    what = "link" if source.format == "urdf" else "body"
    out = []
    for name, lam in bad.items():
        bid = mujoco.mj_name2id(compiled, mujoco.mjtObj.mjOBJ_BODY, name)
        new = np.sort(compiled.body_inertia[bid])
        change = np.abs(new - lam).max() / max(np.abs(lam).max(), 1e-300)
        if change <= UNCHANGED_RTOL:  # balanceinertia left it as written (a zero moment is no A + B < C)
            continue
        finding = Finding(
            Kind.REPAIR,
            "mujoco",
            f"{what} {name}",
            "principal moments changed by MuJoCo's balanceinertia (A + B >= C); Pinocchio keeps the file's values",
            {
                "moments before": lam.round(12).tolist(),
                "moments after": new.round(12).tolist(),
                "max relative change": change,
            },
            affects_energy=True,
            root_cause=True,
            hint="--balance-inertia (balance_inertia=True) was asked for",
            brief="principal moments changed by MuJoCo's balanceinertia",
        )
        out.append((name, finding))
    return out


def altered_by_compiler(model: mujoco.MjModel, file_inertia: dict[str, tuple[float, np.ndarray]]) -> list[str]:
    """Bodies still present after compilation whose mass or principal moments differ from the file's.

    Parameters
    ----------
    model : mujoco.MjModel
    file_inertia : dict of str to (float, ndarray)
        Each body's mass and inertia as the file declares them.

    Returns
    -------
    list of str
    """
    out = []
    for name, (mass, inertia) in file_inertia.items():
        bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
        if bid < 0:
            continue
        moments = principal_moments(inertia)
        compiled = np.sort(model.body_inertia[bid])
        scale = max(np.abs(moments).max(), 1e-300)
        if abs(model.body_mass[bid] - mass) > 1e-12 * max(mass, 1e-300) or np.abs(compiled - moments).max() > (
            UNCHANGED_RTOL * scale
        ):
            out.append(name)
    return out
