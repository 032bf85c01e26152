"""iDynTree named by ``--engines`` on the command line, the API and the pytest helper; refused on an MJCF."""

from __future__ import annotations

import pytest
from urdf_engine_cli import (  # noqa: F401 (the shared tests, collected here)
    engines,
    test_an_mjcf_fails_the_run_with_its_reason,
    test_compare_gives_it_a_column,
    test_dynamics_compares_its_mass_matrix,
    test_the_api_runs_it_on_every_pose,
)

from koenig_check.testing import assert_energy_parity

pytest.importorskip("idyntree")

ENGINE = "idyntree"
ENGINES = engines(ENGINE)


@pytest.fixture
def engine_name() -> str:
    """The engine the shared tests of :mod:`urdf_engine_cli` check."""
    return ENGINE


def test_the_pytest_helper_requires_it_to_check_the_model() -> None:
    assert_energy_parity("serial7.urdf", engines=ENGINES, n_poses=3)
    with pytest.raises(AssertionError):  # the check asked for (iDynTree) cannot be made on an MJCF
        assert_energy_parity("double_pendulum.xml", engines=ENGINES, n_poses=3)
