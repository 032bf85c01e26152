"""Mesh references inside a model file (``package://``, ``file://``, relative paths) resolved to existing files."""

from __future__ import annotations

from pathlib import Path


def resolve_uri(uri: str, base_dir: Path, package_dirs: tuple[Path, ...]) -> Path | None:
    """Resolve a mesh reference to an existing file.

    Parameters
    ----------
    uri : str
        ``package://pkg/rel``, ``file:///abs`` or a path (relative to ``base_dir``).
    base_dir : Path
        Directory relative paths are resolved against.
    package_dirs : tuple of Path
        Directories that contain ROS packages (``pkg`` is looked up in each).

    Returns
    -------
    Path or None
        The existing file, or ``None`` if it cannot be found.
    """
    if uri.startswith("package://"):
        rel = uri[len("package://") :].lstrip("/")
        for d in package_dirs:
            candidate = d / rel
            if candidate.is_file():
                return candidate
        return None
    if uri.startswith("file://"):
        uri = uri[len("file://") :]
    path = Path(uri)
    if not path.is_absolute():
        path = base_dir / path
    return path if path.is_file() else None
