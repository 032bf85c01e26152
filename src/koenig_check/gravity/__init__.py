"""The same robot under gravity: each engine's gravity vector, ``g(q)`` and potential-energy differences.

:func:`~koenig_check.gravity.parity.gravity_parity` reads every loaded engine's gravity terms at the run's poses
(:mod:`koenig_check.gravity.readings`), compares them with MuJoCo's and names why they differ
(:mod:`koenig_check.gravity.attribution`).
"""

from koenig_check.gravity.parity import GravityParity, gravity_parity

__all__ = ["GravityParity", "gravity_parity"]
