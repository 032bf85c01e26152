"""Refuse compiled models that carry non-finite numbers, or unphysical segments; note large finite numbers.

A file may hold NaN or inf that a parser accepts; they would only surface later as non-finite energies.  A
large finite number (a 100 kg sensor link 333 m away, fused by MuJoCo into its carrier: an inertia of 4e7
kg m²) is the engines' to accept or refuse, not ours: it is noted, never refused.  These checks run at load
time and name the element.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pinocchio as pin

from koenig_check.engines.errors import ModelLoadError
from koenig_check.findings import Finding, Kind

#: Largest length (m), mass (kg) or inertia (kg m²) taken without a note (a larger finite one is noted).
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


def check_finite(mj_model: mujoco.MjModel, pin_model: pin.Model, path: str, names: tuple[str, str]) -> list[Finding]:
    """Raise if either engine compiled a non-finite number into the model; note each large finite one.

    Parameters
    ----------
    mj_model : mujoco.MjModel
    pin_model : pinocchio.Model
    path : str
        The model file, for the message.
    names : (str, str)
        The two engines' names, as the findings carry them (MuJoCo's, Pinocchio's).

    Returns
    -------
    list of Finding
        One ``LOAD`` note per engine whose model holds a finite value above :data:`MAX_MAGNITUDE` (the
        first such element and its value): both engines loaded it, so it is theirs to judge.

    Raises
    ------
    ModelLoadError
        Naming the file, the engine, the element and the quantity.
    """
    notes: list[Finding] = []
    for field, obj in _MUJOCO_FIELDS.items():
        values = np.asarray(getattr(mj_model, field), dtype=float)
        if values.size == 0:
            continue
        values = values.reshape(values.shape[0], -1) if values.ndim else values.reshape(1, 1)
        bad = ~np.isfinite(values)
        large = np.zeros_like(bad) if field in _UNBOUNDED else np.isfinite(values) & (np.abs(values) > MAX_MAGNITUDE)
        for found, refused in ((bad, True), (large, False)):
            if not found.any() or (not refused and notes):
                continue
            row = int(np.argwhere(found)[0][0])
            if obj is None:
                element, quantity = "model", f"{field}[{row}]"
            else:
                kind = "body" if obj == mujoco.mjtObj.mjOBJ_BODY else "joint"
                element = f"{kind} {mujoco.mj_id2name(mj_model, obj, row) or f'#{row}'}"
                quantity = field.split("_", 1)[1]
            value = float(values[tuple(np.argwhere(found)[0])])
            if refused:
                raise ModelLoadError(f"{path}: non-finite value {value:g} in MuJoCo's model, {element}: {quantity}")
            notes.append(_large(names[0], element, quantity, value))
    axes = np.linalg.norm(np.asarray(mj_model.jnt_axis, dtype=float).reshape(-1, 3), axis=1)
    for j in range(mj_model.njnt):
        if int(mj_model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
            if abs(axes[j] - 1.0) > 1e-6:
                name = mujoco.mj_id2name(mj_model, mujoco.mjtObj.mjOBJ_JOINT, j) or f"#{j}"
                raise ModelLoadError(
                    f"{path}: joint {name!r}: its axis has no direction after normalisation (MuJoCo made it "
                    f"{np.round(mj_model.jnt_axis[j], 6).tolist()}): zero, non-finite or overflowing components"
                )
    pin_noted = False
    for j in range(1, pin_model.njoints):
        name = pin_model.names[j]
        inertia = pin_model.inertias[j]
        placement = pin_model.jointPlacements[j]
        values = np.concatenate(
            [[inertia.mass], inertia.lever, inertia.inertia.ravel(), placement.translation, placement.rotation.ravel()]
        )
        if not np.all(np.isfinite(values)):
            raise ModelLoadError(f"{path}: non-finite value in Pinocchio's model, joint {name!r}: placement or inertia")
        largest = float(np.abs(values).max())
        if largest > MAX_MAGNITUDE and not pin_noted:
            notes.append(_large(names[1], f"joint {name}", "placement or inertia", largest))
            pin_noted = True
    return notes


def _large(engine: str, element: str, quantity: str, value: float) -> Finding:
    """The note of a large finite value in an engine's model (the engine loaded it: it is not refused)."""
    return Finding(
        Kind.LOAD,
        engine,
        element,
        f"holds a large finite value ({quantity}); loaded as written",
        {"value": value, "noted above": MAX_MAGNITUDE},
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
