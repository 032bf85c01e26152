"""Engine parity over every public model set installed: example-robot-data, dm_control, the project's models.

For every model file, with a fixed and with a floating base: whether MuJoCo, Pinocchio and Drake load it (and the
engine's whole reason when not), the root causes the import-parity report names, the energy parity (largest
relative difference of the rigid-body kinetic energy over N seeded random poses, MuJoCo vs Pinocchio and Drake vs
MuJoCo), and each engine's consistency with itself (its kinetic-energy function against ½ q̇ᵀ M(q) q̇ from its own
mass matrix, e.g. Pinocchio's ``computeKineticEnergy`` against ``crba``).  Where MuJoCo refuses an inertia the
model is loaded with ``--repair-inertia`` and the row says so.

Each row depends only on its model, its base and N: poses are drawn with a seed derived from the row's label.

Usage::

    python comparisons/engine_parity.py                     # everything, writes engine_parity.md / .png
    python comparisons/engine_parity.py --models koenig-check:gimbal.xml,dm_control:suite/cartpole.xml \\
        --poses 5 --out DIR                                  # a subset (names as printed in the table)
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np
from common import (
    HERE,
    display_name,
    dm_control_corpus,
    erd_corpus,
    model_seed,
    progress,
    project_corpus,
    scrub,
    table,
)

#: Relative tolerance of the agree/disagree verdict (the tool's default).
RTOL = 1e-9
CORPORA = ("example-robot-data", "dm_control", "koenig-check")


@dataclass
class Row:
    """One model file with one base: what each engine did with it."""

    model: str
    base: str
    mujoco: str = ""
    pinocchio: str = ""
    drake: str = ""
    causes: str = ""
    parity: float | None = None
    drake_parity: float | None = None
    self_consistency: dict[str, float] = field(default_factory=dict)
    verdict: str = ""
    seconds: float = 0.0

    @property
    def corpus(self) -> str:
        return self.model.split(":", 1)[0]


def _fmt(x: float | None) -> str:
    return "—" if x is None else f"{x:.1e}"


def _refusal(err: BaseException) -> str:
    from koenig_check.api import one_line

    return "refused: " + scrub(one_line(err))


def check_one(task: tuple[str, bool, int, bool]) -> Row:
    """One row; an unexpected exception becomes the row's verdict instead of ending the run (see :func:`_check`)."""
    try:
        return _check(task)
    except Exception as err:
        return Row(display_name(task[0]), "floating" if task[1] else "fixed", verdict="error: " + _refusal(err)[9:])


