"""The plugin's report is one run of every model it checked: each model's tolerance when they share one, and
the models that could not be compared listed with their reason."""

from __future__ import annotations

from pathlib import Path

import koenig_check
from koenig_check.run.stats import DEFAULT_RTOL
from koenig_check.testing.plugin import merged


def test_models_sharing_a_tolerance_keep_it_in_the_report() -> None:
    checks = [koenig_check.compare(m, rtol=1e-6, n_poses=2, formulas=["exact"]) for m in ("gimbal.xml", "gimbal.urdf")]
    assert DEFAULT_RTOL != 1e-6  # the test can tell the models' tolerance from the default
    assert merged(checks).rtol == 1e-6
    checks.append(koenig_check.compare("serial7.xml", rtol=1e-7, n_poses=2, formulas=["exact"]))
    assert merged(checks).rtol == DEFAULT_RTOL  # two tolerances: none of them is the run's


def test_a_model_that_could_not_be_compared_stays_in_the_report(tmp_path: Path) -> None:
    missing = tmp_path / "missing.xml"
    checks = [koenig_check.compare(m, n_poses=2, formulas=["exact"]) for m in ("gimbal.xml", missing)]
    together = merged(checks)
    assert [c.model for c in together.comparisons] == ["gimbal.xml"]
    assert [label for label, _ in together.failures] == ["missing.xml"]
    assert not together.ok
