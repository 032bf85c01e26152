"""The rigid-body / armature split of each engine's energy, on one-dof bodies attached to the world.

MuJoCo precomputes the mass-matrix diagonal of "simple" dofs (a slide, or a hinge whose body's
centre of mass is on the axis, on a body attached to the world) at compile time, armature
included; the split must still put the armature in the armature term.  Expected values are hand
computations: ½ m v² for a slide, ½ (I_axis + m d²) ω² for a hinge, ½ a q̇² for the armature.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from koenig_check.engines import load_model

MODELS = Path(__file__).parent / "models"

#: file, whether MuJoCo treats its dof as simple, hand-computed rigid "inertia" along the dof, armature.
CASES = [
    ("slide_armature.xml", True, 2.0, 0.1),  # m
    ("hinge_armature.xml", True, 0.4, 0.05),  # I_zz
    ("hinge_armature_offset.xml", False, 0.4 + 1.0 * 0.2**2, 0.05),  # I_zz + m d²
]


@pytest.mark.parametrize(("name", "simple", "inertia", "armature"), CASES, ids=[c[0] for c in CASES])
@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_rigid_and_armature_energy_of_a_world_attached_joint(name, simple, inertia, armature, engine) -> None:
    pair = load_model(MODELS / name)
    assert bool(pair.mujoco.model.dof_simplenum[0]) is simple  # the case this file is about
    rng = np.random.default_rng(8)
    qpos = rng.uniform(-1.0, 1.0, size=(5, 1))
    qvel = rng.normal(scale=2.0, size=(5, 1))
    parts = getattr(pair, engine).kinetic_energy(qpos, qvel)
    v2 = qvel[:, 0] ** 2
    np.testing.assert_allclose(parts.rigid, 0.5 * inertia * v2, rtol=1e-12)
    np.testing.assert_allclose(parts.armature, 0.5 * armature * v2, rtol=1e-12)
    np.testing.assert_allclose(parts.reported, 0.5 * (inertia + armature) * v2, rtol=1e-12)


@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_engines_agree_on_a_world_attached_joint_with_armature(name) -> None:
    from koenig_check.api import compare

    check = compare(MODELS / name, n_poses=5, seed=3)
    assert check.ok, check.reason()
