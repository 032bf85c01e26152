"""The paper's claims, one by one, against MuJoCo and Pinocchio: what it says, what was run, what came out.

Claims (a)–(h) of issue 11: (a) one-axis rotation, eq. (38) = eq. (1); (b) axial moments unchanged by rotation,
eq. (29); (c) centrifugal moments updated by eq. (36) under each reading of Δθ, with the path dependence of the
integrated one; (d) the section-3 motion, eqs. (39)–(41), and the concluding formula; (e) "Koenig's formula exceeds
the actual values"; (f) eq. (37) with a moving pole; (g) eq. (38) with the current centrifugal moments (27);
(h) the dynamics each formula implies (second seed).  Each claim gets a row (paper, run, difference with its sign,
verdict `holds`, `fails` or `holds only when …`) and a figure; (e)–(g) also get one row per model, computed with a
seed derived from the model's name so that a row does not depend on the other models of the run.

Usage::

    python comparisons/paper_claims.py                 # every claim, every model; writes paper_claims.md, figures
    python comparisons/paper_claims.py --claims a,c,e --models koenig-check:gimbal.xml,ur5 --out DIR
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from common import HERE, display_name, erd_corpus, model_seed, progress, project_corpus, scrub, table

from koenig_check.roundoff import ROUNDOFF, fmt

#: Verdict tolerance on relative energy differences (the tool's default).
RTOL = 1e-9
#: Rates of (outer_z, inner_x) for the gimbal's fixed-velocity sweeps (rad/s).
RATES = (1.5, -2.0)
GRID = 25
CLAIMS = "abcdefgh"
FIG = "paper_claims_{}.png"


@dataclass
class Claim:
    """One row of the claims table."""

    key: str
    paper: str
    run: str
    difference: str
    verdict: str
    figure: str


def pct(x: float) -> str:
    """A signed relative difference as a percentage, three significant digits (round-off as 0)."""
    if abs(x) / 100 < ROUNDOFF:
        return "0"
    return f"{x:+.3g} %" if abs(x) >= 1e-4 else f"{x / 100:+.1e}"


def rel_range(rel: np.ndarray) -> str:
    """Size and sign of relative differences: the extremes, in percent."""
    rel = np.asarray(rel, dtype=float) * 100
    if pct(rel.min()) == pct(rel.max()):
        return f"{pct(rel.min())} throughout"
    return f"from {pct(rel.min())} to {pct(rel.max())}"


def small(x: float) -> str:
    """A small difference: ``0 (rounding)`` below the round-off threshold (1e-12)."""
    text = fmt(x, ".1e")
    return "0 (rounding)" if text == "0" else text


#: Q* comes from central differences chosen for about 1e-7 relative accuracy (measured: 7e-10 at worst on
#: exact formulas); below this floor a Q* error is the differences' own error, printed as such.
Q_FLOOR = 1e-8


def q_error(x: float) -> str:
    """A Q* error: below :data:`Q_FLOOR` it is the finite differences' own error."""
    return f"< {Q_FLOOR:.0e} (finite differences)" if x < Q_FLOOR else f"{x:.1e}"


# ---------------------------------------------------------------------------------------------------- the gimbal


def gimbal():
    """The project's section-3 gimbal, loaded in both engines."""
    from koenig_check.engines import load_model

    path = next(p for p in project_corpus() if p.name == "gimbal.xml")
    return load_model(path, check=False)


def states_at(pair, qpos: np.ndarray, qvel: np.ndarray, engine: str = "mujoco"):
    return getattr(pair, engine).segment_states(np.atleast_2d(qpos), np.atleast_2d(qvel))


def total(name: str, states, angles=None) -> np.ndarray:
    from koenig_check.formulas import FORMULAS

    return FORMULAS[name](states, angles=angles).sum(axis=1)


def grid_qpos(n: int = GRID) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The demo's 25 × 25 sweep of (outer_z, inner_x) over their ranges [-π, π]."""
    a = np.linspace(-np.pi, np.pi, n)
    A, B = np.meshgrid(a, a, indexing="ij")
    return a, A, B