def _check(task: tuple[str, bool, int, bool]) -> Row:
    """Load one model file with one base into every engine and compare their energies.

    Parameters
    ----------
    task : (path, floating, n_poses, use_drake)

    Returns
    -------
    Row
    """
    from koenig_check.diagnosis.import_parity import import_parity
    from koenig_check.diagnosis.reason import disagreement_cause
    from koenig_check.engines import load_model
    from koenig_check.engines.drake.building import load_drake_engine
    from koenig_check.engines.drake.loader import drake_available
    from koenig_check.engines.errors import InertiaError, NotFloatableError
    from koenig_check.engines.mujoco.loader import ROOT_JOINT_NAME, load_mujoco, root_free_joint
    from koenig_check.engines.pinocchio.loader import load_pinocchio
    from koenig_check.engines.sampling import random_states
    from koenig_check.modelfile.validate import preflight
    from koenig_check.run.stats import relative_error
    from koenig_check.sources.catalogue import resolve_model

    path, floating, n_poses, use_drake = task
    start = time.perf_counter()
    row = Row(display_name(path), "floating" if floating else "fixed")
    try:
        source = resolve_model(path)
        preflight(source.path)
    except Exception as err:  # the file itself is refused: every engine column says so
        row.mujoco = row.pinocchio = _refusal(err)
        row.verdict = "refused"
        return row
    repair, mj_model, not_floatable = False, None, False
    try:
        mj_model, _, _ = load_mujoco(source, floating=floating)
        row.mujoco = "loads"
    except InertiaError as err:
        try:
            mj_model, _, _ = load_mujoco(source, floating=floating, repair_inertia=True)
            repair = True
            row.mujoco = f"loads with --repair-inertia (without: {_refusal(err)})"
        except Exception as err2:
            row.mujoco = _refusal(err2)
    except Exception as err:
        row.mujoco = _refusal(err)
        not_floatable = isinstance(err, NotFloatableError)
    root = root_free_joint(mj_model) if mj_model is not None else (ROOT_JOINT_NAME if floating else None)
    try:
        load_pinocchio(source, root_joint=root)
        row.pinocchio = "loads"
    except Exception as err:
        row.pinocchio = _refusal(err)
    drake = None
    if not use_drake or not drake_available():
        row.drake = "not run"
    elif mj_model is None:
        row.drake = "not tried (its state map needs MuJoCo's model)"
    else:
        try:
            drake = load_drake_engine(source, mj_model)
            row.drake = "loads"
        except Exception as err:
            row.drake = _refusal(err)
    if mj_model is None and floating and not_floatable:
        row.verdict = "not applicable (no single jointless top body to float)"
        row.seconds = time.perf_counter() - start
        return row
    if mj_model is None or not row.pinocchio.startswith("loads"):
        row.verdict = "refused"
        row.seconds = time.perf_counter() - start
        return row
    try:
        pair = load_model(source.path, floating=floating, repair_inertia=repair)
    except Exception as err:  # both engines load the file but cannot be paired (joints, segments)
        row.verdict = "not paired: " + _refusal(err)[len("refused: ") :]
        row.seconds = time.perf_counter() - start
        return row
    qpos, qvel = random_states(pair.mujoco.model, n_poses, seed=model_seed(f"{row.model} {row.base}"))
    energies = {name: e.kinetic_energy(qpos, qvel) for name, e in pair.engines.items()}
    mj, pn = energies["mujoco"].rigid, energies["pinocchio"].rigid
    row.parity = float(np.abs(relative_error(pn, mj)).max())
    arm = np.abs(energies["pinocchio"].armature - energies["mujoco"].armature)
    arm_rel = float((arm / np.maximum(np.abs(mj) + energies["mujoco"].armature, 1e-300)).max())
    engines = list(pair.engines.values())
    if drake is not None:
        try:
            dr = drake.kinetic_energy(qpos, qvel).rigid
            row.drake_parity = float(np.abs(relative_error(dr, mj)).max())
            engines.append(drake)
        except Exception as err:
            row.drake = "loads; " + _refusal(err).replace("refused", "fails on the poses")
    for engine in engines:
        reported = engine.kinetic_energy(qpos, qvel).reported
        quad = 0.5 * np.einsum("pi,pij,pj->p", qvel, engine.mass_matrix(qpos), qvel)
        row.self_consistency[engine.engine] = float(np.abs(relative_error(reported, quad)).max())
    agree = row.parity <= RTOL and arm_rel <= RTOL
    try:
        report = import_parity(pair)
    except Exception as err:  # the parity report itself fails: said in the row, the energies still count
        causes = [f"import-parity report failed: {_refusal(err)[len('refused: ') :]}"]
    else:
        causes = [scrub(c.message()) for c in report.causes if c.affects_energy]
        if not causes and not agree:  # the tool's own choice: a repaired or fused inertia, else the symptoms
            causes = [scrub(disagreement_cause(pair.findings) or report.headline())]
    row.causes = "; ".join(causes)
    row.verdict = "agree" if agree else "disagree"
    if not agree and arm_rel > RTOL:
        row.verdict += f" (armature energy differs by {arm_rel:.1e} relative)"
    if repair:
        row.verdict += " (--repair-inertia)"
    row.seconds = time.perf_counter() - start
    return row


