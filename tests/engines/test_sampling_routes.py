"""A seed gives the same poses on every route: the CLI, the API, the pytest helper, export's proof, dynamics.

Each route is run on a model with every joint type (free, ball, unlimited slide, limited and unlimited
hinge); the states MuJoCo's adapter is handed are recorded, and the first ``N`` of them must be exactly
:func:`koenig_check.engines.random_states` of the same model, ``N`` and seed.  A route that drew its poses
from a sampler of its own (another generator, another distribution for a joint type) hands other states.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import koenig_check
from koenig_check.cli.main import main
from koenig_check.engines import load_model, random_states
from koenig_check.engines.mujoco.adapter import MujocoEngine
from koenig_check.testing import assert_energy_parity

N, SEED = 7, 11

MODEL = """<mujoco model="every_joint">
  <compiler angle="radian"/>
  <worldbody>
    <body name="base" pos="0 0 1"><freejoint name="root"/>
      <inertial pos="0.01 0 0" mass="1" diaginertia="0.1 0.2 0.25"/>
      <body name="arm" pos="0.2 0 0"><joint name="ball" type="ball"/>
        <inertial pos="0.1 0 0" mass="0.5" diaginertia="0.01 0.02 0.02"/>
        <body name="slider" pos="0.2 0 0"><joint name="slide" type="slide" axis="1 0 0"/>
          <inertial pos="0 0 0" mass="0.3" diaginertia="0.01 0.01 0.01"/>
          <body name="hand" pos="0.1 0 0"><joint name="wrist" axis="0 0 1" limited="true" range="-0.4 0.9"/>
            <inertial pos="0.05 0.02 0" mass="0.2" diaginertia="0.002 0.003 0.004"/>
            <body name="finger" pos="0.05 0 0"><joint name="spin" axis="0 1 0"/>
              <inertial pos="0.02 0 0.01" mass="0.1" diaginertia="0.001 0.001 0.001"/></body>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.fixture(scope="module")
def model_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("every_joint") / "every_joint.xml"
    path.write_text(MODEL, encoding="utf-8")
    return path


@pytest.fixture
def handed(monkeypatch: pytest.MonkeyPatch) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """Every (qpos, qvel) MuJoCo's adapter is handed while the test runs (qvel None for M(q))."""
    seen: list[tuple[np.ndarray, np.ndarray | None]] = []

    def spy(name: str, with_velocity: bool) -> None:
        original = getattr(MujocoEngine, name)

        def recording(self, qpos, *args, **kwargs):  # type: ignore[no-untyped-def]
            qvel = args[0] if with_velocity and args else None
            seen.append((np.array(qpos, copy=True), None if qvel is None else np.array(qvel, copy=True)))
            return original(self, qpos, *args, **kwargs)

        monkeypatch.setattr(MujocoEngine, name, recording)

    for name, with_velocity in (
        ("sweep", True),
        ("kinetic_energy", True),
        ("mass_matrix", False),
        ("inverse_dynamics", True),
    ):
        spy(name, with_velocity)
    return seen


def _route_cli(path: Path, out: Path) -> None:
    assert main(["compare", str(path), "--poses", str(N), "--seed", str(SEED), "--out", str(out / "cli")]) == 0


def _route_api(path: Path, out: Path) -> None:
    assert koenig_check.compare(path, n_poses=N, seed=SEED).ok


def _route_helper(path: Path, out: Path) -> None:
    assert_energy_parity(path, n_poses=N, seed=SEED)


def _route_export(path: Path, out: Path) -> None:
    result = koenig_check.export(path, to="mjcf", out=out / "export.xml", poses=N, seed=SEED, engines=("mujoco",))
    assert result.proof.poses == N


def _route_dynamics(path: Path, out: Path) -> None:
    koenig_check.dynamics(path, n_poses=N, seed=SEED, engines=["mujoco", "pinocchio"])


ROUTES: dict[str, Callable[[Path, Path], None]] = {
    "cli compare": _route_cli,
    "api compare": _route_api,
    "assert_energy_parity": _route_helper,
    "export proof": _route_export,
    "dynamics": _route_dynamics,
}


@pytest.mark.parametrize("route", list(ROUTES))
def test_a_seed_gives_the_same_poses_on_every_route(
    route: str, model_file: Path, tmp_path: Path, handed: list[tuple[np.ndarray, np.ndarray | None]]
) -> None:
    qpos, qvel = random_states(load_model(model_file).mujoco.model, N, seed=SEED)
    handed.clear()  # the load above handed states of its own checks
    ROUTES[route](model_file, tmp_path)
    matches = [
        (q, v)
        for q, v in handed
        if q.shape[0] >= N and np.array_equal(q[:N], qpos) and (v is None or np.array_equal(v[:N], qvel))
    ]
    assert any(v is not None for _, v in matches), (
        f"{route}: none of the {len(handed)} batches of states MuJoCo was handed is random_states(model, {N}, "
        f"seed={SEED}) with its velocities"
    )
