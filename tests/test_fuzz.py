"""Fuzz: mutated copies of the project's own model files are reported or refused, never crash or hang."""

from __future__ import annotations

import re
import time
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from koenig_check.api import compare_model

MODELS = Path(__file__).resolve().parents[1] / "models"
FILES = sorted(MODELS.glob("*.xml")) + sorted(MODELS.glob("*.urdf"))
NUMBER = re.compile(r"-?\d+\.?\d*(?:e-?\d+)?")
REPLACEMENTS = ["nan", "inf", "-inf", "-1", "0", "1e300", "-0.5", "abc", "", "1 2", "1e-300"]


@st.composite
def mutated_model(draw: st.DrawFn) -> tuple[str, str]:
    path = draw(st.sampled_from(FILES))
    text = path.read_text()
    kind = draw(st.sampled_from(["number", "number", "delete", "truncate", "duplicate", "attribute", "tag"]))
    if kind == "number":
        spans = [m.span() for m in NUMBER.finditer(text)]
        a, b = draw(st.sampled_from(spans))
        text = text[:a] + draw(st.sampled_from(REPLACEMENTS)) + text[b:]
    elif kind == "delete":
        a = draw(st.integers(0, len(text) - 1))
        b = draw(st.integers(a, min(len(text), a + 200)))
        text = text[:a] + text[b:]
    elif kind == "truncate":
        text = text[: draw(st.integers(0, len(text)))]
    elif kind == "duplicate":
        a = draw(st.integers(0, len(text) - 1))
        b = draw(st.integers(a, min(len(text), a + 300)))
        text = text[:b] + text[a:b] + text[b:]
    elif kind == "attribute":
        names = sorted(set(re.findall(r'(\w+)="', text)))
        name = draw(st.sampled_from(names))
        text = text.replace(f'{name}="', f'{name}="{draw(st.sampled_from(REPLACEMENTS))} ', 1)
    else:
        tags = sorted(set(re.findall(r"<(\w+)", text)))
        tag = draw(st.sampled_from(tags))
        text = re.sub(rf"<{tag}\b[^>]*/>", "", text, count=1)
    return path.suffix, text


@settings(
    max_examples=200,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(case=mutated_model())
def test_mutated_models_are_reported_or_refused(tmp_path: Path, case: tuple[str, str]) -> None:
    suffix, text = case
    path = tmp_path / f"mutant{suffix}"
    path.write_text(text)
    start = time.perf_counter()
    try:
        comp = compare_model(path, n_poses=2, seed=0, floating=path.suffix == ".urdf" and "free_body" in text)
    except ValueError as err:  # a refusal: one line, naming the file
        message = str(err)
        assert "\n" not in message, message
        assert str(path) in message or "mutant" in message, message
    else:
        assert len(comp.records) > 0
        totals = comp.records.where(scope="total")
        assert np.all(np.isfinite(totals["reference_value"])), "a loaded model must give finite energies"
    assert time.perf_counter() - start < 60, "no hang"