def claim_a(pair, out: Path) -> Claim:
    import matplotlib.pyplot as plt

    angles = np.linspace(-np.pi, np.pi, 121)
    cases = {
        "about world z from the initial pose (inner_x = 0)": (np.c_[angles, 0 * angles], (RATES[0], 0.0)),
        "about world x from the initial pose (outer_z = 0)": (np.c_[0 * angles, angles], (0.0, RATES[1])),
        "about world z after inner_x = 0.6 rad": (np.c_[angles, 0.6 + 0 * angles], (RATES[0], 0.0)),
    }
    res = {}
    for label, (q, v) in cases.items():
        s = states_at(pair, q, np.tile(v, (len(q), 1)))
        ex, k1 = total("exact", s), total("koenig_world", s)
        res[label] = {c: total(f"alyushin_paper:{c}", s) / k1 - 1 for c in ("rotvec", "euler_xyz")}
        res[label]["koenig_world vs exact"] = k1 / ex - 1
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6), sharey=False)
    for ax, (label, r) in zip(axes, res.items(), strict=True):
        for name, values in r.items():
            ax.plot(angles, 100 * values, label=name if name.endswith("exact") else f"eq. (38) {name} vs eq. (1)")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("swept angle (rad)")
    axes[0].set_ylabel("relative difference (%)")
    axes[2].legend(fontsize=7)
    fig.suptitle("(a) one-axis rotation of the gimbal: eq. (38) as prescribed vs eq. (1)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / FIG.format("a"), dpi=100)
    plt.close(fig)
    one = [np.abs(np.r_[res[k]["rotvec"], res[k]["euler_xyz"]]).max() for k in list(cases)[:2]]
    eq1 = max(np.abs(res[k]["koenig_world vs exact"]).max() for k in cases)
    off = res[list(cases)[2]]
    return Claim(
        "(a)",
        'eq. (17) and conclusions: for rotation about a single axis "the results of equations (38) and (1) are '
        'the same"',
        "gimbal.xml (MuJoCo states), 121 angles over [-π, π] per case: outer_z alone and inner_x alone from the "
        f"initial pose, and outer_z alone after inner_x = 0.6 rad; rates {RATES[0]}, {RATES[1]} rad/s; Δθ as "
        "`rotvec` and `euler_xyz`",
        f"from the initial pose: {small(max(one))}; eq. (1) vs exact in every case: {small(eq1)}; "
        f"after inner_x = 0.6 rad, eq. (38) vs eq. (1): rotvec {rel_range(off['rotvec'])}, euler_xyz "
        f"{rel_range(off['euler_xyz'])}",
        "holds only when the body has turned about that same world axis from its initial pose",
        FIG.format("a"),
    )


def claim_b(pair, out: Path) -> Claim:
    import matplotlib.pyplot as plt

    a, A, B = grid_qpos()
    s = states_at(pair, np.c_[A.ravel(), B.ravel()], np.zeros((A.size, 2)))
    inner = list(s.names).index("inner_x")
    J = np.diagonal(s.inertia_world(), axis1=-2, axis2=-1)[:, inner]  # (P, 3) about world axes through C
    J0 = np.diag(s.rotation_ref[inner] @ s.inertia_body[inner] @ s.rotation_ref[inner].T)
    change = J / J0 - 1
    worst = np.abs(change).max(axis=1).reshape(A.shape)
    z_only = np.isclose(B.ravel(), 0.0)
    fig, ax = plt.subplots(figsize=(5.2, 4.2))
    im = ax.pcolormesh(a, a, 100 * worst.T, shading="nearest")
    fig.colorbar(im, label="max |J_C^i(q) / J_C^i(q0) − 1| over i = x, y, z (%)")
    ax.set_xlabel("outer_z (rad)")
    ax.set_ylabel("inner_x (rad)")
    ax.set_title("(b) axial moments of the gimbal's inner body, eq. (29)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out / FIG.format("b"), dpi=100)
    plt.close(fig)
    parts = ", ".join(f"J^{ax} {rel_range(change[:, i])}" for i, ax in enumerate("xyz"))
    return Claim(
        "(b)",
        'eq. (29): the axial moments (28) "retain their values at any rotation of the body"',
        f"gimbal.xml inner body (MuJoCo), {GRID} × {GRID} grid of (outer_z, inner_x) over [-π, π]: diagonal of "
        "R I Rᵀ about world axes through C against the initial pose",
        f"{parts}; J^z under rotations about z alone (inner_x = 0): {small(np.abs(change[z_only, 2]).max())}",
        "holds only when the body turns about that moment's own axis",
        FIG.format("b"),
    )


def _path_angles(pair, legs: list[tuple[int, float]], n: int = 2001) -> np.ndarray:
    """∫ω dt of each segment along a path made of one-joint legs from q = 0 (trapezoid rule on each leg)."""
    from koenig_check.formulas import integrate_angular_velocity

    q = np.zeros(2)
    total_angles = 0.0
    for joint, angle in legs:
        t = np.linspace(0.0, 1.0, n)
        qs = np.tile(q, (n, 1))
        qs[:, joint] += angle * t
        v = np.zeros((n, 2))
        v[:, joint] = angle
        s = states_at(pair, qs, v)
        total_angles = total_angles + integrate_angular_velocity(s.omega, t)[-1]
        q = qs[-1]
    return total_angles


def path_dependence(pair, final=(1.0, 1.2)) -> dict:
    """Two paths from q = 0 to ``final``: outer_z then inner_x, and inner_x then outer_z."""
    paths = {
        "outer_z then inner_x": [(0, final[0]), (1, final[1])],
        "inner_x then outer_z": [(1, final[1]), (0, final[0])],
    }
    s = states_at(pair, np.array(final), np.array(RATES))
    inner = list(s.names).index("inner_x")
    out = {"exact": float(total("exact", s)[0])}
    for label, legs in paths.items():
        ang = _path_angles(pair, legs)
        out[label] = (ang[inner], float(total("alyushin_paper:integrated", s, angles=ang[None])[0]))
    return out


def claim_c(pair, out: Path) -> tuple[Claim, list[list[object]]]:
    import matplotlib.pyplot as plt

    from koenig_check.formulas import integrate_angular_velocity
    from koenig_check.run.poses import trajectory_poses

    a, A, B = grid_qpos()
    s = states_at(pair, np.c_[A.ravel(), B.ravel()], np.tile(RATES, (A.size, 1)))
    ex = total("exact", s)
    rel = {c: total(f"alyushin_paper:{c}", s) / ex - 1 for c in ("rotvec", "euler_xyz")}
    traj = trajectory_poses(pair.mujoco.model, duration=2.0, samples=200, seed=0, velocity_scale=2.0)
    st = states_at(pair, traj.qpos, traj.qvel)
    ang = integrate_angular_velocity(st.omega, traj.times)
    rel_traj = total("alyushin_paper:integrated", st, angles=ang) / total("exact", st) - 1
    pdep = path_dependence(pair)
    fig, axes = plt.subplots(1, 3, figsize=(14, 3.8))
    for ax, c in zip(axes[:2], ("rotvec", "euler_xyz"), strict=True):
        im = ax.pcolormesh(a, a, 100 * rel[c].reshape(A.shape).T, shading="nearest", cmap="RdBu_r")
        fig.colorbar(im, ax=ax, label="(eq. 38 paper − exact) / exact (%)")
        ax.set_xlabel("outer_z (rad)")
        ax.set_ylabel("inner_x (rad)")
        ax.set_title(f"Δθ = {c}, rates {RATES}", fontsize=9)
    axes[2].plot(traj.times, 100 * rel_traj)
    axes[2].set_xlabel("time (s)")
    axes[2].set_title("Δθ = ∫ω dt along a torque-free MuJoCo trajectory", fontsize=9)
    axes[2].set_ylabel("relative difference (%)")
    fig.suptitle("(c) centrifugal moments updated by eq. (36): the gimbal", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / FIG.format("c"), dpi=100)
    plt.close(fig)
    labels = [k for k in pdep if k != "exact"]
    (ang1, e1), (ang2, e2) = pdep[labels[0]], pdep[labels[1]]
    claim = Claim(
        "(c)",
        'eqs. (33)/(36): the centrifugal moments "can be calculated through the moments of inertia (32)" of the '
        "initial state, rotated by Δθx, Δθy, Δθz",
        f"gimbal.xml (MuJoCo), {GRID} × {GRID} grid over [-π, π] with rates {RATES} for `rotvec` and `euler_xyz`; "
        "`integrated` along a 2 s torque-free trajectory from the initial pose (200 samples, seed 0, velocities "
        "× 2) and along two paths to the same state",
        f"rotvec {rel_range(rel['rotvec'])}, euler_xyz {rel_range(rel['euler_xyz'])}, integrated "
        f"{rel_range(rel_traj)}; two paths to q = (1, 1.2) rad give Δθ of the inner body "
        f"({', '.join(f'{x:.3f}' for x in ang1)}) and ({', '.join(f'{x:.3f}' for x in ang2)}) rad and energies "
        f"{e1:.4f} J and {e2:.4f} J (exact {pdep['exact']:.4f} J)",
        "fails",
        FIG.format("c"),
    )
    detail = [
        ["rotvec", f"{GRID} × {GRID} grid", small(np.abs(rel["rotvec"]).max()), rel_range(rel["rotvec"])],
        ["euler_xyz", f"{GRID} × {GRID} grid", small(np.abs(rel["euler_xyz"]).max()), rel_range(rel["euler_xyz"])],
        ["integrated", "trajectory, 200 samples", small(np.abs(rel_traj).max()), rel_range(rel_traj)],
        [
            "integrated",
            f"path {labels[0]}",
            small(abs(e1 / pdep["exact"] - 1)),
            f"Δθ = ({', '.join(f'{x:.3f}' for x in ang1)}) rad, E = {e1:.4f} J",
        ],
        [
            "integrated",
            f"path {labels[1]}",
            small(abs(e2 / pdep["exact"] - 1)),
            f"Δθ = ({', '.join(f'{x:.3f}' for x in ang2)}) rad, E = {e2:.4f} J",
        ],
    ]
    return claim, detail


def claim_d(pair, out: Path) -> list[Claim]:
    import matplotlib.pyplot as plt

    from koenig_check.formulas.paper_section3 import concluding_energy, integrand_41
    from koenig_check.formulas.point_masses import equimomental_points

    a, A, B = grid_qpos()
    s = states_at(pair, np.c_[A.ravel(), B.ravel()], np.tile(RATES, (A.size, 1)))
    inner = list(s.names).index("inner_x")
    exact_inner = __import__("koenig_check.formulas", fromlist=["FORMULAS"]).FORMULAS["exact"](s)[:, inner]
    offsets, masses = equimomental_points(s.mass[inner : inner + 1], s.inertia_body[inner : inner + 1])
    lagrange = s.com_ref[inner] + offsets[0] @ s.rotation_ref[inner].T  # the particles at the initial pose
    pole = s.pole_ref[inner]
    e41 = 0.5 * (integrand_41(lagrange, pole, B.ravel(), RATES[0], RATES[1]) * masses[0]).sum(axis=-1)
    concl = concluding_energy(masses[0], lagrange, pole, np.full(A.size, RATES[0]), np.full(A.size, RATES[1]))
    rel41, relc = e41 / exact_inner - 1, concl / exact_inner - 1
    at0 = np.isclose(B.ravel(), 0.0)
    fig, ax = plt.subplots(figsize=(6, 3.8))
    for j in range(0, GRID, 6):
        ax.plot(a, 100 * relc.reshape(A.shape)[j], label=f"outer_z = {a[j]:.2f}")
    ax.plot(a, 100 * rel41.reshape(A.shape)[0], "k--", label="eq. (41) integrated (all outer_z)")
    ax.set_xlabel("inner_x = Δθx (rad)")
    ax.set_ylabel("(formula − exact) / exact (%)")
    ax.set_title("(d) section 3 on the gimbal's inner body: the concluding formula", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / FIG.format("d"), dpi=100)
    plt.close(fig)
    run = (
        f"gimbal.xml inner body (MuJoCo states; six equimomental particles at the initial pose as the Lagrange "
        f"coordinates), pole = inner_x's anchor (fixed), {GRID} × {GRID} grid of (Δθz, Δθx) = (outer_z, inner_x) "
        f"over [-π, π], rates (θz,t, θx,t) = {RATES}"
    )
    return [
        Claim(
            "(d) eqs. (39)–(41)",
            'eq. (41) is the integrand of eq. (10) for the motion (39): "the integration results should be the same"',
            run,
            f"½ Σ m (41) vs exact: {small(np.abs(rel41).max())}",
            "holds",
            FIG.format("d"),
        ),
        Claim(
            "(d) concluding formula",
            "conclusions: E = ½ v_P² m + ½ θz,t² J_P^z + ½ θx,t² J_P^x − θx,t θz,t I_xz for this motion",
            run + "; moments from the initial pose as prescribed",
            f"{rel_range(relc)}; at Δθx = 0: {small(np.abs(relc[at0]).max())}",
            "holds only when Δθx = 0 (the inner body at its initial angle)",
            FIG.format("d"),
        ),
    ]


# ---------------------------------------------------------------------------------------------------- per model


@dataclass
class ModelRow:
    """Per-model results of claims (e), (f), (g)."""

    model: str
    group: str
    n_poses: int
    over: int = 0
    under: int = 0
    max_over: float = 0.0
    max_under: float = 0.0
    current_rel: float = 0.0  # (g) alyushin_current vs exact
    pole_fixed: float | None = None  # (f) max |ΔE_seg| / E over segments whose pole does not move
    pole_moving: float | None = None
    note: str = ""
    refused: str = ""


def model_targets() -> list[tuple[str, str, Path, bool]]:
    """(label, group, path, floating) of every model of (e)–(g): the project's models, then every ERD URDF."""
    from koenig_check.demo import FLOATING_MODELS

    out = [(display_name(p), "project", p, p.name in FLOATING_MODELS) for p in project_corpus()]
    out += [(display_name(p), "robots", p, False) for p in erd_corpus()]
    return out


def model_row(label: str, group: str, path: Path, floating: bool, n_poses: int) -> ModelRow:
    """Koenig's sign (e), eq. (37) about the joint anchor (f), eq. (38) with current moments (g) on one model."""
    from koenig_check.api import one_line
    from koenig_check.engines import load_model
    from koenig_check.engines.errors import InertiaError, NoMovingSegmentError
    from koenig_check.engines.sampling import random_states
    from koenig_check.formulas import FORMULAS

    row = ModelRow(label, group, n_poses)
    notes = []
    try:
        try:
            pair = load_model(path, floating=floating, check=False)
        except NoMovingSegmentError:  # a single body: it moves only with a free base
            floating = True
            notes.append("floating (a single body)")
            pair = load_model(path, floating=floating, check=False)
    except InertiaError:
        try:
            pair = load_model(path, floating=floating, repair_inertia=True, check=False)
            notes.append("--repair-inertia")
        except Exception as err:
            row.refused = scrub(one_line(err))
            return row
    except Exception as err:
        row.refused = scrub(one_line(err))
        return row
    row.note = ", ".join(notes)
    qpos, qvel = random_states(pair.mujoco.model, n_poses, seed=model_seed(label))
    s = pair.mujoco.segment_states(qpos, qvel)
    ex_seg = FORMULAS["exact"](s)
    ex = ex_seg.sum(axis=1)
    signed = FORMULAS["koenig_world"](s).sum(axis=1) / ex - 1
    row.over, row.under = int((signed > RTOL).sum()), int((signed < -RTOL).sum())
    row.max_over, row.max_under = float(max(signed.max(), 0.0)), float(min(signed.min(), 0.0))
    row.current_rel = float(np.abs(FORMULAS["alyushin_current"](s).sum(axis=1) / ex - 1).max())
    dpole = np.abs(FORMULAS["alyushin_pole:current"](s) - ex_seg) / ex[:, None]
    speed = np.linalg.norm(s.v_pole, axis=-1)
    at_com = np.linalg.norm(s.pole - s.com, axis=-1) <= 1e-12
    fixed = (speed <= 1e-12) | at_com
    row.pole_fixed = float(dpole[fixed].max()) if fixed.any() else None
    row.pole_moving = float(dpole[~fixed].max()) if (~fixed).any() else None
    return row


def _opt(x: float | None) -> str:
    return "—" if x is None else small(x)


MODEL_HEADER = [
    "model",
    "group",
    "poses",
    "(e) eq. (1) over / under",
    "(e) largest over / under",
    "(f) eq. (37), fixed pole",
    "(f) eq. (37), moving pole",
    "(g) eq. (38) current moments",
    "note",
]


def model_table_rows(rows: list[ModelRow]) -> list[list[object]]:
    out = []
    for r in rows:
        if r.refused:
            out.append([r.model, r.group, r.n_poses, "—", "—", "—", "—", "—", f"not loaded: {r.refused}"])
            continue
        out.append(
            [
                r.model,
                r.group,
                r.n_poses,
                f"{r.over / r.n_poses:.0%} / {r.under / r.n_poses:.0%}",
                f"{pct(100 * r.max_over)} / {pct(100 * r.max_under)}",
                _opt(r.pole_fixed),
                _opt(r.pole_moving),
                small(r.current_rel),
                r.note or "—",
            ]
        )
    return out


def pooled(rows: list[ModelRow], group: str) -> tuple[int, int, int, int]:
    sel = [r for r in rows if r.group == group and not r.refused]
    n = sum(r.n_poses for r in sel)
    return len(sel), n, sum(r.over for r in sel), sum(r.under for r in sel)


def claim_e(rows: list[ModelRow], out: Path, subset: bool) -> Claim:
    import matplotlib.pyplot as plt

    loaded = [r for r in rows if not r.refused]
    fig, ax = plt.subplots(figsize=(12, 3.8))
    x = np.arange(len(loaded))
    ax.bar(x, [r.over / r.n_poses for r in loaded], label="eq. (1) > exact")
    ax.bar(x, [-r.under / r.n_poses for r in loaded], label="eq. (1) < exact")
    ax.set_xticks(x, [r.model.split(": ", 1)[-1].split("/")[-1] for r in loaded], rotation=90, fontsize=6)
    ax.set_ylabel("fraction of poses (under shown negative)")
    ax.set_title("(e) sign of Koenig's formula (1) minus the exact energy, per model", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / FIG.format("e"), dpi=100)
    plt.close(fig)
    parts = []
    for group in ("project", "robots"):
        m, n, over, under = pooled(rows, group)
        if m:
            parts.append(f"{group} ({m} models, {n} poses): {over / n:.0%} over, {under / n:.0%} under")
    worst_over = max((r.max_over for r in loaded), default=0.0)
    worst_under = min((r.max_under for r in loaded), default=0.0)
    return Claim(
        "(e)" + (" subset" if subset else ""),
        'conclusions: "the calculated results according to the Koenig formula (1) exceed their actual values"',
        "`koenig_world` (eq. (1) about world axes through C, current pose) against `exact` on MuJoCo's states, "
        "random poses per model (seed from the model's name); the project's models and every example-robot-data "
        "URDF MuJoCo and Pinocchio load (table below)",
        "; ".join(parts) + f"; largest {pct(100 * worst_over)} over and {pct(100 * worst_under)} under",
        "fails",
        FIG.format("e"),
    )


def claim_f(rows: list[ModelRow], out: Path, subset: bool) -> Claim:
    import matplotlib.pyplot as plt

    loaded = [r for r in rows if not r.refused]
    fixed = [r.pole_fixed for r in loaded if r.pole_fixed is not None]
    moving = [r.pole_moving for r in loaded if r.pole_moving is not None]
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.scatter(range(len(loaded)), [max(r.pole_fixed or 0, 1e-17) for r in loaded], s=10, label="fixed pole")
    ax.scatter(range(len(loaded)), [max(r.pole_moving or 0, 1e-17) for r in loaded], s=10, label="moving pole")
    ax.set_yscale("log")
    ax.set_xlabel("model (table order)")
    ax.set_ylabel("max |E_seg(37) − E_seg| / E_total")
    ax.set_title("(f) eq. (37) about the joint anchor, current moments", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / FIG.format("f"), dpi=100)
    plt.close(fig)
    return Claim(
        "(f)" + (" subset" if subset else ""),
        'eq. (37): E = ½ v_P² m + ½ Σ θi,t² J_P^i − Σ θi,t θj,t I_ij about a pole P "belonging to the kinematic pairs"',
        "`alyushin_pole:current` (eq. (37) about each segment's joint anchor, moments (28), (27) of the current "
        "pose) per segment against `exact`, same poses as (e); segments split by whether their pole moves",
        f"fixed pole (or pole at C): at most {small(max(fixed, default=0.0))} of the total energy; moving pole: up "
        f"to {small(max(moving, default=0.0))} of the total energy",
        "holds only when the pole is fixed or is the centre of mass",
        FIG.format("f"),
    )


def claim_g(rows: list[ModelRow], out: Path, subset: bool) -> Claim:
    import matplotlib.pyplot as plt

    loaded = [r for r in rows if not r.refused]
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.scatter(range(len(loaded)), [max(r.current_rel, 1e-17) for r in loaded], s=10)
    ax.axhline(RTOL, color="k", ls="--", lw=0.8, label=f"tolerance {RTOL:g}")
    ax.set_yscale("log")
    ax.set_xlabel("model (table order)")
    ax.set_ylabel("max |E(38) / E − 1|")
    ax.set_title("(g) eq. (38) with the centrifugal moments (27) of the current pose", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / FIG.format("g"), dpi=100)
    plt.close(fig)
    worst = max((r.current_rel for r in loaded), default=0.0)
    return Claim(
        "(g)" + (" subset" if subset else ""),
        'eqs. (34)/(38) with (35) and (27): "the exact analytical dependence of the kinetic energy"',
        "`alyushin_current` (eq. (38), axial and centrifugal moments of the current pose) against `exact`, same "
        f"poses and models as (e) ({len(loaded)} models)",
        f"at most {small(worst)}",
        "holds" if worst <= RTOL else "fails",
        FIG.format("g"),
    )


def claim_h(out: Path, n_poses: int) -> tuple[Claim, list[list[object]]]:
    import matplotlib.pyplot as plt
    from inertia_forces import model_dynamics

    gimbal_path = next(p for p in project_corpus() if p.name == "gimbal.xml")
    md = model_dynamics(display_name(gimbal_path), str(gimbal_path), n_poses)
    names = ["exact", "koenig_world", "alyushin_current", "alyushin_paper:rotvec", "alyushin_paper:euler_xyz"]
    names += ["alyushin_pole:current", "point_masses"]
    m = {f: md.errors[(f, "mujoco", "M")] for f in names}
    q = {f: md.errors[(f, "mujoco", "Q*")] for f in names}
    fig, ax = plt.subplots(figsize=(8, 3.8))
    x = np.arange(len(names))
    ax.bar(x - 0.2, [max(m[f], 1e-17) for f in names], 0.4, label="M")
    ax.bar(x + 0.2, [max(q[f], 1e-17) for f in names], 0.4, label="Q*")
    ax.set_yscale("log")
    ax.set_xticks(x, names, rotation=40, ha="right", fontsize=7)
    ax.set_ylabel("max relative error vs MuJoCo")
    ax.set_title(f"(h) dynamics implied by each formula, gimbal.xml, {n_poses} poses", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / FIG.format("h"), dpi=100)
    plt.close(fig)
    detail = [[f"`{f}`", small(m[f]), small(q[f])] for f in names]
    claim = Claim(
        "(h)",
        'second seed (Kane & Levinson): Q*_j = −(d/dt ∂T/∂q̇_j − ∂T/∂q_j) from T; the paper: eqs. (37)/(38) "can be '
        'used for dynamic analysis of mechanisms of any complexity"',
        f"`koenig_check.dynamics` on gimbal.xml, {n_poses} random poses, velocities and accelerations (seed from the "
        "model's name): M by polarization and Q* by Lagrange's equations from each formula's energy on MuJoCo's "
        "states, against MuJoCo's M and inverse dynamics (armature out); more models in inertia_forces.md",
        f"paper's recipe: M {small(m['alyushin_paper:rotvec'])} (rotvec), {small(m['alyushin_paper:euler_xyz'])} "
        f"(euler_xyz), Q* {small(q['alyushin_paper:rotvec'])}, {small(q['alyushin_paper:euler_xyz'])}; eq. (1) M "
        f"{small(m['koenig_world'])}, Q* {small(q['koenig_world'])}; current moments M "
        f"{small(m['alyushin_current'])}, Q* {q_error(q['alyushin_current'])}",
        "holds only when the moments of the current pose are used",
        FIG.format("h"),
    )
    return claim, detail


# ---------------------------------------------------------------------------------------------------- output

CLAIM_HEADER = ["claim", "what the paper says", "what was run", "difference (size and sign)", "verdict", "figure"]


def markdown(claims: list[Claim], c_detail, model_rows, h_detail, n_poses: int, dyn_poses: int, versions: str) -> str:
    lines = [
        "# The paper's claims, one by one",
        "",
        "Yu. Alyushin, *Correction of the Koenig formula for the kinetic energy of a rotating solid*, checked against "
        f"MuJoCo and Pinocchio ({versions}). Differences are relative to the exact energy "
        "½ m v_C² + ½ ω·I_C ω, which both engines reproduce to ~1e-15 (engine_parity.md); '+' means the paper's "
        f"formula gives more. Verdict tolerance {RTOL:g}. Produced by `python comparisons/paper_claims.py`.",
        "",
        *table(CLAIM_HEADER, [[c.key, c.paper, c.run, c.difference, c.verdict, f"![]({c.figure})"] for c in claims]),
        "",
    ]
    if c_detail:
        lines += [
            "## (c) each reading of Δθ",
            "",
            *table(["Δθ", "poses", "max relative difference", "size and sign"], c_detail, "llrl"),
            "",
        ]
    if model_rows:
        lines += [
            "## (e), (f), (g) model by model",
            "",
            f"{n_poses} random poses per model (seed derived from the model's name), MuJoCo's segment states, fixed "
            "base except free_body (floating). Over / under: fraction of poses where `koenig_world` exceeds `exact` "
            f"by more than {RTOL:g} relative, or falls short; (f): largest |E_seg(37) − E_seg| / E_total over the "
            "segments whose pole (joint anchor) is fixed or is the centre of mass, and over those whose pole moves.",
            "",
            *table(MODEL_HEADER, model_rows, "llrllrrrl"),
            "",
        ]
    if h_detail:
        lines += [
            f"## (h) gimbal.xml, {dyn_poses} poses: largest relative error against MuJoCo",
            "",
            *table(["formula", "M", "Q*"], h_detail, "lrr"),
            "",
        ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--claims", default=CLAIMS, help="which claims, e.g. a,c,e (default: all)")
    parser.add_argument("--models", help="models of (e)–(g), names as in the table (default: all)")
    parser.add_argument("--poses", type=int, default=200, help="random poses per model for (e)–(g)")
    parser.add_argument("--dynamics-poses", type=int, default=10, help="poses of (h)")
    parser.add_argument("--out", type=Path, default=HERE)
    args = parser.parse_args(argv)
    wanted = [c for c in args.claims.replace(",", "") if c in CLAIMS]
    targets = model_targets()
    if args.models:
        names = [n.strip().replace(" ", "") for n in args.models.split(",") if n.strip()]
        by_label = {t[0].replace(" ", ""): t for t in targets}
        by_label.update({t[2].stem: t for t in targets if t[1] == "robots"})
        unknown = [n for n in names if n not in by_label]
        if unknown:
            raise SystemExit(f"paper_claims: unknown models {unknown} (names as in the table, or a URDF's stem)")
        targets = [by_label[n] for n in names]
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    os.chdir(tempfile.mkdtemp(prefix="paper_claims_"))
    start = time.perf_counter()
    pair = gimbal()
    claims: list[Claim] = []
    c_detail: list = []
    h_detail: list = []
    if "a" in wanted:
        claims.append(claim_a(pair, out))
    if "b" in wanted:
        claims.append(claim_b(pair, out))
    if "c" in wanted:
        c, c_detail = claim_c(pair, out)
        claims.append(c)
    if "d" in wanted:
        claims += claim_d(pair, out)
    rows: list[ModelRow] = []
    if set(wanted) & set("efg"):
        for label, group, path, floating in targets:
            rows.append(model_row(label, group, path, floating, args.poses))
            progress(f"{label}: {'refused' if rows[-1].refused else 'done'}")
        subset = bool(args.models)
        for key, make in (("e", claim_e), ("f", claim_f), ("g", claim_g)):
            if key in wanted:
                claims.append(make(rows, out, subset))
    if "h" in wanted:
        c, h_detail = claim_h(out, args.dynamics_poses)
        claims.append(c)
    from engine_parity import versions

    text = markdown(claims, c_detail, model_table_rows(rows), h_detail, args.poses, args.dynamics_poses, versions())
    (out / "paper_claims.md").write_text(text, encoding="utf-8")
    progress(f"written {out / 'paper_claims.md'} ({time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main()
