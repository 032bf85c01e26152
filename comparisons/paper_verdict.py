"""The published verdict: every formula of the paper against MuJoCo and Pinocchio on real robots.

Runs the cross-check on the project's models and on every example-robot-data URDF that both
engines load, and writes ``comparisons/verdict.md``: engine parity per model, then per formula
the largest and median relative error over all models and poses, the fraction of poses where it
over- and under-estimates, and the models on which it agrees with the engines.

Usage: python comparisons/paper_verdict.py [--poses 20] [--seed 0] [--out comparisons/verdict.md]
"""

from __future__ import annotations

import argparse
import platform
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin

from koenig_check import grid
from koenig_check.api import CrossCheck, compare_model, one_line
from koenig_check.demo import FLOATING_MODELS, builtin_models
from koenig_check.engines import InertiaError, NoMovingSegmentError, list_models
from koenig_check.findings import Kind
from koenig_check.formulas import FORMULAS


def targets() -> list[tuple[str, object, bool]]:
    out = [(p.name, p, p.name in FLOATING_MODELS) for p in builtin_models()]
    out += [(s.name, s.path, False) for s in list_models() if s.origin == "example-robot-data"]
    return out


def run(n_poses: int, seed: int) -> CrossCheck:
    check = CrossCheck()
    for label, target, floating in targets():
        options: dict[str, bool] = {}
        while True:
            try:
                comp = compare_model(target, n_poses=n_poses, seed=seed, floating=floating, label=label, **options)
                break
            except InertiaError as err:  # retried with MuJoCo's balanceinertia, labelled
                if options.get("balance_inertia"):
                    comp = err
                    break
                options["balance_inertia"] = True
                label = f"{label} (balanced inertia)"
            except NoMovingSegmentError as err:  # a single body: retried as a free-floating body, labelled
                if floating:
                    comp = err
                    break
                floating = True
                label = f"{label} (floating)"
            except Exception as err:  # noted in the verdict, the others go on
                comp = err
                break
        if isinstance(comp, Exception):
            check.failures.append((label, one_line(comp)))
            print(f"{label:40s} FAILED {one_line(comp)[:100]}")
            continue
        parity = check.add(comp)
        print(f"{label:40s} {'agree' if parity.agrees else 'DISAGREE'}")
    return check


def formula_table(check: CrossCheck) -> list[str]:
    rec = check.records
    own = rec.where(rec.mask(scope="total") & (rec["source"] == rec["reference"]))
    lines = [
        "| formula | equations | max relative error | median | over / under (fraction of poses) | agrees on |",
        "| --- | --- | ---: | ---: | --- | --- |",
    ]
    n_models = len(check.comparisons)
    for name, formula in FORMULAS.items():
        rows = own.where(formula=name)
        if not len(rows):
            continue
        rel = rows["rel_error"]
        signed = grid.relative_error(rows["value"], rows["reference_value"])
        per_model: dict[str, bool] = {}
        for s in check.summaries:
            if s.formula == name and s.source == s.reference:
                per_model[s.model] = per_model.get(s.model, True) and s.agrees
        lines.append(
            f"| `{name}` | {formula.equations} | {rel.max():.2e} | {np.median(rel):.2e} | "
            f"{np.mean(signed > check.rtol):.0%} / {np.mean(signed < -check.rtol):.0%} | "
            f"{sum(per_model.values())} of {len(per_model)} models |"
        )
    lines.append("")
    lines.append(
        f"{n_models} models compared; each row pools both engines (each formula on an engine's states "
        "against that engine's own energy)."
    )
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--poses", type=int, default=20)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path(__file__).with_name("verdict.md"))
    args = parser.parse_args()
    check = run(args.poses, args.seed)
    lines = [
        "# Verdict: Alyushin's correction of Koenig's formula against MuJoCo and Pinocchio",
        "",
        f"{args.poses} seeded random poses per model (seed {args.seed}), tolerance {check.rtol:g}; MuJoCo "
        f"{mujoco.__version__}, Pinocchio {pin.__version__}, Python {platform.python_version()}. "
        "Produced by `python comparisons/paper_verdict.py`.",
        "",
        "## Formulas",
        "",
        *formula_table(check),
        "",
        "## Engines, model by model",
        "",
        "| model | MuJoCo vs Pinocchio (max rel.) | exact vs MuJoCo | exact vs Pinocchio | verdict |",
        "| --- | ---: | ---: | ---: | --- |",
    ]
    for p in check.parities:
        lines.append(
            f"| {p.model} | {p.rigid_max_rel:.1e} | {p.exact_vs_engine['mujoco']:.1e} | "
            f"{p.exact_vs_engine['pinocchio']:.1e} | {'agree' if p.agrees else 'DISAGREE: ' + p.reason} |"
        )
    if check.failures:
        lines += ["", "## Models that could not be compared", ""]
        lines += [f"- {m}: {r}" for m, r in check.failures]
    findings = sorted(
        {
            f.message()
            for c in check.comparisons
            for f in c.findings
            if f.kind is Kind.SELF_CONSISTENCY and f.affects_energy
        }
    )
    if findings:
        lines += ["", "## Engine findings (self-consistency)", ""] + [f"- {f}" for f in findings]
    args.out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"written {args.out}")


if __name__ == "__main__":
    main()
