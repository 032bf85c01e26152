"""An error in one line: whole parts dropped in order, a cut only as the last resort and never inside brackets."""

from __future__ import annotations

from dataclasses import replace

import pytest

from koenig_check.causes import cause
from koenig_check.diagnosis.one_line import short_error
from koenig_check.exceptions import ModelLoadError
from koenig_check.findings import Finding, Kind
from koenig_check.line_width import closed_cut


@pytest.mark.parametrize("width", range(20, 90, 7))
def test_a_cut_never_leaves_a_bracket_open(width: int) -> None:
    text = "arm.urdf: link 'base': MuJoCo rejects its inertia (error 'inertia must be positive' [in fullinertia]) here"
    line = closed_cut(text, width)
    assert len(line) <= width and line.endswith("…")
    assert line.count("(") == line.count(")") and line.count("[") == line.count("]"), line


#: The cause the includes of these tests are instances of: the brief form is its declaration's.
INCLUDE = "pinocchio.mjcf.include"


def _error(message: str, causes: list[Finding]) -> ModelLoadError:
    err = ModelLoadError(message)
    err.attach_causes(causes)
    return err


def _root(element: str, summary: str) -> Finding:
    return Finding(Kind.IGNORED_CONSTRUCT, "pinocchio", element, summary, affects_energy=True, root_cause=True)


def test_the_engines_detail_goes_whole_before_anything_is_cut() -> None:
    detail = "(the engine's own words, " + "long " * 20 + "and more)"
    err = _error(f"arm.xml: Pinocchio cannot parse the file {detail}; do this (option=1)", [_root("body b", "b lost")])
    line = short_error(err, 100)
    assert line == "arm.xml: Pinocchio cannot parse the file; do this; root cause: body b: b lost"


def test_causes_beyond_the_limit_are_counted_as_root_causes() -> None:
    causes = [_root(f"body b{k}", f"construct {k} ignored by the parser") for k in range(5)]
    line = short_error(_error("arm.xml: joints do not match", causes), 130)
    assert line.endswith("; and 3 more root causes") or line.endswith("; and 4 more root causes"), line
    assert "root cause: body b0: construct 0 ignored by the parser" in line


@pytest.mark.parametrize("n_includes", [2, 3, 5])
def test_a_cause_on_long_elements_is_named_by_its_first_before_it_goes_uncounted(n_includes: int) -> None:
    """Metaworld's sawyer_coffee.xml: three includes under ../objects/assets/ left "1 root cause not shown"."""
    files = [f"../objects/assets/{name}.xml" for name in ("mug", "xyz_base", "coffeemachine", "extra", "more")]
    causes = [
        replace(_root(f"include {f}", "<include> ignored by the parser: its bodies are missing"), cause=INCLUDE)
        for f in files[:n_includes]
    ]
    width = 150 - len("<include> ignored by the parser") + len(cause(INCLUDE).brief)  # the room of the first form
    line = short_error(_error("/some/folder/sawyer_coffee.xml: joints only in MuJoCo (a, b, c)", causes), width)
    more = n_includes - 1
    assert line == (
        "/some/folder/sawyer_coffee.xml: joints only in MuJoCo; root cause: includes ../objects/assets/mug.xml "
        f"(+{more} more): {cause(INCLUDE).brief}"
    )
