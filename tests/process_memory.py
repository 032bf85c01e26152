"""Memory helpers of the tests: give memory back between the big models, and read the process's peak."""

from __future__ import annotations

import ctypes
import gc
import resource
import sys


def _libc() -> ctypes.CDLL | None:
    """glibc, whose ``malloc_trim`` returns freed memory to the system; None elsewhere."""
    try:
        libc = ctypes.CDLL(None)
        libc.malloc_trim  # noqa: B018 (present in glibc only)
    except (OSError, AttributeError):
        return None
    return libc


_LIBC = _libc()


def release_memory() -> None:
    """Clear MuJoCo's asset cache, collect garbage and give freed memory back to the system.

    MuJoCo keeps decoded meshes in a process-wide asset cache of up to 500 MB, which the corpus tests fill and
    which stayed for the rest of the session; glibc keeps freed memory in its arenas until told to trim.  With
    the session-long cache of every engine test model, these held most of the suite's 4.9 GB peak.
    """
    import mujoco

    mujoco.mj_clearCache(mujoco.mj_getCache())
    gc.collect()
    if _LIBC is not None:
        _LIBC.malloc_trim(0)


def peak_memory() -> int:
    """The peak resident memory of this process so far, in bytes."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return peak if sys.platform == "darwin" else peak * 1024  # bytes on macOS, KiB on Linux
