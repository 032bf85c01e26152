"""The dynamics each energy formula implies, M(q) and Q*, against MuJoCo, Pinocchio and Drake on a few robots.

For every formula, ``koenig_check.dynamics`` derives M = ∂²T/∂q̇² (polarization) and Q* = −(d/dt ∂T/∂q̇ − ∂T/∂q)
(Lagrange's equations by finite differences on the configuration manifold) from the formula's energy on one
engine's segment states, and compares them with that engine's mass matrix and inverse dynamics (armature out,
gravity and passive forces off).  The table gives, per model and formula, the largest per-pose relative error
(Frobenius norm for M, Euclidean for Q*) on MuJoCo's states against MuJoCo, on Pinocchio's states against
Pinocchio, and on MuJoCo's states against Drake where Drake loads the file.

Each model's rows depend only on the model and N: poses are drawn with a seed derived from the model's name.

Usage::

    python comparisons/inertia_forces.py                                  # writes inertia_forces.md / .png
    python comparisons/inertia_forces.py --models koenig-check:gimbal.xml --poses 3 --out DIR
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from common import HERE, display_name, model_seed, progress, project_corpus, scrub, table

from koenig_check.roundoff import fmt

#: The robots of the table: small to mid-size, fixed and floating, as named by ``koenig-check models``.
ROBOTS = ("ur5", "panda", "solo12")
#: Formulas in the order of the table (path-dependent and plane-only variants have no M or Q*: listed as refused).
FORMULA_ORDER = (
    "exact",
    "koenig_world",
    "koenig_principal",
    "alyushin_current",
    "alyushin_paper:rotvec",
    "alyushin_paper:euler_xyz",
    "alyushin_pole:current",
    "alyushin_pole:paper:rotvec",
    "alyushin_pole:paper:euler_xyz",
    "point_masses",
)
ENGINE_COLUMNS = (("lagrange@mujoco", "mujoco"), ("lagrange@pinocchio", "pinocchio"), ("lagrange@mujoco", "drake"))


@dataclass
class ModelDynamics:
    """One model's rows: per formula, the max relative error of M and Q* per engine column (None: not run)."""

    model: str
    n_poses: int
    errors: dict[tuple[str, str, str], float]  # (formula, column engine, quantity) -> max rel error
    refusals: dict[str, str]
    engines: tuple[str, ...]


def targets() -> list[tuple[str, str]]:
    """(label, name or path) of every model of the table: the gimbal, serial7, then the robots."""
    by_name = {p.name: p for p in project_corpus()}
    out = [(display_name(by_name[n]), str(by_name[n])) for n in ("gimbal.xml", "serial7.xml")]
    from koenig_check.sources.catalogue import resolve_model

    out += [(display_name(resolve_model(r).path), r) for r in ROBOTS]
    return out


def model_dynamics(label: str, target: str, n_poses: int) -> ModelDynamics:
    """Run ``koenig_check.dynamics`` on one model (with Drake when it is installed) and keep the maxima."""
    import koenig_check
    from koenig_check.engines.drake.loader import drake_available

    engines = ("mujoco", "pinocchio", "drake") if drake_available() else ("mujoco", "pinocchio")
    result = koenig_check.dynamics(
        target, n_poses=n_poses, seed=model_seed(label), formulas=list(FORMULA_ORDER), engines=engines
    )
    errors = {}
    for e in result.errors:
        for route, engine in ENGINE_COLUMNS:
            if e.route == route and e.engine == engine:
                errors[(e.formula, engine, e.quantity)] = float(np.max(e.rel_error))
    ran = tuple(sorted({k[1] for k in errors}, key=["mujoco", "pinocchio", "drake"].index))
    return ModelDynamics(label, n_poses, errors, {k: scrub(v) for k, v in result.refusals.items()}, ran)


#: Q* comes from central differences chosen for about 1e-7 relative accuracy (measured: 7e-10 at worst on
#: exact formulas); below this floor a Q* error is the differences' own error, printed as such.
Q_FLOOR = 1e-8


def _fmt(x: float | None, quantity: str = "M") -> str:
    if x is None:
        return "—"
    if quantity == "Q*" and x < Q_FLOOR:
        return f"< {Q_FLOOR:.0e}"
    return fmt(x, ".1e")  # round-off (below 1e-12) printed as 0


