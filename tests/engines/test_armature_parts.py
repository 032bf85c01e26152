"""Each engine's armature parts (``armature_matrix``, ``armature_forces``): its own matrices with and without armature.

Expected values come from the engines' own routes, not from the adapters' armature code:

* MuJoCo: ``mj_fullM`` and ``mj_inverse`` of the file compiled as written, minus the same of the file compiled with
  every joint's armature set to zero (``MjSpec``).  Compiling anew also recomputes the diagonal MuJoCo precomputes
  for its "simple" dofs (``dof_M0``), so the difference is the armature wherever it sits.
* Drake: ``CalcMassMatrix`` and ``CalcInverseDynamics`` with the actuators' rotor inertias as loaded, minus the same
  with them zero, mapped to canonical coordinates by the state map.

Real files: dm_control's suite models whose actuated joints carry armature (Drake's MJCF parser turns a motor's
joint armature into the motor's rotor inertia, armature / gear², so Drake has it too); the project's single-joint
models, whose joints no motor drives (Drake's parser drops their armature: Drake answers zero, as its own mass
matrix has none, and ``attach`` reports the joints); one hinge driven by two motors (Drake's mass matrix counts the
joint's reflected inertia once, not once per motor).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.engines import load_model, random_states
from koenig_check.engines.canonical import mujoco_joint_names
from koenig_check.findings import Kind

pytestmark = pytest.mark.filterwarnings("ignore:compiler attribute 'settotalmass' is deprecated")

MODELS = Path(__file__).parent / "models"
#: dm_control suite models with armature (``grep -l armature``): cheetah and walker slides and hinges, hopper,
#: humanoid a free root and 21 hinges.
DM_CONTROL = ("cheetah.xml", "hopper.xml", "walker.xml", "humanoid.xml")
#: The project's models: one joint each with armature and no actuator (slide, hinge, ball, free), one with two motors.
OWN = (
    "slide_armature.xml",
    "hinge_armature_offset.xml",
    "ball_armature.xml",
    "free_armature.xml",
    "two_motors_armature.xml",
)
CASES = [f"dm_control/{n}" for n in DM_CONTROL] + list(OWN)
#: Round-off of a difference of two mass matrices (or forces) built by the same code: relative to their largest entry.
RTOL = 1e-12


def _path(case: str) -> Path:
    if case.startswith("dm_control/"):
        dm_control = pytest.importorskip("dm_control")
        return Path(dm_control.__file__).parent / "suite" / case.removeprefix("dm_control/")
    return MODELS / case


def _states(model: mujoco.MjModel) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    qpos, qvel = random_states(model, 4, seed=11)
    qacc = np.random.default_rng(12).normal(size=qvel.shape)
    return qpos, qvel, qacc


def _mujoco_route(path: Path, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``mj_fullM`` and ``mj_inverse`` of the file as written minus those of the file with every armature zero."""
    matrices, forces = [], []
    for armature_zero in (False, True):
        spec = mujoco.MjSpec.from_file(str(path))
        if armature_zero:
            for joint in spec.joints:
                joint.armature = 0.0
        m = spec.compile()
        assert armature_zero is not bool(m.dof_armature.any())
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)  # contacts: no force from the pose
        d = mujoco.MjData(m)
        M, tau = np.zeros((len(qpos), m.nv, m.nv)), np.zeros((len(qpos), m.nv))
        for p in range(len(qpos)):
            d.qpos[:], d.qvel[:], d.qacc[:] = qpos[p], qvel[p], qacc[p]
            mujoco.mj_inverse(m, d)  # runs the mass matrix too
            mujoco.mj_fullM(m, d, M[p])
            tau[p] = d.qfrc_inverse
        matrices.append(M)
        forces.append(tau)
    return matrices[0] - matrices[1], forces[0] - forces[1]


