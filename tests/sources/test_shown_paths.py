"""A model named by the user is named so again: its resolved file written as the user gave it."""

from __future__ import annotations

import re

import pytest

import koenig_check
from koenig_check.sources.shown_paths import as_given


@pytest.mark.parametrize("name", ["go1", "anymal_b_simple/anymal", "anymal_c_simple/anymal"])
def test_a_catalogue_name_is_written_as_given_even_with_a_folder_in_it(name: str) -> None:
    check = koenig_check.compare(name, n_poses=2, formulas=["exact"])  # MuJoCo refuses each: the file is named
    path = re.search(r"(/\S+\.urdf)", check.failures[0][1]).group(1)
    assert as_given(f"{path}: link 'base'", [name]) == f"{name}: link 'base'"


def test_short_names_replace_the_longest_path_first(tmp_path, monkeypatch) -> None:
    """``models/arm.urdf`` is inside the path of ``other/models/arm.urdf``: replacing it first would name
    ``<tmp>/other/arm.urdf``, a file that does not exist, instead of the second model's ``arm.urdf``."""
    monkeypatch.chdir(tmp_path)
    text = f"{tmp_path / 'other' / 'models' / 'arm.urdf'}: link 'a' has no inertial"
    assert (
        as_given(text, ["models/arm.urdf", "other/models/arm.urdf"], short=True) == "arm.urdf: link 'a' has no inertial"
    )


def test_short_names_also_shorten_the_path_as_typed(tmp_path, monkeypatch) -> None:
    """A message that names the file as the user typed it (a missing file) gives its file name alone."""
    monkeypatch.chdir(tmp_path)
    assert as_given("sub/dir/arm.urdf: no such file", ["sub/dir/arm.urdf"], short=True) == "arm.urdf: no such file"
