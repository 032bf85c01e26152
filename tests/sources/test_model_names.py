"""Model names: every accepted name is listed, aliases resolve, ambiguity rules, suggestions from the list."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from koenig_check import cli
from koenig_check.engines.errors import ModelLoadError
from koenig_check.sources.catalogue import DEFAULT_FORMAT, accepted_names, list_models, resolve_model, suggest_names
from koenig_check.sources.model_names import model_names


@pytest.fixture(scope="module")
def listing() -> str:
    import contextlib
    import io

    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert cli.main(["models"]) == 0
    return buffer.getvalue()


def _listed_names(listing: str) -> set[str]:
    names = set()
    for line in listing.splitlines()[3:]:
        parts = line.split(maxsplit=3)
        names.add(parts[0])
        if len(parts) == 4:
            names.update(a.strip() for a in parts[3].split(","))
    return names


def test_listing_holds_every_name_compare_accepts(listing: str) -> None:
    listed = _listed_names(listing)
    for name in ("ur5", "talos", "talos_reduced", "ur/ur5_robot", "gimbal", "gimbal.xml", "gimbal.urdf"):
        assert name in listed
    assert set(accepted_names()) <= listed


@pytest.mark.parametrize("entry", model_names(), ids=lambda e: e.name)
def test_every_listed_name_and_alias_resolves_to_its_file(entry) -> None:
    for name in (entry.name, *entry.aliases):
        assert resolve_model(name).path == entry.path


def test_listing_fits_100_columns(listing: str) -> None:
    assert max(len(line) for line in listing.splitlines()) <= 100


@pytest.mark.parametrize("alias, stem", [("ur5", "ur5_robot"), ("talos", "talos_reduced"), ("panda", "panda")])
def test_aliases_of_example_robot_data(alias: str, stem: str) -> None:
    assert resolve_model(alias).path.stem == stem


def test_project_models_in_both_formats_are_unambiguous() -> None:
    assert resolve_model("gimbal.xml").format == "mjcf"
    assert resolve_model("gimbal.urdf").format == "urdf"
    assert resolve_model("gimbal").format == DEFAULT_FORMAT == "mjcf"
    assert resolve_model("gimbal").path == resolve_model("gimbal.xml").path


def test_a_stem_in_two_packages_is_ambiguous_and_names_both() -> None:
    qualified = sorted(s.name for s in list_models() if s.name.endswith("/anymal"))
    assert len(qualified) == 2
    with pytest.raises(ModelLoadError, match="ambiguous") as exc:
        resolve_model("anymal")
    assert all(q in str(exc.value) for q in qualified)


def test_missing_file_gets_no_far_fetched_suggestions() -> None:
    with pytest.raises(ModelLoadError) as exc:
        resolve_model("my_robot.urdf")
    assert "no such file" in str(exc.value) and "did you mean" not in str(exc.value)


def test_suggestions_come_from_the_accepted_names_only() -> None:
    known = set(accepted_names())
    for typo in ("ur5_robt", "pand", "gimbl", "talso"):
        close = suggest_names(typo)
        assert close and set(close) <= known
    assert "ur5_robot" in suggest_names("ur5_robt")


def test_readme_relative_path_works_from_any_directory(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert not Path("models/gimbal.xml").exists()
    assert resolve_model("models/gimbal.xml").path == resolve_model("gimbal.xml").path
    assert os.getcwd() == str(tmp_path)


def test_check_says_which_load_and_why_not(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from koenig_check.cli.models import _loads_in_both

    assert _loads_in_both("gimbal.urdf") == "yes"
    verdict = _loads_in_both("free_body.urdf")
    assert verdict.startswith("no: ") and "nothing moves" in verdict and "free_body.urdf:" not in verdict