HEADER = [
    "model",
    "formula",
    "M vs MuJoCo",
    "M vs Pinocchio",
    "M vs Drake",
    "Q* vs MuJoCo",
    "Q* vs Pinocchio",
    "Q* vs Drake",
]


def rows_of(md: ModelDynamics) -> list[list[object]]:
    """The table rows of one model (max relative errors, two significant digits)."""
    out = []
    for f in FORMULA_ORDER:
        if f in md.refusals:
            out.append([md.model, f"`{f}`", f"refused: {md.refusals[f]}", "", "", "", "", ""])
            continue
        cells = [_fmt(md.errors.get((f, e, q)), q) for q in ("M", "Q*") for _, e in ENGINE_COLUMNS]
        out.append([md.model, f"`{f}`", *cells])
    return out


def markdown(results: list[ModelDynamics], n_poses: int, versions: str) -> str:
    """The whole ``inertia_forces.md``."""
    rows = [r for md in results for r in rows_of(md)]
    return "\n".join(
        [
            "# Inertia forces: M(q) and Q* implied by each formula, against the engines",
            "",
            f"{n_poses} seeded random poses, velocities and accelerations per model (seed derived from the model's "
            f"name); largest per-pose relative error, ‖X − X_engine‖ / ‖X_engine‖ (Frobenius for M, Euclidean for "
            f"Q*). 'vs MuJoCo': the formula on MuJoCo's segment states against MuJoCo's `mj_fullM` and "
            f"`mj_rne`; 'vs Pinocchio': on Pinocchio's states against `crba` and `rnea`; 'vs Drake': on MuJoCo's "
            f"states against Drake's `CalcMassMatrix` and `CalcInverseDynamics` (armature and reflected inertia out "
            f"on every side). {versions}. Produced by `python comparisons/inertia_forces.py`.",
            "",
            *table(HEADER, rows, "llrrrrrr"),
            "",
            "![inertia forces](inertia_forces.png)",
            "",
        ]
    )


def figure(results: list[ModelDynamics], out: Path) -> None:
    """Per model, M and Q* errors against MuJoCo per formula (log scale)."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    x = np.arange(len(FORMULA_ORDER))
    width = 0.8 / max(len(results), 1)
    for ax, q in zip(axes, ("M", "Q*"), strict=True):
        for k, md in enumerate(results):
            vals = [max(md.errors.get((f, "mujoco", q), np.nan), 1e-17) for f in FORMULA_ORDER]
            ax.bar(x + k * width, vals, width, label=md.model.split(": ", 1)[-1])
        ax.set_yscale("log")
        ax.set_xticks(x + 0.4 - width / 2, FORMULA_ORDER, rotation=60, ha="right", fontsize=7)
        ax.set_title(f"{q} implied by the formula vs MuJoCo (max rel. error)")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def versions() -> str:
    from engine_parity import versions as v

    return v()


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", help="comma-separated names as in the table (default: all)")
    parser.add_argument("--poses", type=int, default=10)
    parser.add_argument("--out", type=Path, default=HERE)
    args = parser.parse_args(argv)
    chosen = targets()
    if args.models:
        wanted = [n.strip().replace(" ", "") for n in args.models.split(",") if n.strip()]
        by_label = {label.replace(" ", ""): (label, t) for label, t in chosen}
        unknown = [n for n in wanted if n not in by_label]
        if unknown:
            raise SystemExit(f"inertia_forces: unknown models {unknown} (names as in the table)")
        chosen = [by_label[n] for n in wanted]
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    os.chdir(tempfile.mkdtemp(prefix="inertia_forces_"))
    start = time.perf_counter()
    results = []
    for label, target in chosen:
        t0 = time.perf_counter()
        results.append(model_dynamics(label, target, args.poses))
        progress(f"{label}: {time.perf_counter() - t0:.1f} s")
    (out / "inertia_forces.md").write_text(markdown(results, args.poses, versions()), encoding="utf-8")
    figure(results, out / "inertia_forces.png")
    progress(f"written {out / 'inertia_forces.md'} ({time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main()
