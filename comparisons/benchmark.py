"""Throughput of the full cross-check as a ratio against the bare engine loop, measured in the same run.

The bare loop is what any energy check must call at least: per pose, MuJoCo's
``mj_kinematics``, ``mj_comPos``, ``mj_comVel``, ``mj_makeM``, ``mj_energyVel``, and Pinocchio's
``forwardKinematics`` and ``computeKineticEnergy``.  The cross-check is everything
``koenig-check compare`` does for a model once it is loaded: segment states, energies and point
velocities from both engines (``run_engine``) and every formula on both engines' states with tidy
records (``compare_runs``).  Each timing is the best of ``--repeat`` runs (the machines are shared
and noisy); the ratio, not the seconds, is the result.

Usage: python comparisons/benchmark.py [--poses 200] [--repeat 5] [--out comparisons/benchmark.md]
"""

from __future__ import annotations

import argparse
import platform
import time
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin

from koenig_check import grid
from koenig_check.demo import builtin_models
from koenig_check.engines import load_model
from koenig_check.poses import random_poses

ROBOTS = ["ur5", "panda", "talos"]


def best_of(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def bare_loop(pair, qpos: np.ndarray, qvel: np.ndarray) -> None:
    m = pair.mujoco.model
    d = mujoco.MjData(m)
    m.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    pm = pair.pinocchio.model
    pd = pm.createData()
    q_pin, v_pin = pair.state_map.to_pinocchio(qpos, qvel)
    for p in range(qpos.shape[0]):
        d.qpos[:], d.qvel[:] = qpos[p], qvel[p]
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_comVel(m, d)
        mujoco.mj_makeM(m, d)
        mujoco.mj_energyVel(m, d)
        pin.forwardKinematics(pm, pd, q_pin[p], v_pin[p])
        pin.computeKineticEnergy(pm, pd)


def cross_check(pair, poses) -> None:
    runs = {"mujoco": grid.run_engine(pair.mujoco, poses), "pinocchio": grid.run_engine(pair.pinocchio, poses)}
    grid.compare_runs("bench", poses, runs)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--poses", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--out", type=Path, default=Path(__file__).with_name("benchmark.md"))
    args = parser.parse_args()
    rows = []
    targets = [(p.name, p) for p in builtin_models() if p.suffix == ".xml"] + [(r, r) for r in ROBOTS]
    for label, target in targets:
        pair = load_model(target)
        poses = random_poses(pair.mujoco.model, args.poses, seed=0)
        bare = best_of(lambda pair=pair, poses=poses: bare_loop(pair, poses.qpos, poses.qvel), args.repeat)
        full = best_of(lambda pair=pair, poses=poses: cross_check(pair, poses), args.repeat)
        extract = best_of(
            lambda pair=pair, poses=poses: (
                pair.mujoco.segment_states(poses.qpos, poses.qvel),
                pair.pinocchio.segment_states(poses.qpos, poses.qvel),
            ),
            args.repeat,
        )
        rows.append((label, pair.mujoco.nv, len(pair.mujoco.segment_names), bare, extract, full))
        print(f"{label:22s} bare {bare * 1e3:8.2f} ms  states {extract / bare:5.1f}x  full {full / bare:5.1f}x")
    lines = [
        "# Benchmark: the cross-check against the bare engine loop",
        "",
        f"{args.poses} random poses per model, best of {args.repeat} runs, Python {platform.python_version()}, "
        f"MuJoCo {mujoco.__version__}, Pinocchio {pin.__version__}, {platform.machine()}.",
        "Ratios are the result; the milliseconds depend on the (shared) machine.",
        "",
        "| model | nv | segments | bare engine loop (ms) | segment states, both engines (× bare) | full cross-check, "
        "all formulas and records (× bare) |",
        "| --- | ---: | ---: | ---: | ---: | ---: |",
    ]
    for label, nv, nseg, bare, extract, full in rows:
        lines.append(f"| {label} | {nv} | {nseg} | {bare * 1e3:.2f} | {extract / bare:.1f} | {full / bare:.1f} |")
    args.out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"written {args.out}")


if __name__ == "__main__":
    main()
