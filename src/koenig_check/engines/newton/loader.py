"""Load a model file in Newton the way its users load a robot for dynamics, and report what it refuses.

``ModelBuilder().add_mjcf(path, floating=None)`` / ``add_urdf(path, floating=None)`` (``floating=True`` for a
free-floating base: ``floating=False`` would replace the root body's own joint by a fixed one), then
``finalize(device="cpu")`` with its defaults (its inertia validation included).  Newton's parsers and Warp print
nothing here (Warp's module messages are silenced); what Newton warns while loading becomes a ``LOAD`` finding.
A refusal (an exception of Newton's parser or of ``finalize``) is a :class:`NewtonLoadError` whose first line names
the file and whose following lines are Newton's own whole text, indented.
"""

from __future__ import annotations

import contextlib
import io
import os
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from koenig_check.exceptions import ModelLoadError
from koenig_check.findings import Finding, Kind


class NewtonLoadError(ModelLoadError):
    """Newton refuses a model file (or its joints cannot be paired with MuJoCo's): the file named, Newton's text.

    Attributes
    ----------
    reason : str
        The refusal in a few words (``"Newton's add_urdf refuses the file"``), without the file.
    engine_text : str
        Newton's own text, whole, as it raised it (empty when the message is the tool's).
    """

    def __init__(self, message: str, reason: str = "", engine_text: str = "") -> None:
        super().__init__(message)
        self.reason = reason
        self.engine_text = engine_text


def refusal(path: Path, stage: str, err: BaseException) -> NewtonLoadError:
    """Newton's refusal of a file: one line naming the file and the stage, then Newton's own whole text indented.

    Parameters
    ----------
    path : Path
    stage : str
        ``"add_mjcf"``, ``"add_urdf"`` or ``"finalize"``.
    err : BaseException
        What Newton raised.

    Returns
    -------
    NewtonLoadError
    """
    text = f"{type(err).__name__}: {err}".rstrip()
    body = "\n".join("    " + line for line in text.splitlines() or [type(err).__name__])
    reason = f"Newton's {stage} refuses the file"
    return NewtonLoadError(f"{path}: {reason}\n{body}", reason, text)


def _quiet_warp() -> Any:
    """Warp, imported with its messages below errors off (its banner and module loads go to stdout otherwise)."""
    import warp as wp

    wp.config.quiet = True  # type: ignore[attr-defined]  # Warp's array types
    if hasattr(wp, "LOG_ERROR"):  # Warp 1.19 logs through a level
        wp.config.log_level = wp.LOG_ERROR
    _init_without_cuda_warning(wp)
    return wp


def _init_without_cuda_warning(wp: Any) -> None:
    """``wp.init()`` with its C-level stderr line about a missing CUDA driver dropped (Newton runs on the CPU here)."""
    import tempfile

    try:
        saved = os.dup(2)
    except OSError:  # no descriptor 2: nothing to keep clean
        wp.init()
        return
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 2)
        try:
            wp.init()
        finally:
            os.dup2(saved, 2)
            os.close(saved)


def build(
    path: Path,
    fmt: str,
    floating: bool,
    package_dirs: tuple[Path, ...] = (),
    copies: int = 1,
    finalize: dict[str, Any] | None = None,
    options: dict[str, Any] | None = None,
) -> tuple[Any, list[str]]:
    """Parse a file with Newton's own parser and finalize it on the CPU, ``copies`` worlds of it.

    Parameters
    ----------
    path : Path
    fmt : str
        ``"mjcf"`` or ``"urdf"``.
    floating : bool
        A free-floating base asked for (``floating=True``); otherwise ``floating=None``, Newton's default, which
        keeps the file's own root joint (a URDF root is fixed, an MJCF free joint stays free).
    package_dirs : tuple of Path
        Directories of ROS packages for ``package://`` URIs (URDF).
    copies : int
        Worlds of the same robot (``ModelBuilder.replicate``), to evaluate that many poses per call.
    finalize : dict, optional
        Keyword arguments of ``finalize`` other than the device (``skip_validation_inertia=True``: the causes).
    options : dict, optional
        Further keyword arguments of ``add_mjcf``/``add_urdf`` (``collapse_fixed_joints=True``,
        ``floating=False``: the causes).

    Returns
    -------
    model : newton.Model
    warned : list of str
        What Newton warned while parsing and finalizing (one entry per distinct message).

    Raises
    ------
    NewtonLoadError
    """
    robot, parsed = parse(path, fmt, floating, package_dirs, options)
    model, done = finalized(robot, path, copies, finalize)
    return model, list(dict.fromkeys(parsed + done))