def corpus_paths() -> list[Path]:
    """Every model file of every corpus, in table order."""
    return erd_corpus() + dm_control_corpus() + project_corpus()


def run(paths: list[Path], n_poses: int, jobs: int, use_drake: bool = True) -> list[Row]:
    """Every (model, base) row, in order, computed in ``jobs`` processes."""
    tasks = [(str(p), floating, n_poses, use_drake) for p in paths for floating in (False, True)]
    rows: list[Row] = []
    if jobs <= 1:
        results = map(check_one, tasks)
        for row in results:
            progress(f"{row.model} ({row.base}): {row.verdict[:60]} [{row.seconds:.1f} s]")
            rows.append(row)
        return rows
    with multiprocessing.get_context("spawn").Pool(jobs, maxtasksperchild=8) as pool:
        for row in pool.imap(check_one, tasks):
            progress(f"{row.model} ({row.base}): {row.verdict[:60]} [{row.seconds:.1f} s]")
            rows.append(row)
    return rows


def counts(rows: list[Row]) -> list[list[object]]:
    """Per corpus and base: rows, not applicable, both load, agree, disagree, refused or unpaired, Drake."""
    out = []
    for corpus in CORPORA:
        for base in ("fixed", "floating"):
            sel = [r for r in rows if r.corpus == corpus and r.base == base]
            if not sel:
                continue
            agree = sum(r.verdict.startswith("agree") for r in sel)
            disagree = sum(r.verdict.startswith("disagree") for r in sel)
            loads = agree + disagree
            drake = sum(r.drake.startswith("loads") for r in sel)
            drake_agree = sum(r.drake_parity is not None and r.drake_parity <= RTOL for r in sel)
            na = sum(r.verdict.startswith("not applicable") for r in sel)
            out.append([corpus, base, len(sel), na, loads, agree, disagree, len(sel) - loads - na, drake, drake_agree])
    return out


def model_rows(rows: list[Row]) -> list[list[object]]:
    """The per-model table rows (everything a row shows, as printed)."""
    out = []
    for r in rows:
        sc = r.self_consistency
        out.append(
            [
                r.model,
                r.base,
                r.mujoco,
                r.pinocchio,
                r.drake,
                r.causes or "—",
                _fmt(r.parity),
                _fmt(r.drake_parity),
                " / ".join(_fmt(sc.get(e)) for e in ("mujoco", "pinocchio", "drake")),
                r.verdict,
            ]
        )
    return out


MODEL_HEADER = [
    "model",
    "base",
    "MuJoCo",
    "Pinocchio",
    "Drake",
    "root causes (energy)",
    "MuJoCo vs Pinocchio, max rel.",
    "Drake vs MuJoCo, max rel.",
    "self-consistency MuJoCo / Pinocchio / Drake",
    "verdict",
]
COUNT_HEADER = [
    "corpus",
    "base",
    "files",
    "not applicable",
    "both load",
    "agree",
    "disagree",
    "refused or not paired",
    "Drake loads",
    "Drake agrees with MuJoCo",
]


def markdown(rows: list[Row], n_poses: int, versions: str) -> str:
    """The whole ``engine_parity.md``."""
    lines = [
        "# Engine parity: every model file we can install, in MuJoCo, Pinocchio and Drake",
        "",
        f"{n_poses} seeded random poses per row (seed derived from the row's model and base, so a row does not "
        f"depend on the other rows); verdict tolerance {RTOL:g} relative on the rigid-body kinetic energy and on the "
        f"armature energy. {versions}. Produced by `python comparisons/engine_parity.py`.",
        "",
        "Columns: load status in each engine (the engine's whole reason when it refuses; MuJoCo refusing an inertia "
        "is retried with `--repair-inertia`, and the row says so), the root causes the import-parity report names "
        "(those that change the energy; otherwise its headline when the energies differ), the largest relative "
        "difference of the rigid-body energy, and each engine's kinetic-energy function against ½ q̇ᵀ M(q) q̇ from "
        "its own mass matrix (MuJoCo `mj_energyVel` vs `mj_fullM`, Pinocchio `computeKineticEnergy` vs `crba`, "
        "Drake `CalcKineticEnergy` vs `CalcMassMatrix`).",
        "",
        "## Counts",
        "",
        *table(COUNT_HEADER, counts(rows), "llrrrrrrrr"),
        "",
        "![engine parity](engine_parity.png)",
        "",
        "## Model by model",
        "",
        *table(MODEL_HEADER, model_rows(rows), "llllllrrrl"),
        "",
    ]
    return "\n".join(lines)


