"""Checks shared by the tests of the engines that read URDF only (PyBullet, iDynTree): each test module runs them.

* :func:`two_link_arm` and :func:`hand_mass_matrix`: a planar 2-link arm whose mass matrix is written by hand;
* :func:`against_mujoco_and_pinocchio`: the engine against MuJoCo and Pinocchio on one loaded model, every
  quantity of the Engine interface, within the engine's declared precision;
* :func:`check_two_link_arm` and :func:`check_agrees` over :data:`ELBOWS` and :data:`CASES`: what each module runs.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from koenig_check.engines import load_model, random_states
from koenig_check.engines.specs import spec

#: The arm: link lengths, COM distances along each link, masses, central moments about the joint axis (z).
L1, C1, C2, M1, M2, I1, I2 = 0.5, 0.2, 0.15, 2.0, 1.5, 0.03, 0.02

ARM = f"""<robot name="two_link_arm">
  <link name="base"/>
  <link name="upper">
    <inertial><origin xyz="{C1} 0 0"/><mass value="{M1}"/>
      <inertia ixx="0.01" iyy="0.025" izz="{I1}" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="fore">
    <inertial><origin xyz="{C2} 0 0"/><mass value="{M2}"/>
      <inertia ixx="0.01" iyy="0.015" izz="{I2}" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/><origin xyz="{L1} 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


def two_link_arm(folder: Path) -> Path:
    """Write the arm's URDF in ``folder``.

    Parameters
    ----------
    folder : Path

    Returns
    -------
    Path
    """
    path = folder / "two_link_arm.urdf"
    path.write_text(ARM)
    return path


def hand_mass_matrix(elbow: float) -> np.ndarray:
    """The arm's mass matrix by hand (planar arm, both axes z): it depends on the elbow angle only.

    Parameters
    ----------
    elbow : float

    Returns
    -------
    ndarray, shape (2, 2)
    """
    c = np.cos(elbow)
    m22 = I2 + M2 * C2**2
    m12 = m22 + M2 * L1 * C2 * c
    m11 = I1 + M1 * C1**2 + I2 + M2 * (L1**2 + C2**2 + 2 * L1 * C2 * c)
    return np.array([[m11, m12], [m12, m22]])


def _rel(a: np.ndarray, b: np.ndarray, scale: float | None = None) -> float:
    """Largest difference relative to ``scale`` (default: the reference's largest entry)."""
    return float(np.abs(a - b).max() / max(np.abs(b).max() if scale is None else scale, 1e-300))


def against_mujoco_and_pinocchio(pair, name: str, n_poses: int = 6, seed: int = 7) -> dict[str, float]:
    """The largest relative difference of each quantity between an optional engine and MuJoCo, Pinocchio.

    Parameters
    ----------
    pair : LoadedModel
    name : str
        The optional engine.
    n_poses, seed : int

    Returns
    -------
    dict of str to float
        ``"<quantity> vs <engine>"`` -> relative difference (to the reference's largest entry).
    """
    engine = pair.attach(name)
    assert engine is not None, pair.refusal(name)
    qpos, qvel = random_states(pair.mujoco.model, n_poses, seed=seed)
    qacc = np.random.default_rng(seed).normal(size=qvel.shape)
    out = {}
    for ref_name in ("mujoco", "pinocchio"):
        ref = pair.engines[ref_name]
        energies = (e.kinetic_energy(qpos, qvel).total for e in (engine, ref))
        out[f"energy vs {ref_name}"] = _rel(*energies)
        out[f"M vs {ref_name}"] = _rel(engine.mass_matrix(qpos), ref.mass_matrix(qpos))
        out[f"inverse dynamics vs {ref_name}"] = _rel(
            engine.inverse_dynamics(qpos, qvel, qacc), ref.inverse_dynamics(qpos, qvel, qacc)
        )
        mine, theirs = engine.segment_states(qpos, qvel), ref.segment_states(qpos, qvel)
        assert mine.names == theirs.names
        # Points against the largest distance, point velocities against the largest speed: a pole on the axis of
        # a fixed base's first joint does not move, its velocity is round-off in both engines.
        length = max(float(np.abs(getattr(theirs, f)).max()) for f in ("com", "pole", "com_ref", "pole_ref"))
        speed = max(float(np.abs(getattr(theirs, f)).max()) for f in ("v_com", "v_pole"))
        scales = {"com": length, "pole": length, "com_ref": length, "pole_ref": length, "v_com": speed, "v_pole": speed}
        for field in ("mass", "omega", *scales):
            out[f"{field} vs {ref_name}"] = _rel(getattr(mine, field), getattr(theirs, field), scales.get(field))
        world = [np.einsum("pbij,bjk,pblk->pbil", s.rotation, s.inertia_body, s.rotation) for s in (mine, theirs)]
        out[f"world inertia vs {ref_name}"] = _rel(*world)
    return out


