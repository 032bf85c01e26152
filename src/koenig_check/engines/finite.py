"""Refuse compiled models that carry non-finite or implausible numbers, or unphysical segments.

A file may hold NaN, inf or absurd magnitudes (1e300 m) that a parser accepts; they would only
surface later as non-finite energies.  These checks run at load time and name the element.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pinocchio as pin

from koenig_check.engines.errors import ModelLoadError
from koenig_check.findings import Finding, Kind

#: Largest length (m), mass (kg) or inertia (kg m²) accepted as physical.
MAX_MAGNITUDE = 1e6

#: MuJoCo model arrays checked, with the kind of element each row belongs to.
_MUJOCO_FIELDS = {
    "body_pos": mujoco.mjtObj.mjOBJ_BODY,
    "body_quat": mujoco.mjtObj.mjOBJ_BODY,
    "body_ipos": mujoco.mjtObj.mjOBJ_BODY,
    "body_iquat": mujoco.mjtObj.mjOBJ_BODY,
    "body_mass": mujoco.mjtObj.mjOBJ_BODY,
    "body_inertia": mujoco.mjtObj.mjOBJ_BODY,
    "jnt_pos": mujoco.mjtObj.mjOBJ_JOINT,
    "jnt_axis": mujoco.mjtObj.mjOBJ_JOINT,
    "jnt_range": mujoco.mjtObj.mjOBJ_JOINT,
    "qpos0": None,
    "dof_armature": None,
}


#: Fields where huge finite values are legitimate (e.g. ±1e16 limits of continuous joints).
_UNBOUNDED = frozenset({"jnt_range", "qpos0"})


def check_finite(mj_model: mujoco.MjModel, pin_model: pin.Model, path: str) -> None:
    """Raise if either engine compiled a non-finite number into the model.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    pin_model : pinocchio.Model
    path : str
        The model file, for the message.

    Raises
    ------
    ModelLoadError
        Naming the file, the engine, the element and the quantity.
    """
    for field, obj in _MUJOCO_FIELDS.items():
        values = np.asarray(getattr(mj_model, field), dtype=float)
        if values.size == 0:
            continue
        values = values.reshape(values.shape[0], -1) if values.ndim else values.reshape(1, 1)
        bad = ~np.isfinite(values)
        if field not in _UNBOUNDED:
            bad |= np.abs(values) > MAX_MAGNITUDE
        if bad.any():
            row = int(np.argwhere(bad)[0][0])
            if obj is None:
                where = f"{field}[{row}]"
            else:
                kind = "body" if obj == mujoco.mjtObj.mjOBJ_BODY else "joint"
                where = f"{kind} {mujoco.mj_id2name(mj_model, obj, row) or row!r}: {field.split('_', 1)[1]}"
            value = values[tuple(np.argwhere(bad)[0])]
            raise ModelLoadError(
                f"{path}: non-finite or implausible value {value:g} in MuJoCo's model, {where} "
                f"(|value| must be finite and at most {MAX_MAGNITUDE:g})"
            )
    axes = np.linalg.norm(np.asarray(mj_model.jnt_axis, dtype=float).reshape(-1, 3), axis=1)
    for j in range(mj_model.njnt):
        if int(mj_model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
            if abs(axes[j] - 1.0) > 1e-6:
                name = mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_JOINT, j) or f"#{j}"
                raise ModelLoadError(
                    f"{path}: joint {name!r}: its axis has no direction after normalisation (MuJoCo made it "
                    f"{np.round(mj_model.jnt_axis[j], 6).tolist()}): zero, non-finite or overflowing components"
                )
    for j in range(1, pin_model.njoints):
        name = pin_model.names[j]
        inertia = pin_model.inertias[j]
        placement = pin_model.jointPlacements[j]
        values = np.concatenate(
            [[inertia.mass], inertia.lever, inertia.inertia.ravel(), placement.translation, placement.rotation.ravel()]
        )
        if not np.all(np.isfinite(values)) or np.abs(values).max() > MAX_MAGNITUDE:
            raise ModelLoadError(
                f"{path}: non-finite or implausible value in Pinocchio's model, joint {name!r}: placement or "
                f"inertia (|value| must be finite and at most {MAX_MAGNITUDE:g})"
            )


def check_segments(
    engines: tuple, qpos0: np.ndarray, path: str, tolerate: frozenset[str] = frozenset()
) -> list[Finding]:
    """Probe each engine at its reference pose: valid segment states and physical lumped inertias.

    Parameters
    ----------
    engines : tuple of engine models
        Objects with ``engine``, ``nv`` and ``segment_states`` (canonical states).
    qpos0 : ndarray, shape (nq,)
        The canonical reference configuration (MuJoCo ``qpos0``).
    path : str
    tolerate : frozenset of str
        Engines whose non-physical segment inertias are noted instead of refused (Pinocchio keeps
        the file's inertia when MuJoCo was asked to balance it).

    Returns
    -------
    list of Finding
        Tolerated non-physical segments (kind ``INERTIA``).

    Raises
    ------
    ModelLoadError
        Naming the file, the engine and the segment.
    """
    from koenig_check.segments import check_physical_inertia

    notes: list[Finding] = []

    for engine in engines:
        try:
            states = engine.segment_states(np.asarray(qpos0)[None], np.zeros((1, engine.nv)))
        except ValueError as err:
            error = ModelLoadError(f"{path}: {engine.engine} gives an invalid state at the reference pose: {err}")
            error.brief = f"{path}: {engine.engine} gives an invalid state at the reference pose ({err})"  # cut first
            raise error from None
        for name, mass, inertia in zip(states.names, states.mass, states.inertia_body, strict=True):
            reason = check_physical_inertia(float(mass), inertia)
            if reason is None:
                continue
            if engine.engine in tolerate:
                notes.append(
                    Finding(Kind.INERTIA, engine.engine, f"segment {name}", f"keeps a non-physical inertia: {reason}")
                )
            else:
                raise ModelLoadError(f"{path}: {engine.engine}: segment {name!r} (with its welded links): {reason}")
    return notes
