"""``[tool.koenig-check]`` entries: each model's own options reach the load, files named relative to the
pyproject.toml wherever pytest runs from.  Expected values are read from the engines' own models."""

from __future__ import annotations

from pathlib import Path

import pytest

from koenig_check.engines import load_model
from koenig_check.testing.project_config import read_models

_ARM = """<mujoco model="one">
  <worldbody>
    <body name="arm">
      <joint name="hinge" type="hinge" axis="0 0 1"/>
      <inertial pos="{x} 0 0" mass="2" diaginertia="0.01 0.02 0.03"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_a_pinocchio_model_beside_the_pyproject_is_loaded_from_there(tmp_path: Path, monkeypatch) -> None:
    project = tmp_path / "project"
    project.mkdir()
    (project / "a.xml").write_text(_ARM.format(x=0.1))
    (project / "b.xml").write_text(_ARM.format(x=0.3))
    (project / "pyproject.toml").write_text(
        '[tool.koenig-check]\nmodels = [{ model = "a.xml", pinocchio_model = "b.xml", seed = 7 }]\n'
    )
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)  # pytest run from another folder: the names are the pyproject's
    (entry,) = read_models(project / "pyproject.toml")
    assert entry.compare_options()["seed"] == 7
    loaded = load_model(entry.model, entry.load)
    assert loaded.source.path == (project / "a.xml").resolve()
    assert loaded.pinocchio.model.inertias[loaded.pinocchio.model.njoints - 1].lever[0] == pytest.approx(0.3)
    assert loaded.mujoco.model.body_ipos[1][0] == pytest.approx(0.1)
