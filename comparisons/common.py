"""Shared pieces of the comparison scripts: the model corpora, machine-free names, Markdown tables.

Every model is named relative to the package that ships it (``example-robot-data: ur_description/urdf/ur5.urdf``,
``dm_control: suite/cartpole.xml``, ``koenig-check: gimbal.xml``), and every message an engine gives is
rewritten the same way, so that no committed output carries a path of the machine it was produced on.
"""

from __future__ import annotations

import os
import re
import sys
import xml.etree.ElementTree as ET
import zlib
from collections.abc import Sequence
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from koenig_check.demo import builtin_models
from koenig_check.engines import list_models

HERE = Path(__file__).resolve().parent

#: dm_control's model files: the globs of its shipped MJCF models (assets-only fragments are dropped).
DM_CONTROL_GLOBS = (
    "suite/*.xml",
    "locomotion/walkers/assets/**/*.xml",
    "locomotion/soccer/assets/**/*.xml",
    "third_party/**/*.xml",
    "mujoco/testing/assets/*.xml",
)


def _is_model(path: Path) -> bool:
    """An MJCF file with a ``<worldbody>`` (not a schema, defaults-only or assets-only fragment)."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError:
        return False
    return root.tag == "mujoco" and root.find("worldbody") is not None


def dm_control_root() -> Path | None:
    """The installed dm_control package directory, or None."""
    try:
        import dm_control
    except ImportError:
        return None
    return Path(dm_control.__file__).resolve().parent


def dm_control_corpus() -> list[Path]:
    """Every model file shipped with dm_control (empty when dm_control is not installed)."""
    root = dm_control_root()
    if root is None:
        return []
    return sorted({p for g in DM_CONTROL_GLOBS for p in root.glob(g) if _is_model(p)})


def erd_corpus() -> list[Path]:
    """Every URDF of example-robot-data."""
    return sorted({Path(s.path).resolve() for s in list_models() if s.origin == "example-robot-data"})


def project_corpus() -> list[Path]:
    """The project's own model files (MJCF then URDF per mechanism)."""
    return [Path(p).resolve() for p in builtin_models()]


def _roots() -> list[tuple[Path, str]]:
    roots: list[tuple[Path, str]] = []
    for s in list_models():
        if s.origin == "example-robot-data":
            for d in s.package_dirs:
                if d.name == "robots":
                    roots.append((Path(d).resolve(), "example-robot-data"))
                    break
            break
    dm = dm_control_root()
    if dm is not None:
        roots.append((dm, "dm_control"))
    if builtin_models():
        roots.append((Path(builtin_models()[0]).resolve().parent, "koenig-check"))
    return roots


_ROOTS = _roots()


def display_name(path: str | os.PathLike[str]) -> str:
    """A model path relative to the package that ships it, e.g. ``dm_control: suite/cartpole.xml``."""
    p = Path(path).resolve()
    for root, package in _ROOTS:
        if p.is_relative_to(root):
            return f"{package}: {p.relative_to(root).as_posix()}"
    return p.name


_ABSOLUTE = re.compile(r"(?<![\w.:/])/(?:[^\s'\"():,;]+/)+([^\s'\"():,;]*)")


def scrub(text: str) -> str:
    """Rewrite every absolute path in an engine's message: package-relative where known, else the file name."""
    for root, package in sorted(_ROOTS, key=lambda r: -len(str(r[0]))):
        text = re.sub(re.escape(str(root)) + r"/([^\s'\"():,;]+)", lambda m, p=package: f"{p}: {m.group(1)}", text)
    return _ABSOLUTE.sub(lambda m: m.group(1) or "…", text)


def model_seed(label: str, seed: int = 0) -> int:
    """A per-model seed: the same rows for a model whichever other models are in the run."""
    return (zlib.crc32(label.encode()) + seed) % 2**31


def cell(text: object) -> str:
    """A Markdown table cell: pipes escaped, newlines flattened."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def table(header: Sequence[str], rows: Sequence[Sequence[object]], align: str | None = None) -> list[str]:
    """A Markdown table, one line per row; ``align`` is one character per column (``l`` or ``r``)."""
    align = align or "l" * len(header)
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join("---:" if a == "r" else "---" for a in align) + " |"]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in rows]
    return lines


def parse_table_rows(markdown: str) -> list[list[str]]:
    """The body rows of every Markdown table in a text, as lists of cells (header and rule lines dropped)."""
    rows, previous_rule = [], False
    lines = markdown.splitlines()
    for i, line in enumerate(lines):
        if not line.startswith("| "):
            continue
        is_rule = bool(re.fullmatch(r"\|( ?-+:? \|)+", line.replace("---:", "---")))
        next_is_rule = i + 1 < len(lines) and bool(re.fullmatch(r"\|( -{3}:? \|)+", lines[i + 1]))
        if is_rule or next_is_rule:
            continue
        cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line)[1:-1]]
        rows.append(cells)
        previous_rule = is_rule
    del previous_rule
    return rows


def progress(message: str) -> None:
    """One line on stderr."""
    print(message, file=sys.stderr, flush=True)
