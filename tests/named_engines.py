"""The engines added by issue 25 and which file formats each reads, written down here from the engines' own
documentation (PyBullet's loadMJCF does not read an MJCF as written, iDynTree has no MJCF reader), not read from
their specs: the expectation the tests of ``--engines NAME`` and ``--engines all`` hold the code to."""

from __future__ import annotations

import pytest

from koenig_check.engines.registry import installed, label

#: The engines users move their robots to (issue 25), each named by ``--engines``.
NEW_ENGINES = ("newton", "pybullet", "idyntree")
#: Per format, the engines whose parser reads it.
READS = {
    "mjcf": ("mujoco", "pinocchio", "drake", "newton"),
    "urdf": ("mujoco", "pinocchio", "drake", "idyntree", "newton", "pybullet"),
}
#: The new engines without an MJCF reader: named on an MJCF, each fails the run with its own reason.
URDF_ONLY = tuple(e for e in NEW_ENGINES if e not in READS["mjcf"])


def named(engine: str) -> object:
    """``engine`` as a pytest parameter, skipped (with the extra to install) where it is not installed."""
    return pytest.param(engine, id=engine, marks=pytest.mark.skipif(not installed(engine), reason=f"{engine} absent"))


def installed_reading(fmt: str) -> tuple[str, ...]:
    """The installed engines that read ``fmt``, in :data:`READS` order."""
    return tuple(e for e in READS[fmt] if installed(e))


def labels(engines: tuple[str, ...]) -> str:
    """``"MuJoCo, Pinocchio, Drake"``: how the reports list engines."""
    return ", ".join(label(e) for e in engines)
