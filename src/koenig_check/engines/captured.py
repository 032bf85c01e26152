"""What an engine's C or C++ code prints while it runs, captured instead of mixed into the program's output.

Engines written in C or C++ print their parsers' warnings and errors to the process's standard output and error
from C (PyBullet its banner and its URDF parser's messages, iDynTree its ``[ERROR]`` lines); a Python redirection
does not see them.  :func:`captured_output` points file descriptors 1 and 2 at a temporary file for a block and
returns the text, which an engine's loader keeps as its own reason when it refuses a file.
"""

from __future__ import annotations

import ctypes
import io
import os
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager, redirect_stdout


@contextmanager
def captured_output(out: list[str]) -> Iterator[None]:
    """Run a block with the C-level standard output and error sent to a temporary file; append what was printed.

    Parameters
    ----------
    out : list of str
        Extended with the printed text (one string) when the block ends, normally or not.
    """
    sys.stdout.flush()
    sys.stderr.flush()
    libc = ctypes.CDLL(None)
    saved = [os.dup(1), os.dup(2)]
    python_level = io.StringIO()  # what an engine writes through Python's sys.stdout
    with tempfile.TemporaryFile() as tmp:
        os.dup2(tmp.fileno(), 1)
        os.dup2(tmp.fileno(), 2)
        try:
            with redirect_stdout(python_level):
                yield
        finally:
            libc.fflush(None)
            for fd, kept in zip((1, 2), saved, strict=True):
                os.dup2(kept, fd)
                os.close(kept)
            tmp.seek(0)
            out.append(python_level.getvalue() + tmp.read().decode("utf-8", "replace"))
