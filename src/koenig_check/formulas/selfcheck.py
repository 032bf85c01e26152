"""Run every formula on analytic cases and tabulate how far each is from ``exact``."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from koenig_check.formulas import FORMULAS, NotPlaneParallelError, integrate_angular_velocity
from koenig_check.formulas.analytic import (
    box_inertia,
    constant_rotation_states,
    cylinder_inertia,
    random_rotations,
    random_states,
    rigid_states,
)
from koenig_check.formulas.angles import rotvec_angles
from koenig_check.formulas.paper_section3 import angular_velocity_39, rotation_39
from koenig_check.segments import SegmentStates


@dataclass(frozen=True)
class Case:
    """An analytic case: states, the path integrals of ω, and a description."""

    name: str
    description: str
    states: SegmentStates
    angles: np.ndarray


@dataclass(frozen=True)
class CaseResult:
    """One formula on one case: relative error against ``exact`` or the refusal reason."""

    case: str
    formula: str
    max_rel_error: float | None
    min_signed_rel_error: float | None
    max_signed_rel_error: float | None
    min_energy: float | None
    refused: str | None = None


def _path_case(name: str, description: str, states: SegmentStates, times: np.ndarray) -> Case:
    return Case(name, description, states, integrate_angular_velocity(states.omega, times))


def analytic_cases(seed: int = 0) -> list[Case]:
    """The self-check cases, all with paths so that every angle convention applies.

    Parameters
    ----------
    seed : int
        Seed of the random cases.

    Returns
    -------
    list of Case
    """
    rng = np.random.default_rng(seed)
    box = box_inertia(3.0, 0.4, 0.3, 0.2)
    t = np.linspace(0.0, 2.0, 201)
    cases = [
        _path_case(
            "box_spin_z",
            "uniform box spinning about its principal z axis (½Jω²)",
            constant_rotation_states(3.0, box, np.array([0.0, 0.0, 4.0]), t),
            t,
        ),
        _path_case(
            "cylinder_translate",
            "solid cylinder translating without rotation (½mv²)",
            constant_rotation_states(
                2.0, cylinder_inertia(2.0, 0.1, 0.5), np.zeros(3), t, v_com=np.array([0.3, -1.2, 2.0])
            ),
            t,
        ),
        _path_case(
            "tilted_box_one_axis",
            "box with tilted principal axes turning about world z from its initial state (eq. 17)",
            constant_rotation_states(3.0, box, np.array([0.0, 0.0, 2.5]), t, rotation_ref=random_rotations(rng, ())),
            t,
        ),
    ]
    R = rotation_39(1.3 * t, 0.8 * t)
    omega = angular_velocity_39(1.3 * t, np.full_like(t, 1.3), np.full_like(t, 0.8))
    gimbal = rigid_states(np.array([3.0]), box[None], R[:, None], omega[:, None], np.zeros((t.size, 1, 3)))
    cases.append(_path_case("gimbal_z_then_x", "box turned by the paper's section-3 motion (39)", gimbal, t))
    rand = random_states(rng, 200, 4)
    cases.append(
        Case(
            "random",
            "200 random poses × 4 random physical bodies; path integrals = rotation vectors",
            rand,
            rotvec_angles(rand),
        )
    )
    return cases


def run_selfcheck(seed: int = 0) -> list[CaseResult]:
    """Evaluate every formula on every analytic case.

    Parameters
    ----------
    seed : int

    Returns
    -------
    list of CaseResult
    """
    results = []
    for case in analytic_cases(seed):
        exact = FORMULAS["exact"](case.states).sum(axis=1)
        for name, formula in FORMULAS.items():
            try:
                value = formula(case.states, angles=case.angles).sum(axis=1)
            except NotPlaneParallelError as err:
                results.append(CaseResult(case.name, name, None, None, None, None, refused=str(err)))
                continue
            moving = exact > 0
            rel = np.where(moving, (value - exact) / np.where(moving, exact, 1.0), value)
            results.append(
                CaseResult(
                    case.name,
                    name,
                    float(np.abs(rel).max()),
                    float(rel.min()),
                    float(rel.max()),
                    float(value.min()),
                )
            )
    return results


def format_table(results: list[CaseResult], rtol: float = 1e-9) -> str:
    """Render the self-check as a plain-text table, one row per formula, one column per case.

    Parameters
    ----------
    results : list of CaseResult
    rtol : float
        Relative error under which a formula is marked as agreeing with ``exact``.

    Returns
    -------
    str
    """
    cases = list(dict.fromkeys(r.case for r in results))
    formulas = list(dict.fromkeys(r.formula for r in results))
    cell = {(r.case, r.formula): r for r in results}

    def text(r: CaseResult) -> str:
        if r.refused is not None:
            return "refused"
        assert r.max_rel_error is not None  # set on every result that is not a refusal
        mark = "=" if r.max_rel_error <= rtol else "≠"
        return f"{mark} {r.max_rel_error:8.1e}"

    width = max(len(f) for f in formulas) + 2
    col = max(12, *(len(c) for c in cases)) + 2
    lines = [
        f"max |relative error| against exact (= within {rtol:g}, ≠ beyond; refused = formula does not apply)",
        "formula".ljust(width) + "".join(c.rjust(col) for c in cases),
    ]
    for f in formulas:
        lines.append(f.ljust(width) + "".join(text(cell[(c, f)]).rjust(col) for c in cases))
    negative = [r for r in results if r.min_energy is not None and r.min_energy < 0]
    lines.append("")
    if negative:
        lines += [f"negative energy: {r.formula} on {r.case} (min {r.min_energy:.4g} J)" for r in negative]
    else:
        lines.append("no formula returned a negative energy on these cases")
    return "\n".join(lines)
