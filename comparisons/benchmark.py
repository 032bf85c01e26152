"""Throughput of the cross-check against the bare engine calls it needs, measured in one run, interleaved.

Per model (example-robot-data ``ur5`` and ``talos``) and per repetition, three measurements run one
after the other, each in a fresh Python process (so that each one's peak memory is its own):

(a) bare
    the floor: the bare engine calls the cross-check needs, timed alone. Per pose set the state,
    MuJoCo's ``mj_kinematics`` + ``mj_comPos`` + ``mj_makeM`` + ``mj_energyVel`` and Pinocchio's
    ``computeKineticEnergy``. The tool's own preparation (``load_model``, drawing the seeded poses,
    mapping them to Pinocchio's coordinates) runs first, outside the timed span: it is not the
    engines' cost, and counting it in the floor would make the ratios look better as the tool's
    loading grows;
(b) api
    the full default cross-check through the public API, ``koenig_check.compare(model, n_poses=N)``
    (load, both engines' segment states, every default formula, summaries, engine parity), no file
    output;
(c) report
    the same with the default report written, ``koenig-check compare MODEL --poses N --out DIR``;
(b2) api, jobs=J
    with ``--jobs J``: (b) in J processes (wall clock).

``--engine NAME`` measures an optional engine instead, per pose against its own bare loop:
(d) engine-bare, the engine's own calls as its users make them (``engines/<name>/benchmark.py``'s
``bare_loop``: Newton's batched ``eval_fk`` + ``eval_mass_matrix``; PyBullet's ``resetJointStatesMultiDof`` +
``getLinkStates`` with velocities per pose, the energy summed over its links; iDynTree's ``setRobotState``, each
link's ``getWorldTransform`` and ``getFrameVel``, and ``½ νᵀ M ν`` of ``getFreeFloatingMassMatrix`` per pose), and
(e) engine, the adapter's sweep
(segment states and energy in canonical coordinates, what the cross-check reads per pose); both on a model
already loaded, so that the cost per pose is the result.

Each measurement is timed inside its process after the Python imports, the same for all three
(matplotlib included; their time is reported in a column of its own).  (b) and (c) include loading
the model, drawing the poses and the diagnosis, as a user pays them; (a) is the engine calls alone.
The ratios b/a and c/a are the result; seconds
depend on the shared machine.  Besides the wall clock, each measurement's own CPU time (user +
system, ``time.process_time``) is reported: on a shared machine it is not inflated by the time
the process waits for a core.  (With ``--jobs``, the wall clock only: the work is in the workers.)
Peak memory is the process's own ``ru_maxrss``.  Each figure is the best of ``--repeat``
interleaved repetitions.

Usage::

    python comparisons/benchmark.py [--poses 100000] [--repeat 1] [--jobs 2] [--out comparisons/benchmark.md]
    python comparisons/benchmark.py --smoke       # a few poses, nothing written (run by the test suite)
    python comparisons/benchmark.py --engine newton --poses 10000 --models ur5 talos   # printed, not written
    python comparisons/benchmark.py --engine pybullet --smoke    # (d) and (e) on a few poses (run by the suite)
"""

from __future__ import annotations

import argparse
import json
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROBOTS = ("ur5", "talos")
#: What the floor (a) is, printed with every run.
FLOOR_NOTE = (
    "(a) the floor: the bare engine calls the cross-check needs (MuJoCo mj_kinematics, mj_comPos, mj_makeM, "
    "mj_energyVel; Pinocchio computeKineticEnergy), timed alone: load_model, pose drawing and the state mapping "
    "run outside it. (b) and (c) include loading, drawing and diagnosis."
)
KINDS = ("bare", "api", "report")


