"""The independent route of the export tests: MuJoCo's and Pinocchio's own mass matrices, read here directly.

Nothing of koenig-check is used to load or pose a model: MuJoCo through ``MjModel``/``MjSpec`` and
``mj_fullM``, Pinocchio through its own parsers and ``crba``.  Coordinates are paired by joint name; a free
root is posed at the identity orientation, where MuJoCo's world-frame and Pinocchio's local-frame linear
velocities coincide, so the two mass matrices can be compared entry by entry.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin

MODELS = Path(__file__).resolve().parent / "models"
#: Relative tolerance of the independent checks.
RTOL = 1e-9
#: Label of the free root's six coordinates, whatever the joint is called in each engine.
FREE = "free"


def mujoco_model(path: Path, floating: bool = False) -> mujoco.MjModel:
    """MuJoCo's own model of an MJCF or URDF file (URDF: mesh paths as written, a free root if asked)."""
    spec = mujoco.MjSpec.from_file(str(path))
    if path.suffix == ".urdf":
        spec.strippath = False
        for mesh in spec.meshes:
            mesh.file = str((path.parent / mesh.file).resolve())
        if floating:
            spec.worldbody.first_body().add_freejoint()
    with warnings.catch_warnings():  # settotalmass.xml uses the construct on purpose
        warnings.filterwarnings("ignore", "compiler attribute 'settotalmass' is deprecated")
        return spec.compile()


def pinocchio_model(path: Path, floating: bool = False) -> pin.Model:
    """Pinocchio's own model of an MJCF or URDF file."""
    if path.suffix == ".urdf":
        if floating:
            return pin.buildModelFromUrdf(str(path), pin.JointModelFreeFlyer())
        return pin.buildModelFromUrdf(str(path))
    return pin.buildModelFromMJCF(str(path))


def _labels(name: str, nv: int, free: bool) -> list[str]:
    if free:
        return [f"{FREE}:{k}" for k in range(6)]
    return [name] if nv == 1 else [f"{name}:{k}" for k in range(nv)]


def random_joint_values(names: list[str], rng: np.random.Generator) -> dict[str, np.ndarray]:
    """A coordinate in [-1, 1] per one-dof joint and a random unit quaternion (w, x, y, z) per ball joint."""
    out: dict[str, np.ndarray] = {}
    for name in names:
        quat = rng.normal(size=4)
        out[name] = np.array([rng.uniform(-1, 1)])
        out[name + ":quat"] = quat / np.linalg.norm(quat)
    return out


def mujoco_matrix(model: mujoco.MjModel, values: dict[str, np.ndarray]) -> tuple[np.ndarray, list[str]]:
    """MuJoCo's rigid mass matrix (armature removed) at the named joint values, and each row's label."""
    qpos = np.array(model.qpos0, dtype=float)
    labels: list[str] = []
    for j in range(model.njnt):
        name, adr, kind = model.joint(j).name, int(model.jnt_qposadr[j]), int(model.jnt_type[j])
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            qpos[adr : adr + 7] = [0, 0, 0, 1, 0, 0, 0]
            labels += _labels(name, 6, True)
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            qpos[adr : adr + 4] = values[name + ":quat"]
            labels += _labels(name, 3, False)
        else:
            qpos[adr] = values[name][0]
            labels.append(name)
    data = mujoco.MjData(model)
    data.qpos[:] = qpos
    mujoco.mj_forward(model, data)
    matrix = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, matrix)
    return matrix - np.diag(model.dof_armature), labels


def sibling_joints(path: Path) -> dict[str, list[str]]:
    """MJCF: the first joint of each body with several joints -> all its joints in file order.

    Pinocchio's MJCF parser turns such a body's joints into one composite joint named after the first one.
    """
    import xml.etree.ElementTree as ET

    out = {}
    for body in ET.parse(path).getroot().iter("body"):
        names = [j.get("name", "") for j in body.findall("joint")]
        if len(names) > 1:
            out[names[0]] = names
    return out


def pinocchio_matrix(
    model: pin.Model, values: dict[str, np.ndarray], siblings: dict[str, list[str]] | None = None
) -> tuple[np.ndarray, list[str]]:
    """Pinocchio's rigid mass matrix (armature removed) at the named joint values, and each row's label.

    ``siblings`` (:func:`sibling_joints`) names the one-dof joints inside a composite joint.
    """
    q = pin.neutral(model)
    labels: list[str] = [""] * model.nv
    for j in range(1, model.njoints):
        joint, name = model.joints[j], model.names[j]
        iq, iv, nq, nv = joint.idx_q, joint.idx_v, joint.nq, joint.nv
        if joint.shortname() == "JointModelComposite":
            parts = (siblings or {})[name.removeprefix("Composite_")]
            assert nq == nv == len(parts), (name, parts)
            q[iq : iq + nq] = [values[p][0] for p in parts]
            labels[iv : iv + nv] = parts
            continue
        if nq == 7 and nv == 6:
            q[iq : iq + 7] = [0, 0, 0, 0, 0, 0, 1]
        elif nq == 4 and nv == 3:
            w, x, y, z = values[name + ":quat"]
            q[iq : iq + 4] = [x, y, z, w]
        elif nq == 2 and nv == 1:
            q[iq : iq + 2] = [np.cos(values[name][0]), np.sin(values[name][0])]
        else:
            q[iq] = values[name][0]
        labels[iv : iv + nv] = _labels(name, nv, nq == 7)
    data = model.createData()
    pin.crba(model, data, q)
    matrix = np.triu(data.M) + np.triu(data.M, 1).T
    return matrix - np.diag(model.armature), labels


def in_order(matrix: np.ndarray, labels: list[str], order: list[str]) -> np.ndarray:
    """The matrix with rows and columns in ``order`` (every label must be there)."""
    index = [labels.index(name) for name in order]
    return matrix[np.ix_(index, index)]


def relative_difference(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / max |a|."""
    return float(np.abs(a - b).max() / np.abs(a).max())


def one_dof_joint_names(model: mujoco.MjModel) -> list[str]:
    """Names of the MuJoCo model's joints (every joint of the test models is named)."""
    return [model.joint(j).name for j in range(model.njnt)]
