"""The engines' states as component planes: the same numbers as the (P, B, 3) kernels, and no copy for the formulas."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from koenig_check.engines import load_model
from koenig_check.engines.planes import (
    byte_view,
    cross_planes,
    entry_index,
    gather_planes,
    matrices,
    rotate_constant,
    rotate_planes,
    vectors,
)
from koenig_check.kernels import components, cross, matrix_components, rotate
from koenig_check.run.poses import random_poses

FREE_BALL_HINGE = Path(__file__).resolve().parents[1] / "data" / "free_ball_hinge.xml"
MODELS = Path(__file__).resolve().parents[2] / "models"
CASES = [FREE_BALL_HINGE, MODELS / "serial7.urdf", MODELS / "armature_chain.xml", "ur5", "a1"]


#: Row layouts of the segments in an engine's array: scattered, consecutive (a strided view per component), one
#: row, every segment on one row (a root shared by all), consecutive but descending, none.
ROW_LAYOUTS = {
    "scattered": [3, 0, 4],
    "consecutive": [1, 2, 3, 4],
    "one row": [2],
    "one row repeated": [2, 2, 2],
    "descending": [4, 3, 2],
    "none": [],
}


@pytest.mark.parametrize("rows", ROW_LAYOUTS.values(), ids=ROW_LAYOUTS.keys())
@pytest.mark.parametrize("entries", [[2, 0, 3], [0, 1, 2, 3]], ids=["some entries, reordered", "every entry"])
def test_gather_planes_picks_every_pose_entry_by_entry(rng: np.random.Generator, rows, entries) -> None:
    raw = rng.standard_normal((7, 5 * 4))  # 7 poses, 5 rows of 4 entries
    planes = gather_planes(raw, entry_index(np.array(rows, dtype=int), 4, entries))
    assert planes.shape == (len(entries), 7, len(rows)) and planes.flags.c_contiguous
    for c, e in enumerate(entries):
        for b, r in enumerate(rows):
            np.testing.assert_array_equal(planes[c, :, b], raw[:, 4 * r + e])


def test_gather_planes_reads_any_index_np_take_reads(rng: np.random.Generator) -> None:
    raw = rng.standard_normal((4, 12))
    for index in (np.array([[9, 6, 3]], dtype=np.uint64), np.array([[-3, -2, -1]]), np.array([[11, 11]])):
        expected = np.swapaxes(np.take(raw, index.astype(np.intp), axis=1), 0, 1)
        np.testing.assert_array_equal(gather_planes(raw, index), expected)
    with pytest.raises(IndexError):
        gather_planes(raw, np.array([[10, 11, 12]]))


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_a_batch_of_no_poses_gives_empty_states(engine: str) -> None:
    eng = getattr(load_model("ur5"), engine)
    states = eng.segment_states(np.zeros((0, eng.nq)), np.zeros((0, eng.nv)))
    assert states.n_poses == 0 and states.com.shape == (0, len(eng.segment_names), 3)
    _, velocities, rigid, armature = eng.sweep(np.zeros((0, eng.nq)), np.zeros((0, eng.nv)))
    assert velocities is None and rigid.shape == armature.shape == (0,)


def test_byte_view_writes_through_and_refuses_a_strided_array() -> None:
    out = np.zeros((3, 4))
    view = byte_view(out)
    assert len(view) == out.nbytes
    view[32:64] = byte_view(np.arange(4.0))  # row 1, as the engine loops copy a pose's row
    np.testing.assert_array_equal(out, [[0, 0, 0, 0], [0, 1, 2, 3], [0, 0, 0, 0]])
    with pytest.raises(ValueError, match=r"shape \(3, 2\) is not C-contiguous"):
        byte_view(out[:, ::2])
    assert len(byte_view(np.empty((0, 4)))) == 0  # no poses: nothing to copy


def test_plane_kernels_give_the_numbers_of_rotate_and_cross_bit_for_bit(rng: np.random.Generator) -> None:
    P, B = 50, 7
    R = rng.standard_normal((P, B, 3, 3))
    v, w = rng.standard_normal((P, B, 3)), rng.standard_normal((P, B, 3))
    constant = rng.standard_normal((B, 3))
    R_planes = np.ascontiguousarray(np.moveaxis(R.reshape(P, B, 9), -1, 0))
    v_planes, w_planes = components(v), components(w)
    np.testing.assert_array_equal(vectors(rotate_constant(R_planes, constant)), rotate(R, constant))
    np.testing.assert_array_equal(vectors(rotate_planes(R_planes, v_planes)), rotate(R, v))
    np.testing.assert_array_equal(vectors(cross_planes(w_planes, v_planes)), cross(w, v))
    np.testing.assert_array_equal(matrices(R_planes), R)


def _mujoco_states_pose_by_pose(eng, qpos: np.ndarray, qvel: np.ndarray) -> dict[str, np.ndarray]:
    """MuJoCo's segment states read from MjData one pose at a time, with the (P, B, 3) kernels (the former route)."""
    m, d = eng.model, mujoco.MjData(eng.model)
    body, root = eng._seg_body, eng._seg_root
    out: dict[str, list] = {k: [] for k in ("com", "v_com", "rotation", "omega", "pole", "v_pole")}
    for qpos_p, qvel_p in zip(qpos, qvel, strict=True):
        d.qpos[:], d.qvel[:] = qpos_p, qvel_p
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_comVel(m, d)
        R = d.xmat[body].reshape(-1, 3, 3).copy()
        x, ref, w, v = d.xpos[body].copy(), d.subtree_com[root].copy(), d.cvel[body, :3].copy(), d.cvel[body, 3:]
        com, pole = x + rotate(R, eng._com_local), x + rotate(R, eng._anchor_local)
        out["com"].append(com)
        out["v_com"].append(v + cross(w, com - ref))
        out["rotation"].append(R)
        out["omega"].append(w)
        out["pole"].append(pole)
        out["v_pole"].append(v + cross(w, pole - ref))
    return {k: np.array(a) for k, a in out.items()}


@pytest.mark.parametrize("model", CASES, ids=lambda m: Path(str(m)).name)
def test_mujoco_states_from_planes_equal_mjdata_pose_by_pose(model) -> None:
    eng = load_model(model).mujoco
    poses = random_poses(eng.model, 40, seed=3)
    states, _, _, _ = eng.sweep(poses.qpos, poses.qvel)
    expected = _mujoco_states_pose_by_pose(eng, poses.qpos, poses.qvel)
    for name, value in expected.items():
        np.testing.assert_array_equal(getattr(states, name), value, err_msg=name)


@pytest.mark.parametrize("engine", ["mujoco", "pinocchio"])
def test_the_formulas_read_the_sweeps_planes_without_a_copy(engine: str) -> None:
    pair = load_model("ur5")
    poses = random_poses(pair.mujoco.model, 30, seed=2)
    states, _, _, _ = getattr(pair, engine).sweep(poses.qpos, poses.qvel)
    R = states.rotation
    assert np.shares_memory(matrix_components(R), R), "the rotations were copied into planes again"
    for name in ("com", "v_com", "omega", "pole", "v_pole"):
        value = getattr(states, name)
        assert np.shares_memory(components(value), value), f"{name} was copied into planes again"