def _bare(model: str, n_poses: int) -> tuple[float, float]:
    """The bare engine calls on ``n_poses`` seeded poses: (wall seconds, CPU seconds) of the calls alone."""
    import mujoco
    import pinocchio as pin

    from koenig_check.engines import load_model
    from koenig_check.run.poses import random_poses

    pair = load_model(model)
    poses = random_poses(pair.mujoco.model, n_poses, seed=0)
    m = pair.mujoco.model
    m.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    d = mujoco.MjData(m)
    pm = pair.pinocchio.model
    pd = pm.createData()
    q_pin, v_pin = pair.state_map.to_pinocchio(poses.qpos, poses.qvel)
    start, cpu_start = time.perf_counter(), time.process_time()  # the floor: from here, engine calls only
    for p in range(n_poses):
        d.qpos[:], d.qvel[:] = poses.qpos[p], poses.qvel[p]
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_makeM(m, d)
        mujoco.mj_energyVel(m, d)
        pin.computeKineticEnergy(pm, pd, q_pin[p], v_pin[p])
    return time.perf_counter() - start, time.process_time() - cpu_start


def _api(model: str, n_poses: int, jobs: int) -> None:
    import koenig_check

    options = {"jobs": jobs} if jobs > 1 else {}
    check = koenig_check.compare(model, n_poses=n_poses, seed=0, debug=True, **options)
    if not check.comparisons:
        raise SystemExit(f"{model}: {check.reason()}")


def _report(model: str, n_poses: int) -> None:
    from koenig_check.cli import main

    with tempfile.TemporaryDirectory() as out:
        code = main(["compare", model, "--poses", str(n_poses), "--out", out])
        size = sum(f.stat().st_size for f in Path(out).iterdir())
    print(json.dumps({"exit": code, "report_bytes": size}), file=sys.stderr)


def _engine(kind: str, model: str, n_poses: int, engine: str) -> dict:
    """(d) or (e) for an optional engine: its bare loop or the adapter's sweep, timed after loading."""
    import importlib

    from koenig_check.engines import load_model
    from koenig_check.engines.load_options import LoadOptions
    from koenig_check.run.poses import random_poses

    pair = load_model(model, LoadOptions(engines=("mujoco", "pinocchio", engine)))
    adapter = pair.engine(engine)
    poses = random_poses(pair.mujoco.model, n_poses, seed=0)
    bare = importlib.import_module(f"koenig_check.engines.{engine}.benchmark").bare_loop
    # a first pass, untimed: kernel loads and the engine's batched models (one per batch size) are loading
    adapter.sweep(poses.qpos, poses.qvel)
    bare(adapter, poses.qpos, poses.qvel)
    start, cpu_start = time.perf_counter(), time.process_time()
    if kind == "engine-bare":
        bare(adapter, poses.qpos, poses.qvel)
    else:
        adapter.sweep(poses.qpos, poses.qvel)
    return {"seconds": time.perf_counter() - start, "cpu": time.process_time() - cpu_start}


def run_one(kind: str, model: str, n_poses: int, jobs: int) -> dict:
    """Run one measurement in this process; return seconds and peak memory."""
    import contextlib
    import io

    imports = time.perf_counter()
    import koenig_check.api
    import koenig_check.cli
    import koenig_check.diagnosis.diagnose
    import koenig_check.engines
    import koenig_check.engines.loading  # the engines' modules (SciPy among them): imported, not timed
    import koenig_check.report.figures
    import koenig_check.sources.external  # noqa: F401  (imports are not the measurement; loading the model is)

    start, cpu_start = time.perf_counter(), time.process_time()
    imports = start - imports
    with contextlib.redirect_stdout(io.StringIO()):
        floor = None
        if kind == "bare":
            floor = _bare(model, n_poses)
        elif kind == "api":
            _api(model, n_poses, jobs)
        else:
            _report(model, n_poses)
    seconds, cpu = time.perf_counter() - start, time.process_time() - cpu_start
    if floor is not None:  # the bare engine calls alone: the tool's loading and pose drawing are not the floor
        seconds, cpu = floor
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024  # --jobs workers (Linux: KiB)
    return {"seconds": seconds, "cpu": cpu, "peak_bytes": max(peak_rss(), children), "imports": imports}


