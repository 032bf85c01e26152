"""xacro files expanded to URDF with ``xacrodoc`` (extra ``[xacro]``; no ROS needed).

The file is expanded with its ``<xacro:arg>`` defaults, overridden by ``--xacro-arg NAME=VALUE``
(``xacro_args``).  ``$(find pkg)`` and ``package://pkg/...`` are resolved against the file's own tree (the
nearest ``package.xml`` named ``pkg`` above it), the directories given, then ``ROS_PACKAGE_PATH``; mesh paths are
written absolute (``file://``), so the expanded URDF can live anywhere: in the cache directory
(``KOENIG_CHECK_CACHE``, default a ``koenig-check`` directory in the system's temporary directory), under a name
that depends on the file and its arguments, replaced atomically.
"""

from __future__ import annotations

import hashlib
import os
import re
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

from koenig_check.exceptions import one_line
from koenig_check.sources.errors import missing_extra


def cache_dir() -> Path:
    """Where expanded files are written: ``$KOENIG_CHECK_CACHE/xacro`` or a per-user temporary directory.

    Returns
    -------
    Path
    """
    root = os.environ.get("KOENIG_CHECK_CACHE")
    if root:
        return Path(root).expanduser() / "xacro"
    user = os.getuid() if hasattr(os, "getuid") else os.getlogin()
    return Path(tempfile.gettempdir()) / f"koenig-check-{user}" / "xacro"


def xacro_available(model: str) -> None:
    """Raise the missing-extra error when ``xacrodoc`` cannot be imported.

    Parameters
    ----------
    model : str
        The model as typed, for the message.

    Raises
    ------
    ModelSourceError
    """
    try:
        import xacrodoc  # noqa: F401
    except ImportError:
        raise missing_extra(model, "xacro", "xacrodoc") from None


def expand_xacro(
    path: Path,
    args: Mapping[str, str] | Iterable[tuple[str, str]] = (),
    package_dirs: Sequence[Path] = (),
    label: str | None = None,
) -> Path:
    """Expand a xacro file into a URDF file.

    Parameters
    ----------
    path : Path
        The ``.xacro`` file.
    args : mapping or pairs
        ``$(arg NAME)`` values; the file's defaults apply to the others.
    package_dirs : sequence of Path
        Directories searched for ROS packages after the file's own tree and before ``ROS_PACKAGE_PATH``.
    label : str, optional
        How the model was named, for messages (default: the path).

    Returns
    -------
    Path
        The expanded URDF (in :func:`cache_dir`).

    Raises
    ------
    ModelSourceError
        If ``xacrodoc`` is not installed.
    ModelLoadError
        If the file is missing or xacro cannot expand it (one line: the file and xacro's reason).
    """
    from koenig_check.exceptions import ModelLoadError

    name = label or str(path)
    xacro_available(name)
    from xacrodoc import XacroDoc, packages

    path = Path(path).expanduser().resolve()
    if not path.is_file():
        raise ModelLoadError(f"{name}: no such file")
    values = {str(k): str(v) for k, v in (args.items() if isinstance(args, Mapping) else args)}
    packages.reset()  # a fresh finder: ROS_PACKAGE_PATH as it is now, no package found for another file
    ros = [Path(p) for p in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    extra = [str(d) for d in (*package_dirs, *ros) if Path(d).is_dir()]
    if extra:
        packages.look_in(extra, priority=0)
    packages.walk_up_from(path, priority=0)  # the file's own tree first
    try:
        doc = XacroDoc.from_file(path, walk_up=False, subargs=values, resolve_packages=True)
        text = doc.to_urdf_string(use_protocols=True)
    except Exception as err:  # xacro's own reason (undefined arg, unknown package, bad XML), one line
        reason = xacro_reason(err)
        raise ModelLoadError(f"{name}: xacro cannot expand {path.name}: {reason}") from None
    empty = _no_link(path, text)
    if empty:
        raise ModelLoadError(f"{name}: {empty}")
    return _write(path, values, text)


#: The Python spelling of an exception's type that xacrodoc puts before its message (``<class 'x.Y'>: ``).
_TYPE_REPR = re.compile(r"<class '[\w.]+'>:\s*")


def xacro_reason(err: BaseException) -> str:
    """The reason xacro gives, on one line, said once and without the Python spelling of an exception's type.

    xacro's ``XacroException`` prints its message and then the exception it wraps, and xacrodoc's message is that
    exception's type and text: ``<class 'xacrodoc.packages.PackageNotFoundError'>: Package not found: pkg Package
    not found: pkg`` becomes ``Package not found: pkg``; anything xacro adds after the repeat is kept.

    Parameters
    ----------
    err : BaseException
        What expanding the file raised.

    Returns
    -------
    str
    """
    text = _TYPE_REPR.sub("", one_line(err))
    repeated = re.fullmatch(r"(.{10,}?) \1( .*)?", text)  # a whole clause said twice, not a word
    return repeated[1] + (repeated[2] or "") if repeated else text


def _no_link(path: Path, text: str) -> str:
    """Why the expansion holds no robot (a file of macros that only another xacro file calls), or ``""``."""
    import xml.etree.ElementTree as ET

    try:
        root = ET.fromstring(text)
    except ET.ParseError:
        return ""  # the loaders name the XML error
    if root.tag != "robot" or root.find("link") is not None:
        return ""
    macros = re.findall(r"<xacro:macro\s[^>]*\bname\s*=\s*[\"']([^\"']+)", path.read_text(errors="replace"))
    called = f"it defines macros ({', '.join(macros)}) and calls none" if macros else "it writes no <link>"
    return f"xacro expands it to a <robot> without any <link>: {called}; expand the file that uses it"


def expansion_stem(name: str) -> str:
    """The stem of the file a xacro file named ``name`` expands to (``arm`` for ``arm.urdf.xacro``).

    Parameters
    ----------
    name : str
        The xacro file's name.

    Returns
    -------
    str
    """
    stem = name[: -len(".xacro")] if name.endswith(".xacro") else Path(name).stem
    return stem[: -len(".urdf")] if stem.endswith(".urdf") else stem


def _write(source: Path, values: Mapping[str, str], text: str) -> Path:
    """Write the expansion under a name unique to the file and its arguments (atomic replace)."""
    key = repr((str(source), sorted(values.items()), text)).encode()
    digest = hashlib.sha256(key).hexdigest()[:16]
    stem = expansion_stem(source.name)
    out_dir = cache_dir()
    out_dir.mkdir(parents=True, exist_ok=True)
    target = out_dir / f"{stem}-{digest}.urdf"
    fd, tmp = tempfile.mkstemp(dir=out_dir, suffix=".urdf.tmp")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, target)
    return target