def _drake_route(drake, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drake's ``CalcMassMatrix`` and ``CalcInverseDynamics`` with rotor inertias as loaded minus with them zero."""
    from pydrake.multibody.tree import MultibodyForces

    plant = drake.plant
    as_loaded, rotorless = plant.CreateDefaultContext(), plant.CreateDefaultContext()
    for index in plant.GetJointActuatorIndices():
        plant.get_joint_actuator(index).SetRotorInertia(rotorless, 0.0)
    q, v = drake.state_map.to_drake(qpos, qvel)
    _, a = drake.state_map.to_drake(qpos, qacc)
    M, tau = np.zeros((2, len(q), plant.num_velocities(), plant.num_velocities())), np.zeros((2, *v.shape))
    for k, context in enumerate((as_loaded, rotorless)):
        for p in range(len(q)):
            plant.SetPositions(context, q[p])
            plant.SetVelocities(context, v[p])
            M[k, p] = plant.CalcMassMatrix(context)
            tau[k, p] = plant.CalcInverseDynamics(context, a[p], MultibodyForces(plant))
    return (
        drake.state_map.matrix_to_canonical(qpos, M[0] - M[1]),
        drake.state_map.force_to_canonical(qpos, tau[0] - tau[1]),
    )


def _close(got: np.ndarray, expected: np.ndarray, scale: float) -> bool:
    return bool(np.abs(np.asarray(got) - expected).max() <= RTOL * max(scale, 1.0))


@pytest.fixture(scope="module", params=CASES)
def loaded(request: pytest.FixtureRequest):
    path = _path(request.param)
    model = load_model(path, check=False)
    return path, model, _states(model.mujoco.model)


def test_mujoco_armature_parts_are_its_mass_matrix_and_forces_less_the_armature_free_ones(loaded) -> None:
    path, model, (qpos, qvel, qacc) = loaded
    mj = model.mujoco
    expected_M, expected_tau = _mujoco_route(path, qpos, qvel, qacc)
    assert np.abs(expected_M).max() > 0  # every case has armature in MuJoCo
    assert _close(mj.armature_matrix(qpos), expected_M, float(np.abs(mj.mass_matrix(qpos)).max()))
    full = mj.inverse_dynamics(qpos, qvel, qacc)
    assert _close(mj.armature_forces(qpos, qvel, qacc), expected_tau, float(np.abs(full).max()))


def test_drake_armature_parts_are_its_mass_matrix_and_forces_less_the_rotorless_ones(loaded) -> None:
    pytest.importorskip("pydrake", reason="Drake (the optional extra [drake]) is not installed")
    _, model, (qpos, qvel, qacc) = loaded
    drake = model.attach("drake")
    expected_M, expected_tau = _drake_route(drake, qpos, qvel, qacc)
    assert _close(drake.armature_matrix(qpos), expected_M, float(np.abs(drake.mass_matrix(qpos)).max()))
    full = drake.inverse_dynamics(qpos, qvel, qacc)
    assert _close(drake.armature_forces(qpos, qvel, qacc), expected_tau, float(np.abs(full).max()))
    # What Drake holds, against MuJoCo's armature: the same where a motor drives the joint, none where none does.
    mj = model.mujoco.model
    driven = np.zeros(mj.nv, dtype=bool)
    for joint in mj.actuator_trnid[mj.actuator_trntype == mujoco.mjtTrn.mjTRN_JOINT, 0]:
        driven[mj.jnt_dofadr[joint]] = True
    expected = np.where(driven, mj.dof_armature, 0.0)
    assert _close(
        np.diagonal(drake.armature_matrix(qpos), axis1=1, axis2=2), expected[None], float(mj.dof_armature.max())
    )
    names = mujoco_joint_names(mj)
    undriven = sorted({names[int(mj.dof_jntid[i])] for i in np.flatnonzero(~driven & (mj.dof_armature > 0))})
    drake_says = [
        f for f in model.optional_findings if f.engine == "drake" and f.kind in (Kind.IGNORED_CONSTRUCT, Kind.ARMATURE)
    ]
    assert [(f.kind, f.element, sorted(f.values["joints"])) for f in drake_says] == (
        [(Kind.IGNORED_CONSTRUCT, "joint armature", undriven)] if undriven else []
    )
