"""User-supplied pose files: canonical (MuJoCo-layout) ``qpos`` and ``qvel`` rows.

Two formats:

``.npz``
    arrays ``qpos`` (P, nq) and ``qvel`` (P, nv), optionally ``ids`` (P,) strings;
``.csv``
    one pose per row, ``nq + nv`` numbers (``qpos`` then ``qvel``); lines starting with ``#``
    and a first line of column names are skipped.

Non-finite values and quaternions far from unit length are refused with the file, row
and column; poses outside joint limits are allowed and flagged in the notes.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines.canonical import mujoco_coordinate_names
from koenig_check.exceptions import PoseFileError
from koenig_check.run.poses import PoseSet

#: Largest accepted deviation of a quaternion's norm from 1.
QUAT_NORM_TOL = 1e-6


def _read(path: Path, nq: int, nv: int) -> tuple[np.ndarray, np.ndarray, tuple[str, ...] | None]:
    if not path.exists():
        raise PoseFileError(f"{path}: pose file not found")
    if path.suffix == ".npz":
        try:
            with np.load(path, allow_pickle=False) as data:
                if "qpos" not in data or "qvel" not in data:
                    raise PoseFileError(f"{path}: needs arrays 'qpos' and 'qvel', found {sorted(data.files)}")
                qpos, qvel = np.asarray(data["qpos"], dtype=float), np.asarray(data["qvel"], dtype=float)
                ids = tuple(str(x) for x in data["ids"]) if "ids" in data else None
        except (OSError, ValueError) as err:
            if isinstance(err, PoseFileError):
                raise
            raise PoseFileError(f"{path}: not a readable .npz file ({err})") from None
        return np.atleast_2d(qpos), np.atleast_2d(qvel), ids
    rows = []
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as err:
        raise PoseFileError(f"{path}: cannot be read ({err})") from None
    header_allowed = True
    for number, line in enumerate(lines, start=1):
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        cells = [c.strip() for c in text.split(",")]
        bad = [c for c in cells if not _is_float(c)]
        if bad and header_allowed:
            header_allowed = False  # the first data line may be column names
            continue
        header_allowed = False
        if bad:
            raise PoseFileError(f"{path}: row {number}: {bad[0]!r} is not a number")
        if len(cells) != nq + nv:
            raise PoseFileError(f"{path}: row {number}: {len(cells)} values, expected nq + nv = {nq} + {nv}")
        rows.append([float(c) for c in cells])
    if not rows:
        raise PoseFileError(f"{path}: no pose rows")
    table = np.array(rows)
    return table[:, :nq], table[:, nq:], None


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def load_pose_file(path: str | Path, model: mujoco.MjModel) -> PoseSet:
    """Read a pose file for a model, validating every value.

    Parameters
    ----------
    path : str or Path
    model : mujoco.MjModel
        The canonical layout (``nq``, ``nv``, joint limits, quaternion slots).

    Returns
    -------
    PoseSet
        Kind ``file``; ``notes`` list the poses outside joint limits.

    Raises
    ------
    PoseFileError
        Missing or unreadable file, wrong shape, non-finite value, non-unit quaternion.
    """
    path = Path(path)
    qpos, qvel, ids = _read(path, model.nq, model.nv)
    if qpos.shape[1] != model.nq or qvel.shape[1] != model.nv or qpos.shape[0] != qvel.shape[0]:
        raise PoseFileError(
            f"{path}: qpos {qpos.shape} and qvel {qvel.shape} do not fit the model (nq={model.nq}, nv={model.nv})"
        )
    qnames, vnames = mujoco_coordinate_names(model)
    for arr, names, what in ((qpos, qnames, "qpos"), (qvel, vnames, "qvel")):
        bad = ~np.isfinite(arr)
        if bad.any():
            row, col = np.argwhere(bad)[0]
            raise PoseFileError(
                f"{path}: row {row + 1}: {what}[{col}] ({names[col]}) is {arr[row, col]}: every value must be finite"
            )
    notes = []
    at_rest = np.flatnonzero(~np.any(qvel, axis=1))
    if at_rest.size == qvel.shape[0]:
        raise PoseFileError(
            f"{path}: every pose has zero velocity: every kinetic energy is zero and no relative error is defined"
        )
    if at_rest.size:
        notes.append(
            f"{path.name}: {at_rest.size} pose(s) at rest (first: row {at_rest[0] + 1}): their energies are zero "
            "and their relative errors are 0 by convention"
        )
    for j in range(model.njnt):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j) or f"joint{j}"
        adr, jtype = model.jnt_qposadr[j], int(model.jnt_type[j])
        if jtype in (0, 1):  # free, ball: a quaternion
            start = adr + (3 if jtype == 0 else 0)
            norm = np.linalg.norm(qpos[:, start : start + 4], axis=1)
            off = np.flatnonzero(np.abs(norm - 1) > QUAT_NORM_TOL)
            if off.size:
                raise PoseFileError(
                    f"{path}: row {off[0] + 1}: quaternion of joint {name!r} has norm {norm[off[0]]:.9g}, expected 1"
                )
        elif model.jnt_limited[j]:
            lo, hi = model.jnt_range[j]
            outside = np.flatnonzero((qpos[:, adr] < lo) | (qpos[:, adr] > hi))
            if outside.size:
                notes.append(
                    f"{path.name}: {outside.size} pose(s) put joint {name!r} outside its range [{lo:g}, {hi:g}] "
                    f"(first: row {outside[0] + 1}, value {qpos[outside[0], adr]:g}); they are compared as given"
                )
    if ids is None:
        ids = tuple(f"file-{i}" for i in range(qpos.shape[0]))
    return PoseSet(qpos, qvel, ids, "file", notes=tuple(notes))