def figure(rows: list[Row], out: Path) -> None:
    """Max relative energy difference per row (log scale), one colour per corpus."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(10, 4.5))
    floor = 1e-17
    for k, corpus in enumerate(CORPORA):
        sel = [(i, r) for i, r in enumerate(rows) if r.corpus == corpus and r.parity is not None]
        if sel:
            ax.scatter(
                [i for i, _ in sel],
                [max(r.parity, floor) for _, r in sel],
                s=12,
                label=f"{corpus}: MuJoCo vs Pinocchio",
            )
        dsel = [(i, r) for i, r in enumerate(rows) if r.corpus == corpus and r.drake_parity is not None]
        if dsel:
            ax.scatter(
                [i for i, _ in dsel],
                [max(r.drake_parity, floor) for _, r in dsel],
                s=12,
                marker="x",
                color=f"C{k}",
                alpha=0.6,
                label=f"{corpus}: Drake vs MuJoCo",
            )
    ax.axhline(RTOL, color="k", lw=0.8, ls="--", label=f"tolerance {RTOL:g}")
    ax.set_yscale("log")
    ax.set_xlabel("row (model × base, table order)")
    ax.set_ylabel("max relative difference, rigid-body T")
    ax.set_title("Engine parity over N seeded poses (refused rows not shown)")
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def versions() -> str:
    import platform

    import mujoco
    import pinocchio

    from koenig_check.engines.drake.loader import drake_available, drake_version

    drake = f", Drake {drake_version()}" if drake_available() else ", Drake not installed"
    return f"MuJoCo {mujoco.__version__}, Pinocchio {pinocchio.__version__}{drake}, Python {platform.python_version()}"


def select(names: str | None) -> list[Path]:
    """The corpus, or the models named as in the table (``dm_control: suite/cartpole.xml``; spaces optional)."""
    paths = corpus_paths()
    if not names:
        return paths
    by_name = {display_name(p).replace(" ", ""): p for p in paths}
    wanted = [n.strip().replace(" ", "") for n in names.split(",") if n.strip()]
    unknown = [n for n in wanted if n not in by_name]
    if unknown:
        raise SystemExit(f"engine_parity: unknown models {unknown} (names as in the table's model column)")
    return [by_name[n] for n in wanted]


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", help="comma-separated names as in the table (default: every corpus)")
    parser.add_argument("--poses", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-drake", action="store_true", help="leave Drake out")
    parser.add_argument("--out", type=Path, default=HERE, help="directory for engine_parity.md and .png")
    args = parser.parse_args(argv)
    paths = select(args.models)
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    os.chdir(tempfile.mkdtemp(prefix="engine_parity_"))  # engines' log files land here, not in the tree
    start = time.perf_counter()
    rows = run(paths, args.poses, args.jobs, use_drake=not args.no_drake)
    (out / "engine_parity.md").write_text(markdown(rows, args.poses, versions()), encoding="utf-8")
    (out / "engine_parity.json").write_text(
        __import__("json").dumps([{k: v for k, v in asdict(r).items() if k != "seconds"} for r in rows], indent=1),
        encoding="utf-8",
    )
    figure(rows, out / "engine_parity.png")
    progress(f"written {out / 'engine_parity.md'} ({len(rows)} rows, {time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main()
