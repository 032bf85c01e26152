"""Library noise: MuJoCo's default warning handler prints and writes ``MUJOCO_LOG.TXT`` in the working directory.

The loader already turns MuJoCo's compiler warnings into findings while it compiles a model
(:mod:`koenig_check.engines.mujoco.loader`); the same file compiled again elsewhere (the root-cause analysis, a
file refused for a NaN) would repeat them, and MuJoCo's default handler would leave ``MUJOCO_LOG.TXT`` behind.
:func:`route_mujoco_warnings` sends them to the ``koenig_check.mujoco`` logger instead (silent unless
logging is configured, e.g. by ``--debug``).
"""

from __future__ import annotations

import logging

LOGGER = logging.getLogger("koenig_check.mujoco")


def _to_log(message: str) -> None:
    LOGGER.info("MuJoCo warning: %s", message.strip())


def route_mujoco_warnings() -> None:
    """Install a MuJoCo warning handler that logs instead of printing and writing ``MUJOCO_LOG.TXT``.

    Process-wide; the command line calls it at start, the test suite for its session.  Scoped captures
    (the loader's) still take precedence while they run.
    """
    import mujoco

    mujoco.set_mju_user_warning(_to_log)