@contextlib.contextmanager
def _caught() -> Iterator[list[str]]:
    """Newton's warnings recorded (one entry per distinct message) and its printing dropped."""
    said: list[str] = []
    with warnings.catch_warnings(record=True) as caught, contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("always")
        try:
            yield said
        finally:
            said.extend(dict.fromkeys(" ".join(str(w.message).split()) for w in caught or []))


def parse(
    path: Path, fmt: str, floating: bool, package_dirs: tuple[Path, ...] = (), options: dict[str, Any] | None = None
) -> tuple[Any, list[str]]:
    """Parse a file with Newton's own parser into a ``ModelBuilder`` (the arguments of :func:`build`).

    A builder is finalized as often as wanted (``finalize`` leaves it as it is): the file, with its meshes, is
    read once for every ``finalize`` option measured on it.

    Returns
    -------
    builder : newton.ModelBuilder
    warned : list of str

    Raises
    ------
    NewtonLoadError
    """
    _quiet_warp()
    import newton

    robot = newton.ModelBuilder()
    stage = "add_mjcf" if fmt == "mjcf" else "add_urdf"
    kwargs: dict[str, Any] = {"floating": True if floating else None}
    kwargs.update(options or {})
    if fmt == "urdf" and package_dirs:
        kwargs["package_dirs"] = [str(d) for d in package_dirs]
    with _caught() as warned:
        try:
            getattr(robot, stage)(os.fspath(path), **kwargs)
        except Exception as err:  # Newton's parser refuses: its own text, whole
            raise refusal(path, stage, err) from err
    return robot, warned


def finalized(
    robot: Any, path: Path, copies: int = 1, finalize: dict[str, Any] | None = None, collapse: bool = False
) -> tuple[Any, list[str]]:
    """Finalize a parsed file on the CPU, ``copies`` worlds of it (``finalize`` leaves the builder as it is).

    Parameters
    ----------
    robot : newton.ModelBuilder
        From :func:`parse`.
    path : Path
        For a refusal's message.
    copies : int
        Worlds of the same robot (``ModelBuilder.replicate``).
    finalize : dict, optional
        Keyword arguments of ``finalize`` other than the device.
    collapse : bool
        ``collapse_fixed_joints()`` first (what ``add_*(collapse_fixed_joints=True)`` does at the end of parsing),
        on the builder itself: it is that robot from then on.

    Returns
    -------
    model : newton.Model
    warned : list of str

    Raises
    ------
    NewtonLoadError
    """
    import newton

    with _caught() as warned:
        builder = robot
        if collapse:
            builder.collapse_fixed_joints()
        if copies > 1:
            one, builder = builder, newton.ModelBuilder()
            builder.replicate(one, copies)
        try:
            model = builder.finalize(device="cpu", **(finalize or {}))
        except Exception as err:
            raise refusal(path, "finalize", err) from err
    return model, warned


def warning_findings(warned: list[str]) -> list[Finding]:
    """One ``LOAD`` finding per distinct warning Newton gave while loading.

    Parameters
    ----------
    warned : list of str

    Returns
    -------
    list of Finding
    """
    return [Finding(Kind.LOAD, "newton", "model", f"Newton warns: {w}") for w in warned]


def newton_version() -> str:
    """The installed Newton version, or ``""``.

    Returns
    -------
    str
    """
    try:
        import importlib.metadata

        return importlib.metadata.version("newton")
    except Exception:
        return ""
