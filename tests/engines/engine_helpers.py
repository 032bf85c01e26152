"""Shared cases and numpy helpers of the engine tests (imported by conftest and the tests)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from koenig_check.engines import list_models
from koenig_check.sources.catalogue import project_models_dir

N_POSES = 20
SEED = 20261121
RTOL = 1e-9

PROJECT = ("free_body", "gimbal", "double_pendulum", "serial7", "armature_chain")

#: example-robot-data robots that cannot be loaded in both engines (MuJoCo 4.0 / pin 4.1), with
#: the element the error names.  Identical for fixed and floating base unless a tuple is given.
EXPECTED_LOAD_FAILURES = {
    "alex_psyonic_hands": "LeftPsyonicAbilityBaseLink",  # A + B >= C
    "allegro_left_hand": "link_11.0",  # A + B >= C
    "allegro_right_hand": "link_3.0",  # A + B >= C
    "anymal-kinova": "base",  # not positive definite
    "anymal_b_simple/anymal": "base",  # not positive definite
    "anymal_c_simple/anymal": "depth_camera_front_camera",  # A + B >= C (and 'hatch' not PD)
    "b1": "base",
    "b1-z1": "base",
    "finger_edu": "finger_lower_link",  # a zero principal moment
    "go1": "base",
    "human": "left_upperleg_virtual",  # massless moving link
    "hyq_no_sensors": "base_link",
    "icub": "l_ankle_2",
    "icub_reduced": "l_ankle_2",
    "pr2": "sensor_mount_link",  # A + B >= C
    "romeo": "LFinger11Link",  # massless moving link
    "romeo_laas_small": "body",
    "romeo_small": "RShoulderYawLink",  # A + B >= C
    "tiago": "base_antenna_left_link",
    "tiago_dual": "base_antenna_left_link",
    "tiago_no_hand": "base_antenna_left_link",
    "ur3": ("ur3.urdf", "floating=True"),  # no robot name (Pinocchio); no link at all (MuJoCo)
}
#: Loadable with ``balance_inertia=True`` (only A + B >= C violations).
BALANCEABLE = ("alex_psyonic_hands", "allegro_left_hand", "allegro_right_hand", "pr2", "romeo_small")
#: Single-link robots: no segment unless floating.
NO_DOF_WHEN_FIXED = ("iris_simple", "quadrotor_base")


@dataclass(frozen=True)
class Case:
    """One way of loading a model into both engines."""

    id: str
    model: str
    floating: bool = False
    pinocchio_source: str | None = None
    balance_inertia: bool = False


def _project_file(name: str, suffix: str) -> str:
    directory = project_models_dir()
    assert directory is not None, "the repository's models/ directory was not found"
    return str(Path(directory) / f"{name}{suffix}")


def _cases() -> list[Case]:
    cases = [Case(f"{n}.xml", f"{n}.xml") for n in PROJECT]
    cases += [Case(f"{n}.urdf", f"{n}.urdf") for n in PROJECT if n != "free_body"]
    cases += [Case(f"{n}.urdf-floating", f"{n}.urdf", floating=True) for n in PROJECT]
    cases += [
        Case(f"{n}.xml|pin:{n}.urdf", _project_file(n, ".xml"), False, _project_file(n, ".urdf")) for n in PROJECT
    ]
    cases += [
        Case(f"{n}.urdf|pin:{n}.xml", _project_file(n, ".urdf"), False, _project_file(n, ".xml"))
        for n in PROJECT
        if n != "free_body"
    ]
    for source in list_models(origin="example-robot-data"):
        if source.name in EXPECTED_LOAD_FAILURES:
            continue
        # mimic joints are loaded: both engines' energies are defined on the tree's coordinates
        if source.name not in NO_DOF_WHEN_FIXED:
            cases.append(Case(f"erd:{source.name}", source.name))
        cases.append(Case(f"erd:{source.name}-floating", source.name, floating=True))
    cases += [Case(f"erd:{n}-balanced", n, balance_inertia=True) for n in BALANCEABLE]
    return cases


CASES = _cases()


def exact_energy(states) -> np.ndarray:
    """½ m v_C² + ½ ω·(R I Rᵀ) ω per pose and segment, computed here from the fields alone."""
    inertia_world = states.rotation @ states.inertia_body[None] @ np.swapaxes(states.rotation, -1, -2)
    trans = 0.5 * states.mass[None, :] * np.sum(states.v_com**2, axis=-1)
    rot = 0.5 * np.einsum("pbi,pbij,pbj->pb", states.omega, inertia_world, states.omega)
    return trans + rot


def physical(mass: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """Mask (B,) of segments whose second moments S = ½tr(I)1 − I are all >= 0 (an equimomental set exists)."""
    S = 0.5 * np.trace(inertia, axis1=-2, axis2=-1)[:, None, None] * np.eye(3) - inertia
    s = np.linalg.eigvalsh(S)
    return (mass > 0) & np.all(s >= -1e-12 * np.abs(s).max(axis=-1, keepdims=True), axis=-1)


def equimomental(mass: np.ndarray, inertia: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Six points per segment at ±sqrt(3 s_i / m) along the principal axes of S = ½tr(I)1 − I.

    Returns offsets from the COM in segment axes (B, 6, 3) and point masses (B, 6).  A
    non-physical inertia (some s_i < 0) gets points for its clipped moments: callers mask it.
    """
    S = 0.5 * np.trace(inertia, axis1=-2, axis2=-1)[:, None, None] * np.eye(3) - inertia
    s, V = np.linalg.eigh(S)
    d = np.sqrt(np.clip(3.0 * s / mass[:, None], 0.0, None))
    axes = np.swapaxes(V, -1, -2) * d[..., None]
    offsets = np.concatenate([axes, -axes], axis=1)
    return offsets, np.repeat(mass[:, None] / 6.0, 6, axis=1)


def rel_err(a: np.ndarray, b: np.ndarray) -> float:
    """Largest |a - b| relative to the largest |b| (scalar)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max(initial=0.0) / max(np.abs(b).max(initial=0.0), 1e-300))
