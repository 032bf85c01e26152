"""rd:NAME through a stub robot_descriptions (its modules expose MJCF_PATH / XACRO_PATH as after their clone)."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from source_trees import write_hand_expanded

from koenig_check import compare
from koenig_check.engines import load_model
from koenig_check.sources import ModelSourceError
from koenig_check.sources.catalogue import resolve_model

PROJECT_MODEL = Path(__file__).resolve().parents[2] / "models" / "double_pendulum.xml"
OFFLINE_CLONE = (
    "raise RuntimeError(\"Cmd('git') failed due to: exit code(128) cmdline: git clone -v -- "
    "https://github.com/example/robots.git stderr: 'fatal: unable to access: Could not resolve host: github.com'\")\n"
)


@pytest.fixture
def descriptions(stub_descriptions, arm_xacro, tmp_path):
    """Three descriptions: an MJCF one, a xacro one with its XACRO_ARGS, one whose clone cannot happen."""
    clone = tmp_path / "rd-cache" / "pendulum"
    clone.mkdir(parents=True)
    shutil.copy(PROJECT_MODEL, clone / "pendulum.xml")
    stub_descriptions(
        {
            "pendulum_mj_description": f"REPOSITORY_PATH = {str(clone)!r}\n"
            f"MJCF_PATH = {str(clone / 'pendulum.xml')!r}\n",
            "arm_description": f"PACKAGE_PATH = {str(arm_xacro.parents[1])!r}\nXACRO_PATH = {str(arm_xacro)!r}\n"
            "XACRO_ARGS = {'length': '0.8'}\n",
            "offline_description": OFFLINE_CLONE,
        }
    )
    return clone / "pendulum.xml"


@pytest.mark.parametrize("name", ["rd:pendulum_mj_description", "rd:pendulum_mj"])
def test_mjcf_path_is_the_model(name, descriptions):
    source = resolve_model(name)
    assert (source.path, source.format, source.origin, source.name) == (
        descriptions,
        "mjcf",
        "robot_descriptions",
        name,
    )
    check = compare(name, n_poses=4)
    assert check.ok, check.reason()
    assert [c.model for c in check.comparisons] == [name]


@pytest.mark.parametrize(("args", "length"), [({}, "0.8"), ({"length": "0.5"}, "0.5")])
def test_xacro_description_uses_its_args_then_the_users(args, length, descriptions, arm_xacro, tmp_path):
    hand = write_hand_expanded(tmp_path / "hand", length, arm_xacro.parents[1] / "meshes" / "link.stl")
    poses = np.array([[0.2, -0.4], [1.0, 2.0]])
    pair, expected = load_model("rd:arm_description", xacro_args=args), load_model(hand)
    for engine, reference in zip(pair.engines.values(), expected.engines.values(), strict=True):
        np.testing.assert_allclose(engine.mass_matrix(poses), reference.mass_matrix(poses), rtol=1e-12, atol=1e-15)


def test_clone_that_cannot_happen_names_the_cache_variable(descriptions):
    with pytest.raises(ModelSourceError) as info:
        resolve_model("rd:offline_description")
    text = str(info.value)
    assert "\n" not in text and "ROBOT_DESCRIPTIONS_CACHE" in text and "Could not resolve host" in text


def test_unknown_description_suggests_the_closest(descriptions):
    with pytest.raises(ModelSourceError, match="did you mean rd:pendulum_mj_description"):
        resolve_model("rd:pendulm_mj_description")
