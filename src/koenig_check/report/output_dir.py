"""The report directory: checked before any work, cleaned of the tool's own earlier files, listed after.

A report directory holds a manifest (:data:`MANIFEST`) naming every file koenig-check wrote there.  A
new run into the same directory first deletes those files (and only those), so no figure of an
earlier run is left beside the new ones.  A directory holding files koenig-check did not write is
refused unless ``overwrite`` is given (then those files are left alone and the tool's own files,
recognised by the manifest or by their names, are replaced).
"""

from __future__ import annotations

import fnmatch
from collections.abc import Iterable
from pathlib import Path

from koenig_check.arguments import ArgumentValueError

#: The manifest file listing what koenig-check wrote into a report directory.
MANIFEST = ".koenig-check-files"
#: Names of files koenig-check writes (recognised without a manifest, e.g. from an older version).
OWN_PATTERNS = (
    "summary.md",
    "report.html",
    "records.parquet",
    "records.csv",
    "records.json",
    "dynamics.md",
    "dynamics.json",
    "error_distribution*.png",
    "error_map*.png",
    "trajectory_energy*.png",
    MANIFEST,
)


def _manifest(out: Path) -> set[str]:
    path = out / MANIFEST
    if not path.is_file():
        return set()
    names = {line.strip() for line in path.read_text(encoding="utf-8").splitlines() if line.strip()}
    return {n for n in names if "/" not in n and "\\" not in n and n not in (".", "..")}


def _own(name: str, listed: set[str]) -> bool:
    return name in listed or any(fnmatch.fnmatch(name, p) for p in OWN_PATTERNS)


def check_out_dir(out: str | Path, overwrite: bool = False) -> Path:
    """Refuse an unusable report directory before any work starts.

    Parameters
    ----------
    out : str or Path
    overwrite : bool
        Accept a directory holding files koenig-check did not write (they are left in place).

    Returns
    -------
    Path

    Raises
    ------
    ArgumentValueError
        ``out`` is an existing file (or under one), or a directory with foreign files and no ``overwrite``.
    """
    out = Path(out)
    for parent in (out, *out.parents):
        if parent.exists() and not parent.is_dir():
            raise ArgumentValueError(f"--out {out}: {parent} is a file, not a directory")
    if not out.exists():
        return out
    listed = _manifest(out)
    foreign = sorted(p.name for p in out.iterdir() if not (p.is_file() and _own(p.name, listed)))
    if foreign and not overwrite:
        shown = ", ".join(foreign[:3]) + (f" and {len(foreign) - 3} more" if len(foreign) > 3 else "")
        raise ArgumentValueError(
            f"--out {out}: the directory holds files koenig-check did not write ({shown}); "
            "choose another directory or pass --overwrite (those files are then left in place)"
        )
    return out


def clean_out_dir(out: str | Path) -> list[Path]:
    """Create the report directory or delete koenig-check's own earlier files in it.

    Parameters
    ----------
    out : str or Path

    Returns
    -------
    list of Path
        The files deleted.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    listed = _manifest(out)
    removed = []
    for path in sorted(out.iterdir()):
        if path.is_file() and _own(path.name, listed):
            path.unlink()
            removed.append(path)
    return removed


def finish_out_dir(out: str | Path, written: Iterable[Path]) -> list[Path]:
    """Write the manifest of a finished report directory.

    Parameters
    ----------
    out : str or Path
    written : iterable of Path
        The files the run wrote.

    Returns
    -------
    list of Path
        The files written, sorted by name, without duplicates (the manifest not included).
    """
    out = Path(out)
    files = sorted({Path(p).name for p in written})
    (out / MANIFEST).write_text("".join(f"{n}\n" for n in files), encoding="utf-8")
    return [out / n for n in files]


def file_listing(out: str | Path, files: Iterable[Path]) -> str:
    """The lines printed after a run: the directory and each file written, with its size.

    Parameters
    ----------
    out : str or Path
    files : iterable of Path

    Returns
    -------
    str
    """
    files = list(files)
    lines = [f"report: {Path(out).resolve()} ({len(files)} files)"]
    width = max([len(p.name) for p in files] + [10])
    lines += [f"  {p.name:{width}s} {_size(p.stat().st_size):>9s}" for p in files]
    return "\n".join(lines)


def _size(n: int) -> str:
    size = float(n)
    for unit in ("B", "KB", "MB"):
        if size < 1024 or unit == "MB":
            return f"{size:.0f} {unit}" if unit == "B" else f"{size:.1f} {unit}"
        size /= 1024
    return f"{n} B"
