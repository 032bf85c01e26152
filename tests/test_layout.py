"""The package's layout: no import cycle between its subpackages, no module over about 400 lines.

Imports are read from the source (every ``import koenig_check...`` and ``from koenig_check... import``, at the
top of a module and inside functions alike: a function-local import that closes a cycle is still one).
"""

from __future__ import annotations

import ast
import itertools
from collections import defaultdict
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "koenig_check"
#: The largest module the layout allows ("no module over about 400 lines").
MOST_LINES = 400
#: Modules that are compatibility shims, not code: the old import paths of moved modules.
SHIMS = {"_moved.py"}


def _home(dotted: str) -> str:
    """The subpackage a dotted module name lives in (``koenig_check.run.poses`` -> ``run``), or ``""``."""
    parts = dotted.split(".")
    if len(parts) > 1 and (PACKAGE / parts[1]).is_dir():
        return parts[1]
    return ""  # a top-level module (exceptions, findings, ...): shared by all, below every subpackage


def import_graph() -> dict[str, dict[str, list[str]]]:
    """Subpackage -> the subpackages it imports from -> the modules that do, read from the source."""
    graph: dict[str, dict[str, list[str]]] = defaultdict(lambda: defaultdict(list))
    for path in PACKAGE.rglob("*.py"):
        relative = path.relative_to(PACKAGE.parent).with_suffix("")
        module = ".".join(relative.parts).removesuffix(".__init__")
        home = _home(module) if len(relative.parts) > 2 else ""
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                targets = [node.module]
            elif isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                continue
            for target in targets:
                if target.startswith("koenig_check.") and home and _home(target) not in ("", home):
                    graph[home][_home(target)].append(module)
    return graph


def cycles(graph: dict[str, dict[str, list[str]]]) -> list[list[str]]:
    """Every elementary cycle's subpackages (found by depth-first search from each subpackage)."""
    found: list[list[str]] = []

    def walk(start: str, node: str, path: list[str]) -> None:
        for nxt in graph.get(node, {}):
            if nxt == start:
                found.append([*path, start])
            elif nxt not in path and nxt > start:  # each cycle once, from its smallest name
                walk(start, nxt, [*path, nxt])

    for start in sorted(graph):
        walk(start, start, [start])
    return found


def test_the_cycle_finder_finds_a_cycle() -> None:
    """The check below could fail: a hand-made graph with one cycle of three and one edge outside it."""
    graph = {"a": {"b": ["a.x"]}, "b": {"c": ["b.y"]}, "c": {"a": ["c.z"]}, "d": {"a": ["d.w"]}}
    assert cycles(graph) == [["a", "b", "c", "a"]]


def test_no_import_cycle_between_subpackages() -> None:
    graph = import_graph()
    assert graph["cli"] and graph["engines"]  # the graph was read (the CLI and the engines import others)
    found = cycles(graph)
    assert not found, [
        " -> ".join(cycle)
        + ": "
        + "; ".join(f"{a}->{b} in {sorted(set(graph[a][b]))[:2]}" for a, b in itertools.pairwise(cycle))
        for cycle in found
    ]


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_over_about_400_lines(path: Path) -> None:
    if path.name in SHIMS:
        pytest.skip("a table of old import paths")
    assert len(path.read_text(encoding="utf-8").splitlines()) <= MOST_LINES
