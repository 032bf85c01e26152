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
