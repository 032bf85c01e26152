"""Model names, example-robot-data discovery, format detection, mesh URI resolution."""

from __future__ import annotations

import importlib.metadata
from pathlib import Path

import pytest

from koenig_check.engines import ModelLoadError, list_models, resolve_model
from koenig_check.sources.catalogue import detect_format, example_robot_data_dirs, project_models_dir

#: The project models in both formats.
PROJECT = ("free_body", "gimbal", "double_pendulum", "serial7", "armature_chain")


def test_example_robot_data_found_through_the_installed_distribution():
    share, robots = example_robot_data_dirs()
    dist = importlib.metadata.distribution("example-robot-data")
    urdfs = {Path(str(dist.locate_file(f))).resolve() for f in dist.files if str(f).endswith(".urdf")}
    listed = {s.path.resolve() for s in list_models(origin="example-robot-data")}
    assert listed == urdfs and len(listed) > 50
    assert all(p.is_relative_to(robots) for p in listed)
    assert (share / "example-robot-data" / "robots") == robots


def test_every_name_is_unique_and_resolves_to_its_file():
    models = list_models()
    keys = [(s.name, s.format) for s in models]
    assert len(keys) == len(set(keys))
    for s in models:
        assert resolve_model(s.name, s.format) == s
        for alias in s.aliases:
            assert resolve_model(alias, s.format) == s


def test_project_models_are_listed_in_both_formats():
    directory = project_models_dir()
    assert directory is not None
    # The installed package data are the repository's own files (editable or not).
    repo_models = Path(__file__).resolve().parents[2] / "models"
    for name in PROJECT:
        for suffix in (".xml", ".urdf"):
            assert (directory / f"{name}{suffix}").read_bytes() == (repo_models / f"{name}{suffix}").read_bytes()
    project = {(s.name, s.format) for s in list_models(origin="project")}
    assert {(n, f) for n in PROJECT for f in ("mjcf", "urdf")} <= project
    assert resolve_model("serial7.urdf").format == "urdf"
    assert resolve_model("serial7.xml").format == "mjcf"
    assert resolve_model("serial7", fmt="urdf").path.suffix == ".urdf"


def test_short_names_aliases_and_duplicates():
    assert resolve_model("ur5").path.name == "ur5_robot.urdf"
    assert resolve_model("panda").path.name == "panda.urdf"
    assert resolve_model("talos").path.name == "talos_reduced.urdf"
    # anymal.urdf exists in two packages: both get qualified names
    b, c = resolve_model("anymal_b_simple/anymal"), resolve_model("anymal_c_simple/anymal")
    assert b.path != c.path and b.path.name == c.path.name == "anymal.urdf"
    # a project model shadows the example-robot-data robot of the same stem, which stays reachable
    assert resolve_model("double_pendulum", fmt="urdf").origin == "project"
    assert resolve_model("double_pendulum/double_pendulum").origin == "example-robot-data"


def test_ambiguous_and_unknown_names_are_clear_errors():
    assert resolve_model("serial7").format == "mjcf"  # a project model in both formats: the bare name is MJCF
    with pytest.raises(ModelLoadError, match=r"ambiguous.*anymal_b_simple/anymal"):
        resolve_model("anymal")
    with pytest.raises(ModelLoadError, match=r"did you mean.*ur5"):
        resolve_model("ur55")


def test_detect_format(tmp_path):
    mj = tmp_path / "a.xml"
    mj.write_text("<mujoco><worldbody/></mujoco>")
    urdf = tmp_path / "b.xml"
    urdf.write_text('<robot name="r"><link name="l"/></robot>')
    other = tmp_path / "c.xml"
    other.write_text("<sdf/>")
    assert detect_format(mj) == "mjcf" and detect_format(urdf) == "urdf"
    with pytest.raises(ModelLoadError, match=r"c.xml.*<sdf>"):
        detect_format(other)


@pytest.mark.parametrize(
    ("given", "what"),
    [
        ("ur5_robt", "no such file and no model of that name"),  # a plain name: it could have been either
        ("robots/ur5_robt.urdf", "no such file"),  # written as a path: a file was meant
    ],
)
def test_an_unknown_name_says_what_was_looked_for(given: str, what: str) -> None:
    """load_model(name) in Python reaches resolve_model without the command line's usage check."""
    with pytest.raises(ModelLoadError) as err:
        resolve_model(given)
    assert str(err.value).startswith(f"{given}: {what} (")
