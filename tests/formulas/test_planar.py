from __future__ import annotations

import numpy as np
import pytest

from koenig_check.formulas import FORMULAS
from koenig_check.formulas.analytic import random_physical_inertia, random_rotations, rigid_states
from koenig_check.formulas.planar import NotPlaneParallelError, planar


def _plane_motion(rng: np.random.Generator, normal: np.ndarray, P: int = 20, B: int = 3):
    n = normal / np.linalg.norm(normal)
    rates = rng.normal(size=(P, B))
    v = rng.normal(size=(P, B, 3))
    v -= np.einsum("pbi,i->pb", v, n)[..., None] * n
    # Principal axis of each body along n, so the motion stays plane-parallel.
    return rigid_states(
        mass=rng.uniform(0.5, 2, size=B),
        inertia_body=random_physical_inertia(rng, B),
        rotation=random_rotations(rng, (P, B)),
        omega=rates[..., None] * n,
        v_com=v,
    )


@pytest.mark.parametrize("normal", [[0, 0, 1.0], [0, 1.0, 0], [0.3, -0.4, 0.866]])
def test_planar_equals_exact_in_plane_parallel_motion(rng: np.random.Generator, normal: list[float]) -> None:
    states = _plane_motion(rng, np.array(normal))
    np.testing.assert_allclose(planar(states), FORMULAS["exact"](states), rtol=1e-12)
    np.testing.assert_allclose(planar(states, normal=np.array(normal)), FORMULAS["exact"](states), rtol=1e-12)


def test_planar_refuses_rotation_off_the_normal(rng: np.random.Generator) -> None:
    states = _plane_motion(rng, np.array([0, 0, 1.0]))
    tilted = states.omega.copy()
    tilted[7, 1, 0] += 1e-3
    with pytest.raises(NotPlaneParallelError, match=r"segment 'segment1' at pose 7 .*angular velocity"):
        planar(states.with_motion(omega=tilted))


def test_planar_refuses_out_of_plane_velocity(rng: np.random.Generator) -> None:
    states = _plane_motion(rng, np.array([0, 0, 1.0]))
    v = states.v_com.copy()
    v[3, 2, 2] = 0.5
    with pytest.raises(NotPlaneParallelError, match=r"segment 'segment2' at pose 3 .*out of the plane"):
        planar(states.with_motion(v_com=v), normal=np.array([0, 0, 1.0]))


def test_planar_rejects_bad_normal(rng: np.random.Generator) -> None:
    with pytest.raises(ValueError, match="not a finite non-zero vector"):
        planar(_plane_motion(rng, np.array([0, 0, 1.0])), normal=np.zeros(3))