def peak_rss() -> int:
    """This process's peak resident memory, bytes (Linux ``VmHWM``: ``ru_maxrss`` carries a parent's over exec)."""
    try:
        status = Path("/proc/self/status").read_text()
        return int(status.split("VmHWM:")[1].split()[0]) * 1024
    except OSError:
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * (1 if sys.platform == "darwin" else 1024)


def measure(kind: str, model: str, n_poses: int, jobs: int = 1) -> dict:
    """Run one measurement in a fresh process."""
    proc = subprocess.run(
        [sys.executable, __file__, "--one", kind, model, str(n_poses), str(jobs)],
        capture_output=True,
        text=True,
        check=False,
    )
    if proc.returncode != 0:
        raise SystemExit(f"benchmark {kind} {model}: failed\n{proc.stderr[-3000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def _measure_engine(kind: str, model: str, n_poses: int, engine: str) -> dict:
    """(d) or (e) in a fresh process."""
    proc = subprocess.run(
        [sys.executable, __file__, "--engine", engine, "--one", kind, model, str(n_poses), "1"],
        capture_output=True,
        text=True,
        check=False,
    )
    if proc.returncode != 0:
        raise SystemExit(f"benchmark {kind} {engine} {model}: failed\n{proc.stderr[-3000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def _table(results: dict, n_poses: int, jobs: int) -> list[str]:
    head = (
        "| model | poses | (a) bare engine calls, poses/s | (b) API, poses/s | (c) with report, poses/s | b/a | c/a "
        "| b/a, CPU time | c/a, CPU time | writing (c−b)/b | writing, CPU time |"
    )
    sep = "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    if jobs > 1:
        head += f" b/a, --jobs {jobs} (wall) |"
        sep += " ---: |"
    head += " peak memory a / b / c (MiB) | Python imports (s, not timed) |"
    sep += " ---: | ---: |"
    lines = [head, sep]
    nan = {"seconds": float("nan"), "cpu": float("nan"), "peak_bytes": float("nan"), "imports": float("nan")}
    for model, r in results.items():
        r = {k: r.get(k, nan) for k in (*KINDS, "jobs")}
        a, b, c = (r[k]["seconds"] for k in KINDS)
        cells = [model, f"{n_poses:,}", f"{n_poses / a:,.0f}", f"{n_poses / b:,.0f}", f"{n_poses / c:,.0f}"]
        a_cpu, b_cpu, c_cpu = (r[k]["cpu"] for k in KINDS)
        cells += [f"{b / a:.2f}", f"{c / a:.2f}", f"{b_cpu / a_cpu:.2f}", f"{c_cpu / a_cpu:.2f}"]
        cells += [f"{(c - b) / b:.0%}", f"{(c_cpu - b_cpu) / b_cpu:.0%}"]
        if jobs > 1:
            cells.append(f"{r['jobs']['seconds'] / a:.2f}")
        cells.append(" / ".join(f"{r[k]['peak_bytes'] / 2**20:,.0f}" for k in KINDS))
        cells.append(f"{r['report']['imports']:.2f}")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--poses", type=int, default=100_000, help="seeded random poses per model (default 10^5)")
    parser.add_argument("--repeat", type=int, default=1, help="interleaved repetitions; the best is kept")
    parser.add_argument("--jobs", type=int, default=1, help="also time the API with this many processes")
    parser.add_argument("--models", nargs="+", default=list(ROBOTS))
    parser.add_argument("--out", type=Path, default=Path(__file__).with_name("benchmark.md"))
    parser.add_argument("--kinds", nargs="+", choices=KINDS, default=list(KINDS), help="measurements to run")
    parser.add_argument("--smoke", action="store_true", help="a few poses, print only (for the test suite)")
    parser.add_argument("--engine", default="", help="an optional engine's cost per pose against its bare loop")
    parser.add_argument("--one", nargs=4, metavar=("KIND", "MODEL", "POSES", "JOBS"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:
        kind, model, n, jobs = args.one
        if kind.startswith("engine"):
            print(json.dumps(_engine(kind, model, int(n), args.engine)))
        else:
            print(json.dumps(run_one(kind, model, int(n), int(jobs))))
        return
    if args.smoke:
        args.poses, args.repeat = 20, 1
    if args.engine:
        for model in args.models:
            r = {k: _measure_engine(k, model, args.poses, args.engine) for k in ("engine-bare", "engine")}
            per = {k: 1e6 * v["cpu"] / args.poses for k, v in r.items()}
            print(
                f"{model}: {args.engine} bare loop {per['engine-bare']:.1f} µs/pose, adapter sweep "
                f"{per['engine']:.1f} µs/pose (CPU), ratio {per['engine'] / per['engine-bare']:.2f}"
            )
        return
    print(FLOOR_NOTE, flush=True)
    results: dict[str, dict] = {}
    for _ in range(args.repeat):
        for model in args.models:
            best = results.setdefault(model, {})
            kinds = [*args.kinds, "jobs"] if args.jobs > 1 else list(args.kinds)
            for kind in kinds:
                r = measure("api" if kind == "jobs" else kind, model, args.poses, args.jobs if kind == "jobs" else 1)
                if kind not in best:
                    best[kind] = r
                else:  # the best wall clock and the best CPU time, each on its own
                    best[kind] = {
                        "seconds": min(r["seconds"], best[kind]["seconds"]),
                        "cpu": min(r["cpu"], best[kind]["cpu"]),
                        "peak_bytes": min(r["peak_bytes"], best[kind]["peak_bytes"]),
                        "imports": min(r["imports"], best[kind]["imports"]),
                    }
                print(
                    f"{model:6s} {kind:6s} {r['seconds']:9.2f} s  {r['cpu']:9.2f} s CPU  "
                    f"{r['peak_bytes'] / 2**20:8.0f} MiB",
                    flush=True,
                )
    lines = _table(results, args.poses, args.jobs)
    print("\n".join(lines))
    if args.smoke:
        return
    import mujoco
    import pinocchio

    doc = [
        "# Benchmark: the cross-check against the bare engine calls it needs",
        "",
        f"Command: `python comparisons/benchmark.py --poses {args.poses} --repeat {args.repeat}"
        + (f" --jobs {args.jobs}" if args.jobs > 1 else "")
        + "`",
        "",
        f"Seeded random poses, best of {args.repeat} interleaved repetition(s), each measurement in a fresh process. "
        "The floor (a) is the bare engine calls the cross-check needs, timed alone: MuJoCo's mj_kinematics, "
        "mj_comPos, mj_makeM and mj_energyVel and Pinocchio's computeKineticEnergy per pose; the tool's loading, "
        "pose drawing and state mapping run before it, outside the timed span. (b) and (c) include loading the "
        "model, drawing the poses and the diagnosis. "
        f"Python {platform.python_version()}, MuJoCo {mujoco.__version__}, "
        f"Pinocchio {pinocchio.__version__}, {platform.machine()}, shared 2-core machine. "
        "(a) bare engine calls, (b) `koenig_check.compare` (default formulas, summaries, parity, records kept as "
        "totals), (c) `koenig-check compare MODEL --out DIR` (report written). Ratios are the result: wall clock, "
        "and the measuring process's own CPU time (user + system), which the other users of the shared machine "
        "disturb less. The writing share (c−b)/b is the cost of the report (records.parquet, summary.md, "
        "report.html, records.json, the figure) against the compute. The same Python imports (koenig_check, "
        "MuJoCo, Pinocchio, SciPy, pyarrow, matplotlib) precede every measurement and are not timed; their time "
        "in the report's process is the last column.",
        "",
        *lines,
        "",
    ]
    args.out.write_text("\n".join(doc), encoding="utf-8")
    print(f"written {args.out}")


if __name__ == "__main__":
    main()