#: The project's URDF models, with a fixed base and a floating one (free_body only floats), and their test ids.
CASES = [
    (m, f)
    for m in ("double_pendulum.urdf", "gimbal.urdf", "serial7.urdf", "armature_chain.urdf", "free_body.urdf")
    for f in (False, True)
    if f or m != "free_body.urdf"
]
CASE_IDS = [f"{m}-{'floating' if f else 'fixed'}" for m, f in CASES]
#: Elbow angles of :func:`check_two_link_arm`.
ELBOWS = [0.0, 0.7, -1.9, np.pi]


def check_two_link_arm(folder: Path, name: str, elbow: float) -> None:
    """The engine's mass matrix of :func:`two_link_arm` equals :func:`hand_mass_matrix` within its precision.

    Parameters
    ----------
    folder : Path
        Where the arm's URDF is written.
    name : str
        The engine.
    elbow : float
    """
    pair = load_model(str(two_link_arm(folder)))
    engine = pair.attach(name)
    assert engine is not None, pair.refusal(name)
    qpos = np.zeros((1, pair.mujoco.nq))
    qpos[0, pair.mujoco.model.joint("elbow").qposadr[0]] = elbow
    qpos[0, pair.mujoco.model.joint("shoulder").qposadr[0]] = 0.4  # M does not depend on it
    by_hand = hand_mass_matrix(elbow)
    order = [pair.mujoco.model.joint(n).dofadr[0] for n in ("shoulder", "elbow")]
    M = engine.mass_matrix(qpos)[0][np.ix_(order, order)]
    assert np.abs(M - by_hand).max() <= precision(name) * np.abs(by_hand).max()


def check_agrees(model: str, floating: bool, name: str) -> None:
    """Every quantity of :func:`against_mujoco_and_pinocchio` within the engine's precision on one case.

    Parameters
    ----------
    model : str
    floating : bool
    name : str
        The engine.
    """
    differences = against_mujoco_and_pinocchio(load_model(model, floating=floating), name)
    worst = max(differences, key=differences.get)
    assert differences[worst] <= precision(name), f"{worst}: {differences[worst]:.3g}"


def precision(name: str) -> float:
    """The engine's declared precision (its spec's).

    Parameters
    ----------
    name : str

    Returns
    -------
    float
    """
    return spec(name).precision


#: A moving arm with a massless foot that has a moment of inertia (example-robot-data's bolt has four).
MASSLESS_FOOT = """<robot name="massless_foot">
  <link name="base"/>
  <link name="leg"><inertial><origin xyz="0 0 -0.1"/><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.002" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="foot"><inertial><mass value="0"/>
    <inertia ixx="0.004" iyy="0.005" izz="0.003" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hip" type="revolute"><parent link="base"/><child link="leg"/><axis xyz="1 0 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="ankle" type="fixed"><parent link="leg"/><child link="foot"/><origin xyz="0 0 -0.3"/></joint>
</robot>
"""


def exact_energy(states) -> np.ndarray:
    """``Σ ½ m v_C² + ½ ω·I_C ω`` of segment states (world inertia from the segment's own), shape (P,).

    Parameters
    ----------
    states : SegmentStates

    Returns
    -------
    ndarray, shape (P,)
    """
    w_body = np.einsum("pbji,pbj->pbi", states.rotation, states.omega)
    rot = np.einsum("pbi,bij,pbj->p", w_body, states.inertia_body, w_body)
    return 0.5 * (np.einsum("b,pbi,pbi->p", states.mass, states.v_com, states.v_com) + rot)
