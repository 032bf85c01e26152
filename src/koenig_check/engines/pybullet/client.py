"""A PyBullet client of koenig-check's own: DIRECT, its C-level printing captured, the URDF loaded as users load it.

PyBullet 3.2.7 prints from C (``pybullet build time: ...`` to the standard error when imported, its parser's
warnings and errors while loading): left alone, that text would be mixed into the command line's output.  Every
call here that may print runs inside :func:`~koenig_check.engines.captured.captured_output`; what PyBullet printed
is kept, and on a refusal it is the engine's own reason.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

from koenig_check.engines.captured import captured_output
from koenig_check.exceptions import ModelLoadError

#: The flag its users pass to read the file's ``<inertial>`` (without it PyBullet computes inertia from
#: the collision shapes): :mod:`koenig_check.engines.pybullet.causes`.
INERTIA_FROM_FILE = "URDF_USE_INERTIA_FROM_FILE"


class PyBulletLoadError(ModelLoadError):
    """PyBullet refuses a file, or its joints cannot be paired with MuJoCo's (one line naming the file)."""


def pybullet_module() -> Any:
    """The ``pybullet`` module, imported without its banner reaching the standard output.

    Returns
    -------
    module
    """
    if "pybullet" in sys.modules:
        return sys.modules["pybullet"]
    with captured_output([]):
        import pybullet
    return pybullet


#: The source location PyBullet prefixes each message with (``b3Warning[examples/.../File.cpp,126]:``).
_LOCATION = re.compile(r"b3(?:Warning|Error|Printf)\[[^\]]*\]:")


def engine_text(printed: str) -> str:
    """What PyBullet printed, one message part a line, without its source locations and its banner.

    Parameters
    ----------
    printed : str

    Returns
    -------
    str
    """
    lines = [line.strip() for line in _LOCATION.sub("\n", printed).splitlines()]
    return "\n".join(line for line in lines if line and not line.startswith("pybullet build time"))


class Client:
    """One PyBullet DIRECT physics server, gravity zero, owned by one loaded model and disconnected with it.

    Parameters
    ----------
    search_path : Path, optional
        A directory PyBullet searches for files named in the URDF (``setAdditionalSearchPath``).
    """

    def __init__(self, search_path: Path | None = None) -> None:
        self.p = pybullet_module()
        printed: list[str] = []
        with captured_output(printed):
            self.id = self.p.connect(self.p.DIRECT)
            if search_path is not None:
                self.p.setAdditionalSearchPath(str(search_path), physicsClientId=self.id)
            self.p.setGravity(0, 0, 0, physicsClientId=self.id)

    def call(self, function: str, *args: Any, **kwargs: Any) -> Any:
        """Call one of PyBullet's functions on this client (``call("getNumJoints", body)``).

        Parameters
        ----------
        function : str
        *args, **kwargs
            Its arguments, ``physicsClientId`` added.

        Returns
        -------
        Any
        """
        return getattr(self.p, function)(*args, physicsClientId=self.id, **kwargs)

    def load_urdf(self, path: Path, floating: bool, flags: tuple[str, ...] = (INERTIA_FROM_FILE,)) -> int:
        """``loadURDF`` with the given flags, the base fixed unless ``floating``.

        Parameters
        ----------
        path : Path
        floating : bool
        flags : tuple of str
            Names of PyBullet's ``URDF_*`` flags.

        Returns
        -------
        int
            The body's id.

        Raises
        ------
        PyBulletLoadError
            PyBullet refuses the file: the first line names the file, then PyBullet's own text, indented.
        """
        value = 0
        for flag in flags:
            value |= int(getattr(self.p, flag))
        printed: list[str] = []
        try:
            with captured_output(printed):
                body = self.p.loadURDF(str(path), useFixedBase=not floating, flags=value, physicsClientId=self.id)
        except self.p.error as err:
            said = engine_text(printed[0] if printed else "") or str(err)
            text = "\n".join("    " + line for line in [str(err), *said.splitlines()] if line)
            raise PyBulletLoadError(f"{path}: PyBullet's loadURDF refuses the file\n{text}") from None
        return int(body)

    def close(self) -> None:
        """Disconnect the server (once)."""
        if self.id >= 0 and self.p.isConnected(physicsClientId=self.id):
            self.p.disconnect(physicsClientId=self.id)
        self.id = -1

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:  # interpreter shutdown: the module may be gone
            pass
