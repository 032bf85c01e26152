"""Total energy T + V along a MuJoCo trajectory under gravity, with each kinetic-energy formula in place of T.

The paper invites it: a conservative system keeps T + V constant.  MuJoCo simulates the gimbal and the double
pendulum under gravity (RK4, no damping, springs or limits); along the path, V is MuJoCo's gravity potential
energy and T is each formula evaluated on MuJoCo's segment states.  The exact kinetic energy conserves T + V to the
integrator's error (stated: the same drift of MuJoCo's own energy); a formula that is not the kinetic energy of
the motion drifts.  The drift is ``max |E(t) - E(0)| / max(|T| + |V - V(0)|)`` over the path.

Usage::

    python comparisons/gravity_energy.py                      # writes gravity_energy.md / .png
    python comparisons/gravity_energy.py --duration 0.5 --out DIR
"""

from __future__ import annotations

import argparse
import copy
from pathlib import Path

import mujoco
import numpy as np

from koenig_check.engines import load_model
from koenig_check.formulas import FORMULAS, NotPlaneParallelError
from koenig_check.formulas.angles import integrate_angular_velocity
from koenig_check.roundoff import fmt
from koenig_check.run.poses import trajectory_poses

HERE = Path(__file__).resolve().parent
MODELS = ("gimbal.xml", "double_pendulum.xml")


def drifts(
    model: str, duration: float = 2.0, samples: int = 400, seed: int = 0
) -> tuple[dict, np.ndarray, dict, float]:
    """Per formula, the relative drift of T + V along a MuJoCo trajectory under gravity.

    Parameters
    ----------
    model : str
        A project model (``models/``).
    duration : float
    samples : int
    seed : int

    Returns
    -------
    drift : dict of str to float
        Formula (and ``"mujoco"``, MuJoCo's own ``mj_energyVel``) to its relative drift; a formula that refuses
        the motion is left out.
    times : ndarray, shape (P,)
    totals : dict of str to ndarray
        The total energy along the path per formula.
    swing : float
        The range of ``V(t) - V(0)`` along the path: what T and V exchange.
    """
    loaded = load_model(str(HERE.parent / "models" / model))
    sim = copy.copy(loaded.mujoco.model)
    sim.opt.integrator = int(mujoco.mjtIntegrator.mjINT_RK4)
    sim.opt.timestep = 1e-4
    path = trajectory_poses(sim, duration=duration, samples=samples, seed=seed, velocity_scale=3.0, gravity=True)
    mj = loaded.mujoco
    V = mj.potential_energy(path.qpos).gravity
    dV = V - V[0]
    states = mj.segment_states(path.qpos, path.qvel)
    totals = {"mujoco": mj.kinetic_energy(path.qpos, path.qvel).rigid + dV}
    assert path.times is not None
    angles = integrate_angular_velocity(states.omega, path.times)
    for name, formula in FORMULAS.items():
        try:
            kwargs = {"angles": angles} if name.endswith("integrated") else {}
            totals[name] = formula(states, **kwargs).sum(axis=1) + dV
        except NotPlaneParallelError:  # planar refuses a motion it is not defined for
            continue
    scale = float(np.max(np.abs(totals["exact"] - dV)) + np.max(np.abs(dV)))
    drift = {name: float(np.max(np.abs(E - E[0]))) / scale for name, E in totals.items()}
    return drift, path.times, totals, float(np.ptp(dV))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=2.0)
    parser.add_argument("--out", type=Path, default=HERE)
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(MODELS), figsize=(12, 4.5))
    lines = [
        "# T + V along a MuJoCo trajectory under gravity",
        "",
        f"MuJoCo RK4, time step 1e-4 s, {args.duration:g} s from the reference pose with seeded random joint rates "
        "(seed 0, scale 3 rad/s), gravity (0, 0, -9.81), no damping, springs, limits or contacts. "
        "V: MuJoCo's gravity potential energy; T: each formula on MuJoCo's segment states. "
        "Drift: max |E(t) - E(0)| over max |T| + max |V - V(0)|. "
        "The row `mujoco` is MuJoCo's own kinetic energy: the integrator's error.",
        "",
        "| formula | " + " | ".join(MODELS) + " |",
        "| --- | " + " | ".join("---" for _ in MODELS) + " |",
    ]
    results = {m: drifts(m, args.duration) for m in MODELS}
    names = list(dict.fromkeys(n for m in MODELS for n in results[m][0]))
    for name in names:
        cells = [f"{results[m][0][name]:.2e}" if name in results[m][0] else "refused" for m in MODELS]
        lines.append(f"| `{name}` | " + " | ".join(cells) + " |")
    swings = ", ".join(f"{m} {fmt(results[m][3], '.3g')} J" for m in MODELS)
    lines += ["", f"Range of V(t) - V(0) along the path (T and V exchange this much energy): {swings}."]
    for ax, m in zip(axes, MODELS, strict=True):
        _, times, totals, _ = results[m]
        for name, E in totals.items():
            ax.plot(times, E - E[0], label=name, lw=1.0)
        ax.set_title(f"{m}: E(t) - E(0), T from each formula")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("J")
    axes[-1].legend(fontsize=6, loc="best")
    fig.tight_layout()
    fig.savefig(args.out / "gravity_energy.png", dpi=110)
    (args.out / "gravity_energy.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
