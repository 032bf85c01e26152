"""The rigid-body / armature split of each engine's energy, on single bodies attached to the world.

MuJoCo precomputes the mass-matrix diagonal of "simple" dofs (a slide, a hinge whose body's centre
of mass is on the axis, a ball or free joint at the centre of mass, on a body attached to the world)
at compile time, armature included; the split must still put the armature in the armature term.
Expected values are hand computations: ½ m v² for a slide, ½ (I_axis + m d²) ω² for a hinge,
½ Σ I_k ω_k² (body frame) for a ball, both for a free body, ½ a q̇² for the armature.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import load_model, random_states

MODELS = Path(__file__).parent / "models"

#: file, whether MuJoCo treats its dofs as simple, hand-computed rigid inertia along each dof (a diagonal
#: matrix in MuJoCo's velocity coordinates: these bodies have their centre of mass at the joint or on its
#: axis, so T = ½ Σ m_k q̇_k²), armature per dof.
CASES = [
    ("slide_armature.xml", True, [2.0], 0.1),  # m
    ("hinge_armature.xml", True, [0.4], 0.05),  # I_zz
    ("hinge_armature_offset.xml", False, [0.4 + 1.0 * 0.2**2], 0.05),  # I_zz + m d²
    ("ball_armature.xml", True, [0.1, 0.2, 0.25], 0.2),  # body-frame ω: I_xx, I_yy, I_zz
    ("free_armature.xml", True, [2.0, 2.0, 2.0, 0.1, 0.2, 0.25], 0.3),  # world v of the COM: m; body ω: I
]


@pytest.mark.parametrize(("name", "simple", "inertia", "armature"), CASES, ids=[c[0] for c in CASES])
@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_rigid_and_armature_energy_of_a_world_attached_joint(name, simple, inertia, armature, engine) -> None:
    pair = load_model(MODELS / name)
    model = pair.mujoco.model
    assert bool(model.dof_simplenum.all()) is simple and bool(model.dof_simplenum.any()) is simple
    qpos, qvel = random_states(model, 5, seed=8, velocity_scale=2.0)
    parts = getattr(pair, engine).kinetic_energy(qpos, qvel)
    rigid = 0.5 * qvel**2 @ np.asarray(inertia)
    arm = 0.5 * armature * np.sum(qvel**2, axis=1)
    np.testing.assert_allclose(parts.rigid, rigid, rtol=1e-12)
    np.testing.assert_allclose(parts.armature, arm, rtol=1e-12)
    np.testing.assert_allclose(parts.reported, rigid + arm, rtol=1e-12)


@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_engines_agree_on_a_world_attached_joint_with_armature(name) -> None:
    from koenig_check.api import compare

    check = compare(MODELS / name, n_poses=5, seed=3)
    assert check.ok, check.reason()
